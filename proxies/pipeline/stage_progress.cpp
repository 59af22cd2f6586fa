#include "proxies/pipeline/stage_progress.h"

#include <chrono>

#include "proxies/pipeline/proxy_report_text.h"

namespace proxyvis {

StageProgress::StageProgress(bool quiet, bool force)
    : progress_("proxy-gen", kProxyGenSteps, quiet, force) {
  // A log (stderr not a terminal, --progress) gets one line per stage and no redraws.
  if (!progress_.redraws()) return;
  ticker_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; }))
      progress_.update(0);
  });
}

StageProgress::~StageProgress() {
  stopTicker();
  progress_.abandon();  // no-op after done()
}

void StageProgress::stopTicker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

void StageProgress::stage(const std::string& key) {
  for (const StageName& s : proxyGenStages()) {
    if (key != s.key) continue;
    if (s.step > step_) {
      progress_.update(uint64_t(s.step - step_));
      step_ = s.step;
    }
    progress_.setLabel(s.label);
    return;
  }
  progress_.setLabel(key);  // a stage the list does not know yet
}

void StageProgress::done() {
  stopTicker();
  progress_.done();
}

}  // namespace proxyvis
