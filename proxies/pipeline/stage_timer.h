#pragma once
// Seconds per named stage of a proxy-gen run, added up in the report's "seconds",
// and a call as each stage starts (proxy-gen's progress bar).
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>

#include "util/stopwatch.h"

namespace proxyvis {

class StageTimer {
 public:
  explicit StageTimer(std::map<std::string, double>& seconds,
                      std::function<void(const std::string&)> on_start = {})
      : seconds_(seconds), on_start_(std::move(on_start)) {}
  // Runs f() and adds its wall time to `stage`.
  template <typename F>
  auto run(const char* stage, F&& f) {
    if (on_start_) on_start_(stage);
    const Stopwatch clock;
    auto finish = [&] { seconds_[stage] += clock.seconds(); };
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      finish();
    } else {
      auto r = f();
      finish();
      return r;
    }
  }

 private:
  std::map<std::string, double>& seconds_;
  std::function<void(const std::string&)> on_start_;
};

}  // namespace proxyvis
