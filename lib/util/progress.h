#pragma once
// A progress bar on stderr for work longer than about a second (pbrt progressreporter.h). Silent
// when `quiet` or when stderr is not a terminal, unless forced (a --progress flag): then, with
// stderr not a terminal, it writes one line per label change and at the end instead of redrawing
// one line. Thread-safe update().
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace proxyvis {

class Progress {
 public:
  // `force` draws even when stderr is not a terminal; `quiet` (or the global switch) wins.
  Progress(std::string title, uint64_t total_work, bool quiet = false, bool force = false);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Adds `work` done; update(0) only redraws (the elapsed time of a long step).
  void update(uint64_t work = 1);
  // What runs now (e.g. a stage name), shown in place of the estimated time left, which means
  // nothing when the steps take very different times; redraws at once.
  void setLabel(std::string label);
  void done();
  // Ends the bar without drawing it full (a run that failed): on a terminal its line is erased, so
  // that the error line that follows stands alone.
  void abandon();
  double elapsedSeconds() const;
  bool enabled() const { return enabled_; }
  // Drawn as one line redrawn in place (stderr is a terminal), not as a log of lines.
  bool redraws() const { return enabled_ && terminal_; }

  // Global switch set by the apps' --quiet flag.
  static void setGloballyQuiet(bool quiet);

 private:
  void draw(uint64_t done_work, bool final);

  std::string title_;
  uint64_t total_;
  bool enabled_;
  bool terminal_;  // redraw one line; otherwise one line per label and at the end
  std::atomic<uint64_t> done_{0};
  std::atomic<bool> finished_{false};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
  std::string label_;  // guarded by mutex_
};

}  // namespace proxyvis
