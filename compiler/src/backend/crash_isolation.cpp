#include "crash_isolation.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <mutex>

#include "worker.h"

// Set by libFuzzer (and by programs that want a last word before a
// sanitizer ends them); weak, so that it is null in a build without one. A
// child must not run the fuzzer's: it would record the input as a crash of
// the fuzzed program, which the child's parent goes on running.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace facet::backend {
namespace {

// The zygote's end of its request socket, moved to a fixed number.
constexpr int kControlFd = 3;

// Precedes each request on a worker's connection.
struct RequestHeader {
  CrashIsolation::Handler handler;
  uint32_t time_limit_s;
  uint64_t size;  // of the request's bytes, which follow
};

// An answer's first byte: what follows.
constexpr char kAnswered = 'R';     // a u64 length, then the handler's bytes
constexpr char kUnavailable = 'U';  // the zygote could not fork a worker

bool write_all(int fd, const void* bytes, size_t size) {
  const char* data = static_cast<const char*>(bytes);
  while (size > 0) {
    ssize_t n = send(fd, data, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= size_t(n);
  }
  return true;
}

// False at the end of the stream (or on an error) before `size` bytes.
bool read_exact(int fd, void* bytes, size_t size) {
  char* data = static_cast<char*>(bytes);
  while (size > 0) {
    ssize_t n = read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= size_t(n);
  }
  return true;
}

// Only the zygote's socket stays open, and the standard streams become
// /dev/null: a copy of another socket's end would keep that socket from
// closing, and a copy of the caller's stdout or stderr (often a pipe that a
// build tool reads to its end) would keep that pipe open after the caller
// ended. A child's crash is reported by its parent instead.
void close_other_files(int keep) {
  int null = open("/dev/null", O_RDWR);
  if (null >= 0) {
    for (int fd = 0; fd < kControlFd; ++fd) {
      if (fd != keep && fd != null) dup2(null, fd);
    }
    if (null >= kControlFd && null != keep) close(null);
  }
  if (keep != kControlFd) {
    dup2(keep, kControlFd);
    if (keep < kControlFd) close(keep);
  }
  if (close_range(kControlFd + 1, ~0U, 0) != 0) {
    for (int fd = kControlFd + 1; fd < 4096; ++fd) close(fd);
  }
}

// Every signal to its default action (a crash ends the child quietly, not
// through the parent's handlers: a fuzzer's, a test runner's), nothing
// blocked, children reaped by the system.
void reset_signals() {
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  for (int sig = 1; sig < NSIG; ++sig) {
    if (sig != SIGKILL && sig != SIGSTOP) sigaction(sig, &default_action, nullptr);
  }
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGCHLD, &ignore, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
}

// A worker, in a child of the zygote: answers requests on its connection
// until the connection closes, each handler on a large stack; ends without
// running the program's exit handlers.
[[noreturn]] void serve(int fd, pid_t zygote) {
  close(kControlFd);
  // Ends with the zygote, which ends with the Backend or its process: no
  // worker outlives the compiler that asked for it.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != zygote) _exit(5);
  for (;;) {
    RequestHeader header{};
    if (!read_exact(fd, &header, sizeof header)) _exit(0);
    std::string request(header.size, '\0');
    if (!read_exact(fd, request.data(), request.size())) _exit(0);
    if (header.time_limit_s > 0) alarm(header.time_limit_s + 10);
    std::string answer;
    try {
      run_on_worker([&] { answer = header.handler(request); }, 0, {});
    } catch (...) {
      _exit(3);
    }
    alarm(0);
    uint64_t size = answer.size();
    if (!write_all(fd, &kAnswered, 1) || !write_all(fd, &size, sizeof size) || !write_all(fd, answer.data(), size)) {
      _exit(4);
    }
  }
}

// A one-byte message with room for one file descriptor (SCM_RIGHTS): how a
// worker's connection reaches the zygote. Points into itself: not copied.
struct FdMessage {
  char byte = 0;
  alignas(struct cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  struct iovec iov {&byte, 1};
  struct msghdr header {};

  FdMessage() {
    header.msg_iov = &iov;
    header.msg_iovlen = 1;
    header.msg_control = control;
    header.msg_controllen = sizeof control;
  }
  FdMessage(const FdMessage&) = delete;
  FdMessage& operator=(const FdMessage&) = delete;
};

// Receives a connection for a new worker. -1 when the Backend closed its
// end (or the socket failed): time to exit; -2 for a message without one.
int receive_connection() {
  FdMessage message;
  ssize_t n;
  do {
    n = recvmsg(kControlFd, &message.header, MSG_CMSG_CLOEXEC);
  } while (n < 0 && errno == EINTR);
  if (n <= 0) return -1;
  int fd = -2;
  for (struct cmsghdr* c = CMSG_FIRSTHDR(&message.header); c; c = CMSG_NXTHDR(&message.header, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS) std::memcpy(&fd, CMSG_DATA(c), sizeof fd);
  }
  return fd;
}

// The zygote: forks a worker per connection until its socket closes. Makes
// no allocation, so that it never needs a lock it might have been copied
// with.
[[noreturn]] void zygote_main(int control) {
  close_other_files(control);
  reset_signals();
  const pid_t self = getpid();
  for (;;) {
    int fd = receive_connection();
    if (fd == -1) _exit(0);
    if (fd < 0) continue;
    pid_t child = fork();
    if (child == 0) serve(fd, self);
    if (child < 0) (void)!write(fd, &kUnavailable, 1);
    close(fd);
  }
}

bool send_connection(int control, int fd) {
  FdMessage message;
  struct cmsghdr* c = CMSG_FIRSTHDR(&message.header);
  c->cmsg_level = SOL_SOCKET;
  c->cmsg_type = SCM_RIGHTS;
  c->cmsg_len = CMSG_LEN(sizeof(int));
  std::memcpy(CMSG_DATA(c), &fd, sizeof fd);
  ssize_t n;
  do {
    n = sendmsg(control, &message.header, MSG_NOSIGNAL);
  } while (n < 0 && errno == EINTR);
  return n == 1;
}

// One request to the worker on `fd` and its answer.
ChildAnswer exchange(int fd, CrashIsolation::Handler handler, std::string_view request, uint32_t time_limit_s) {
  RequestHeader header{handler, time_limit_s, request.size()};
  // A worker that died while reading leaves the rest unsent; the missing
  // answer says so.
  if (write_all(fd, &header, sizeof header)) write_all(fd, request.data(), request.size());
  ChildAnswer answer;
  answer.kind = ChildAnswer::Kind::died;
  char kind = 0;
  uint64_t size = 0;
  if (!read_exact(fd, &kind, 1)) return answer;
  if (kind == kUnavailable) return {ChildAnswer::Kind::unavailable, {}};
  if (kind != kAnswered || !read_exact(fd, &size, sizeof size)) return answer;
  std::string bytes(size, '\0');
  if (!read_exact(fd, bytes.data(), bytes.size())) return answer;
  return {ChildAnswer::Kind::answered, std::move(bytes)};
}

}  // namespace

void WireWriter::text(std::string_view value) {
  u32(uint32_t(value.size()));
  bytes_.append(value);
}

void WireWriter::words(const std::vector<uint32_t>& value) {
  u32(uint32_t(value.size()));
  bytes_.append(reinterpret_cast<const char*>(value.data()), value.size() * sizeof(uint32_t));
}

bool WireReader::take(void* out, size_t size) {
  if (!ok_ || bytes_.size() - at_ < size) {
    ok_ = false;
    return false;
  }
  if (size == 0) return true;
  std::memcpy(out, bytes_.data() + at_, size);
  at_ += size;
  return true;
}

uint8_t WireReader::byte() {
  uint8_t value = 0;
  take(&value, sizeof value);
  return value;
}

uint32_t WireReader::u32() {
  uint32_t value = 0;
  take(&value, sizeof value);
  return value;
}

std::string WireReader::text() {
  uint32_t size = u32();
  if (!ok_ || bytes_.size() - at_ < size) {
    ok_ = false;
    return {};
  }
  std::string value(bytes_.substr(at_, size));
  at_ += size;
  return value;
}

std::vector<uint32_t> WireReader::words() {
  uint32_t count = u32();
  if (!ok_ || (bytes_.size() - at_) / sizeof(uint32_t) < count) {
    ok_ = false;
    return {};
  }
  std::vector<uint32_t> value(count);
  take(value.data(), count * sizeof(uint32_t));
  return value;
}

CrashIsolation::CrashIsolation() {
  int sockets[2];
  if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sockets) != 0) return;
  pid_t pid = fork();
  if (pid == 0) {
    close(sockets[0]);
    zygote_main(sockets[1]);
  }
  close(sockets[1]);
  if (pid < 0) {
    close(sockets[0]);
    return;
  }
  control_ = sockets[0];
  zygote_ = pid;
}

CrashIsolation::~CrashIsolation() {
  for (int fd : idle_) close(fd);  // their workers exit
  if (control_ < 0) return;
  close(control_);
  while (waitpid(zygote_, nullptr, 0) < 0 && errno == EINTR) {
  }
}

int CrashIsolation::start_worker() const {
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return -1;
  bool sent = send_connection(control_, ends[1]);
  close(ends[1]);
  if (sent) return ends[0];
  close(ends[0]);
  return -1;
}

ChildAnswer CrashIsolation::run(Handler handler, std::string_view request, uint32_t time_limit_s) const {
  if (control_ < 0) return {};
  // A worker that served earlier requests and dies on this one gets a second
  // try in a new worker: only a crash that repeats there is the request's.
  for (bool retry = false;; retry = true) {
    int fd = -1;
    if (!retry) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!idle_.empty()) {
        fd = idle_.back();
        idle_.pop_back();
      }
    }
    const bool reused = fd >= 0;
    if (!reused) fd = start_worker();
    if (fd < 0) return {};
    ChildAnswer answer = exchange(fd, handler, request, time_limit_s);
    if (answer.kind == ChildAnswer::Kind::answered) {
      std::lock_guard<std::mutex> lock(mutex_);
      idle_.push_back(fd);
      return answer;
    }
    close(fd);
    if (!reused || answer.kind == ChildAnswer::Kind::unavailable) return answer;
  }
}

}  // namespace facet::backend
