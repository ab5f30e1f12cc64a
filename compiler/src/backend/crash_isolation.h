// Runs crash-prone library work (glslang's HLSL front end) in a child
// process, so that a crash there becomes an error of the input instead of
// the end of the compiler.
//
// glslang's HLSL parser dereferences null pointers on malformed programs in
// more ways than facet can refuse beforehand (fuzzing keeps finding new
// ones), and glslang is not instrumented, so nothing warns before it
// crashes. A child process dies alone; its parent reports the program.
//
// Why a helper process (a "zygote") instead of forking the caller: facet
// compiles on many threads, and a child forked from a multithreaded process
// inherits every lock another thread held at that instant (the allocator's,
// glslang's own) without the thread that would release it, so it can hang
// forever. The zygote is forked once, when the Backend is made, and stays
// single-threaded: it only waits for connections and forks a worker for
// each. Children of a single-threaded process inherit no held lock.
//
// A worker runs a plain function (no captures: it lives in the zygote's
// copy of the program, not in the caller's memory) on a request's bytes,
// on a large-stack thread (worker.h), and sends back the bytes it returns.
// Workers serve one request after another (a fresh process per request
// would fault in its whole heap each time); one is started when every
// other is busy, and one that dies is replaced.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace facet::backend {

// What a child made of a request.
struct ChildAnswer {
  enum class Kind {
    answered,     // `bytes` holds what the handler returned
    died,         // the child ended before answering (a crash, a signal, out of memory)
    unavailable,  // no child could be started: do the work in-process
  };
  Kind kind = Kind::unavailable;
  std::string bytes;
};

// The fields of a request or an answer, each length-prefixed, in this
// machine's byte order (both ends are the same program).
class WireWriter {
 public:
  void byte(uint8_t value) { bytes_.push_back(char(value)); }
  void u32(uint32_t value) { bytes_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void text(std::string_view value);
  void words(const std::vector<uint32_t>& value);
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a WireWriter wrote. Past the end, or on a length the bytes
// cannot hold, every read returns a zero value and ok() is false.
class WireReader {
 public:
  explicit WireReader(std::string_view bytes) : bytes_(bytes) {}
  uint8_t byte();
  uint32_t u32();
  std::string text();
  std::vector<uint32_t> words();
  bool ok() const { return ok_; }
  bool at_end() const { return ok_ && at_ == bytes_.size(); }

 private:
  bool take(void* out, size_t size);
  std::string_view bytes_;
  size_t at_ = 0;
  bool ok_ = true;
};

class CrashIsolation {
 public:
  // Runs in the child; returns the answer's bytes.
  using Handler = std::string (*)(std::string_view request);

  // Forks the zygote. When that fails, every run() answers `unavailable`.
  CrashIsolation();
  // Ends the zygote (it exits when its socket closes) and reaps it.
  ~CrashIsolation();
  CrashIsolation(const CrashIsolation&) = delete;
  CrashIsolation& operator=(const CrashIsolation&) = delete;

  // handler(request) in a worker process; waits for its answer.
  // Thread-safe. A worker that died on a request after serving others is
  // replaced and the request tried once more: `died` means a new worker
  // died on it too. A worker still running `time_limit_s` + 10 seconds
  // after the request came is killed (SIGALRM), should its caller have
  // stopped waiting; 0: no limit.
  ChildAnswer run(Handler handler, std::string_view request, uint32_t time_limit_s) const;

 private:
  // A connection to a new worker; -1 when none could be asked for.
  int start_worker() const;

  int control_ = -1;  // our end of the zygote's socket
  pid_t zygote_ = -1;
  mutable std::mutex mutex_;
  mutable std::vector<int> idle_;  // connections to workers waiting for a request
};

}  // namespace facet::backend
