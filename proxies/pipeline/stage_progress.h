#pragma once
// proxy-gen's progress bar for one mesh: the six steps of proxy_report_text.h (load, validate,
// build, budget reduction, verify, measure), the name of the stage running and the elapsed time,
// redrawn while a long stage runs. On stderr, only when it is a terminal or with --progress, never
// with
// --quiet (util/progress.h).
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "util/progress.h"

namespace proxyvis {

class StageProgress {
 public:
  StageProgress(bool quiet, bool force);
  ~StageProgress();  // a bar not finished by done() ends where it stands (the run failed)
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  // A stage starts: `key` as in the report's "seconds" (proxy_pipeline.h's on_stage, or "load").
  // The bar moves to the stage's step and never back (the budget fallbacks verify again).
  void stage(const std::string& key);
  // All stages are done: the bar is drawn full and ends its line.
  void done();

 private:
  void stopTicker();

  Progress progress_;
  int step_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread ticker_;  // redraws the elapsed time of a long stage
};

}  // namespace proxyvis
