#pragma once
// A progress bar on stderr for work longer than about a second (pbrt progressreporter.h). Silent
// when `quiet` or when stderr is not a terminal. Thread-safe update().
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace proxyvis {

class Progress {
 public:
  Progress(std::string title, uint64_t total_work, bool quiet = false);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void update(uint64_t work = 1);
  void done();
  double elapsedSeconds() const;

  // Global switch set by the apps' --quiet flag.
  static void setGloballyQuiet(bool quiet);

 private:
  void draw(uint64_t done_work, bool final);

  std::string title_;
  uint64_t total_;
  bool enabled_;
  std::atomic<uint64_t> done_{0};
  std::atomic<bool> finished_{false};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace proxyvis
