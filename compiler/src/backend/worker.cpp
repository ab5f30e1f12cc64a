#include "worker.h"

#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>

namespace facet::backend {
namespace {

// Shared by the caller and the worker; the worker may outlive the caller's
// frame only in the instant before _exit, so it is reference-counted.
struct WorkerState {
  std::function<void()> work;
  std::mutex mutex;
  std::condition_variable done_signal;
  bool done = false;
  std::exception_ptr error;  // what `work` threw (std::bad_alloc), rethrown to the caller
};

void* worker_main(void* arg) {
  auto state = *static_cast<std::shared_ptr<WorkerState>*>(arg);
  delete static_cast<std::shared_ptr<WorkerState>*>(arg);
  try {
    state->work();
  } catch (...) {
    state->error = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(state->mutex);
    state->done = true;
  }
  state->done_signal.notify_all();
  return nullptr;
}

// Starts the worker; false when the system refuses a thread of that stack.
bool start_worker(const std::shared_ptr<WorkerState>& state, pthread_t& thread) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return false;
  bool ok = pthread_attr_setstacksize(&attr, kWorkerStackBytes) == 0;
  auto* arg = new std::shared_ptr<WorkerState>(state);
  ok = ok && pthread_create(&thread, &attr, worker_main, arg) == 0;
  pthread_attr_destroy(&attr);
  if (!ok) delete arg;
  return ok;
}

[[noreturn]] void give_up(const std::string& message) {
  std::fwrite(message.data(), 1, message.size(), stderr);
  std::fflush(stderr);
  _exit(1);
}

}  // namespace

void run_on_worker(const std::function<void()>& work, uint32_t time_limit_s,
                   const std::function<std::string()>& timeout_message) {
  auto state = std::make_shared<WorkerState>();
  state->work = work;
  pthread_t thread;
  if (!start_worker(state, thread)) {
    work();
    return;
  }
  {
    std::unique_lock<std::mutex> lock(state->mutex);
    if (time_limit_s == 0) {
      state->done_signal.wait(lock, [&] { return state->done; });
    } else {
      auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(time_limit_s);
      if (!state->done_signal.wait_until(lock, deadline, [&] { return state->done; })) {
        lock.unlock();
        give_up(timeout_message());
      }
    }
  }
  pthread_join(thread, nullptr);
  if (state->error) std::rethrow_exception(state->error);
}

}  // namespace facet::backend
