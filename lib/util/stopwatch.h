#pragma once
// Wall-clock timing: the renderer's phases, the tables and the benches (steady clock: immune to
// clock adjustments).
#include <chrono>

namespace proxyvis {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace proxyvis
