#include "util/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace proxyvis {

namespace {
std::atomic<bool> g_quiet{false};
}

void Progress::setGloballyQuiet(bool quiet) {
  g_quiet = quiet;
}

Progress::Progress(std::string title, uint64_t total_work, bool quiet, bool force)
    : title_(std::move(title)),
      total_(total_work == 0 ? 1 : total_work),
      enabled_(!quiet && !g_quiet && (force || ::isatty(STDERR_FILENO))),
      terminal_(::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  done();
}

double Progress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(uint64_t work) {
  uint64_t now_done = done_.fetch_add(work) + work;
  if (!redraws() || finished_) return;  // a log gets no redraws
  auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(200)) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  last_draw_ = now;
  draw(now_done, false);
}

void Progress::setLabel(std::string label) {
  if (!enabled_ || finished_) return;
  std::lock_guard lock(mutex_);
  if (label == label_) return;  // a stage that runs again in a row
  label_ = std::move(label);
  last_draw_ = std::chrono::steady_clock::now();
  draw(done_, false);
}

void Progress::done() {
  if (finished_.exchange(true)) return;
  if (enabled_) {
    std::lock_guard lock(mutex_);
    label_.clear();
    draw(total_, true);
  }
}

void Progress::abandon() {
  if (finished_.exchange(true)) return;
  if (redraws()) {
    std::lock_guard lock(mutex_);
    std::fputs("\r\033[K", stderr);  // erase the bar's line: the error line takes it
    std::fflush(stderr);
  }
}

void Progress::draw(uint64_t done_work, bool final) {
  constexpr int kWidth = 40;
  double frac = std::min(1.0, double(done_work) / double(total_));
  int filled = int(frac * kWidth);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
  bar[kWidth] = 0;
  double t = elapsedSeconds();
  double eta = frac > 0 ? t / frac - t : 0;
  // The tail is padded so that a shorter one overwrites all of a longer one on a terminal.
  std::string tail = final            ? std::string()
                     : label_.empty() ? fmt::format("eta {}s", int(eta))
                                      : label_;
  if (terminal_) tail = fmt::format("{:<24}", tail);
  std::fprintf(stderr, "%s%s [%s] %5.1f%% %6.1fs %s%s", terminal_ ? "\r" : "", title_.c_str(), bar,
               100 * frac, t, tail.c_str(), final || !terminal_ ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace proxyvis
