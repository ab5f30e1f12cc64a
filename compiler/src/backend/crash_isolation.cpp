#include "crash_isolation.h"

#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>

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

struct RequestHeader {
  CrashIsolation::Handler handler;
  uint32_t time_limit_s;
};

// An answer's first byte: what follows.
constexpr char kAnswered = 'R';     // a u64 length, then the handler's bytes
constexpr char kUnavailable = 'U';  // the zygote could not fork

bool write_all(int fd, const char* data, size_t size) {
  while (size > 0) {
    ssize_t n = send(fd, data, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= size_t(n);
  }
  return true;
}

bool read_all(int fd, std::string& out) {
  char buffer[65536];
  for (;;) {
    ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) return true;
    out.append(buffer, size_t(n));
  }
}

// Only the zygote's socket and the standard streams stay open: a copy of
// another socket's end would keep that socket from closing.
void close_other_files(int keep) {
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

// One request, in a child of the zygote: read it, run the handler on a
// large stack, answer, end without running the program's exit handlers.
[[noreturn]] void serve(int fd, const RequestHeader& header) {
  close(kControlFd);
  if (header.time_limit_s > 0) alarm(header.time_limit_s + 10);
  std::string request;
  if (!read_all(fd, request)) _exit(2);
  std::string answer;
  try {
    run_on_worker([&] { answer = header.handler(request); }, 0, {});
  } catch (...) {
    _exit(3);
  }
  std::string framed(1, kAnswered);
  uint64_t size = answer.size();
  framed.append(reinterpret_cast<const char*>(&size), sizeof size);
  framed += answer;
  _exit(write_all(fd, framed.data(), framed.size()) ? 0 : 4);
}

// Receives one request: its header and the socket to answer on. 0 when the
// Backend closed its end (or the socket failed): time to exit.
int receive(RequestHeader& header, int& fd) {
  fd = -1;
  alignas(struct cmsghdr) char control[CMSG_SPACE(sizeof(int))];
  struct iovec iov {&header, sizeof header};
  struct msghdr message {};
  message.msg_iov = &iov;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof control;
  ssize_t n;
  do {
    n = recvmsg(kControlFd, &message, MSG_CMSG_CLOEXEC);
  } while (n < 0 && errno == EINTR);
  if (n <= 0) return 0;
  for (struct cmsghdr* c = CMSG_FIRSTHDR(&message); c; c = CMSG_NXTHDR(&message, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS) std::memcpy(&fd, CMSG_DATA(c), sizeof fd);
  }
  return int(n);
}

// The zygote: forks a child per request until the socket closes. Makes no
// allocation, so that it never needs a lock it might have been copied with.
[[noreturn]] void zygote_main(int control) {
  close_other_files(control);
  reset_signals();
  for (;;) {
    RequestHeader header{};
    int fd = -1;
    int received = receive(header, fd);
    if (received == 0) _exit(0);
    if (fd < 0) continue;
    if (size_t(received) == sizeof header) {
      pid_t child = fork();
      if (child == 0) serve(fd, header);
      if (child < 0) (void)!write(fd, &kUnavailable, 1);
    }
    close(fd);
  }
}

bool send_request(int control, const RequestHeader& header, int fd) {
  alignas(struct cmsghdr) char buffer[CMSG_SPACE(sizeof(int))] = {};
  struct iovec iov {const_cast<RequestHeader*>(&header), sizeof header};
  struct msghdr message {};
  message.msg_iov = &iov;
  message.msg_iovlen = 1;
  message.msg_control = buffer;
  message.msg_controllen = sizeof buffer;
  struct cmsghdr* c = CMSG_FIRSTHDR(&message);
  c->cmsg_level = SOL_SOCKET;
  c->cmsg_type = SCM_RIGHTS;
  c->cmsg_len = CMSG_LEN(sizeof(int));
  std::memcpy(CMSG_DATA(c), &fd, sizeof fd);
  ssize_t n;
  do {
    n = sendmsg(control, &message, MSG_NOSIGNAL);
  } while (n < 0 && errno == EINTR);
  return n == ssize_t(sizeof header);
}

ChildAnswer decode(std::string reply) {
  ChildAnswer answer;
  answer.kind = ChildAnswer::Kind::died;
  if (reply.size() == 1 && reply[0] == kUnavailable) answer.kind = ChildAnswer::Kind::unavailable;
  uint64_t size = 0;
  if (reply.size() < 1 + sizeof size || reply[0] != kAnswered) return answer;
  std::memcpy(&size, reply.data() + 1, sizeof size);
  if (size != reply.size() - 1 - sizeof size) return answer;
  answer.kind = ChildAnswer::Kind::answered;
  answer.bytes = reply.substr(1 + sizeof size);
  return answer;
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
  if (control_ < 0) return;
  close(control_);
  while (waitpid(zygote_, nullptr, 0) < 0 && errno == EINTR) {
  }
}

ChildAnswer CrashIsolation::run(Handler handler, std::string_view request, uint32_t time_limit_s) const {
  if (control_ < 0) return {};
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return {};
  bool sent = send_request(control_, RequestHeader{handler, time_limit_s}, ends[1]);
  close(ends[1]);
  if (!sent) {
    close(ends[0]);
    return {};
  }
  // A child that died while reading leaves the rest unsent; its (empty)
  // answer says so.
  write_all(ends[0], request.data(), request.size());
  shutdown(ends[0], SHUT_WR);
  std::string reply;
  bool read = read_all(ends[0], reply);
  close(ends[0]);
  if (!read) return {ChildAnswer::Kind::died, {}};
  return decode(std::move(reply));
}

}  // namespace facet::backend
