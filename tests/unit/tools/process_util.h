// Child processes a test can kill: started without a shell (so the pid is
// the program's own), optionally in a process group of their own.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace facet::tools::testing {

struct Spawned {
  pid_t pid = -1;
};

// Runs `argv` in `dir` with standard output and error appended to `log`;
// with `own_group`, the child leads a new process group, so that killing
// the group reaches every process it forks.
inline Spawned spawn_in(const std::filesystem::path& dir, const std::vector<std::string>& argv,
                        const std::filesystem::path& log, bool own_group = false) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = ::fork();
  if (pid == 0) {
    if (own_group) ::setpgid(0, 0);
    FILE* out = std::fopen(log.c_str(), "ab");
    if (::chdir(dir.c_str()) != 0 || !out) ::_exit(126);
    ::dup2(::fileno(out), 1);
    ::dup2(::fileno(out), 2);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return Spawned{pid};
}

struct Ended {
  bool exited = false;  // else killed by a signal
  int code = -1;        // the exit status, or the signal
};

inline Ended wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return Ended{true, WEXITSTATUS(status)};
  return Ended{false, WIFSIGNALED(status) ? WTERMSIG(status) : -1};
}

// Whether `pid` (a child of ours) is still running; it is not reaped.
inline bool still_running(pid_t pid) {
  siginfo_t info{};
  return ::waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == 0;
}

}  // namespace facet::tools::testing
