#pragma once
// A time budget for the generation of one proxy. Long-running stages (alpha wrap, seed search,
// erosion, decimation) poll it and stop cleanly by throwing Error, so a run can never go on for
// longer than the user allowed (proxy-gen --max-seconds) and never leaves output behind.
#include <chrono>
#include <string>

namespace proxyvis {

class TimeBudget {
 public:
  // No limit.
  TimeBudget() = default;
  // `seconds` from now; `source` names the mesh in the error message.
  TimeBudget(double seconds, std::string source);

  bool limited() const { return limited_; }
  double seconds() const { return seconds_; }
  bool expired() const;
  // Throws Error naming the source and `stage` when the budget is spent.
  void check(const char* stage) const;

 private:
  bool limited_ = false;
  double seconds_ = 0;
  std::chrono::steady_clock::time_point end_{};
  std::string source_;
};

// Polls `budget` when not null (the generators' options carry an optional pointer).
inline void checkBudget(const TimeBudget* budget, const char* stage) {
  if (budget) budget->check(stage);
}

}  // namespace proxyvis
