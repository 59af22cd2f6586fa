#pragma once
// Wall-clock timing: the renderer's phases, the tables and the benches (steady clock: immune to
// clock adjustments).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <thread>

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

// CPU time of the whole process (every thread), in seconds.
inline double processCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return 0;
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The steady clock in seconds since its epoch (CLOCK_MONOTONIC on Linux: the same clock for every
// process of one host, so ranks on one host may compare its readings).
inline double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Waits until steadySeconds() >= t: sleeps while more than 200 us remain (so that ranks sharing
// a core leave it to the others), then yields. Returns the seconds waited.
inline double waitUntilSteady(double t) {
  const double start = steadySeconds();
  for (double now = start; now < t; now = steadySeconds()) {
    if (t - now > 200e-6)
      std::this_thread::sleep_for(std::chrono::duration<double>(t - now - 100e-6));
    else
      std::this_thread::yield();
  }
  return std::max(0.0, steadySeconds() - start);
}

}  // namespace proxyvis
