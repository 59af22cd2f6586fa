#include "child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include "util/error.h"
#include "util/stopwatch.h"

namespace proxyvis::bench {

ChildResult runChild(const std::vector<std::string>& argv, double time_limit) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw Error("", "cannot create a pipe", "the system refused");
  const Stopwatch watch;
  const pid_t pid = fork();
  if (pid < 0) throw Error("", "cannot start a child process", "fork failed");
  if (pid == 0) {
    dup2(pipe_fds[1], STDOUT_FILENO);
    // Library chatter (OpenMesh's add_face warnings) would interleave with the table.
    const int null_fd = open("/dev/null", O_WRONLY);
    if (null_fd >= 0) dup2(null_fd, STDERR_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  ChildResult r;
  char buffer[4096];
  bool open = true;
  while (open) {
    const double left = time_limit - watch.seconds();
    if (left <= 0) {
      kill(pid, SIGKILL);
      r.timed_out = true;
      break;
    }
    pollfd p{pipe_fds[0], POLLIN, 0};
    if (poll(&p, 1, int(std::min(left, 1.0) * 1000) + 1) <= 0) continue;
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n > 0)
      r.output.append(buffer, size_t(n));
    else
      open = false;
  }
  close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  r.seconds = watch.seconds();
  r.peak_rss_kb = usage.ru_maxrss;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

}  // namespace proxyvis::bench
