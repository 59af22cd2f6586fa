#pragma once
// Runs a command as a child process and reports its output, how it ended, its wall time and its
// peak resident set (getrusage's ru_maxrss is per process: one child per measurement gives each
// its own peak).
#include <string>
#include <vector>

namespace proxyvis::bench {

struct ChildResult {
  std::string output;      // everything the child wrote on stdout
  int exit_code = -1;      // when it exited normally, else -1
  int signal = 0;          // the signal that ended it, else 0
  bool timed_out = false;  // killed after the time limit
  double seconds = 0;      // wall time
  long peak_rss_kb = 0;    // ru_maxrss of the child
};

// argv[0] is the program path; the child's stderr is discarded. It is killed (SIGKILL) after
// `time_limit` seconds.
ChildResult runChild(const std::vector<std::string>& argv, double time_limit);

}  // namespace proxyvis::bench
