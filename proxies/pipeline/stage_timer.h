#pragma once
// Seconds per named stage of a proxy-gen run, added up in a JSON object (report key "seconds").
#include <chrono>
#include <nlohmann/json.hpp>
#include <type_traits>

namespace proxyvis {

class StageTimer {
 public:
  explicit StageTimer(nlohmann::json& seconds) : seconds_(seconds) {}
  // Runs f() and adds its wall time to `stage`.
  template <typename F>
  auto run(const char* stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    auto finish = [&] {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      seconds_[stage] = seconds_.value(stage, 0.0) + s;
    };
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
  nlohmann::json& seconds_;
};

}  // namespace proxyvis
