#pragma once
// Roulette for forwarded shadow segments (docs/data_parallel.md, "Roulette"). A segment the local
// trace and the proxies leave undecided (an outside proxy of a remote rank's object says
// "blocked", no inside proxy proves it) is forwarded with probability q and then worth V/q,
// otherwise it takes the proxies' answer 0:
//     E[V~] = q * V/q = V,   Var = V(1-V) + P(MH') (1/q - 1),
// with P(MH') the share of segments that are undecided but in fact visible. Per region (screen
// tile x light) q minimises variance x cost, the cost per segment being c_local + c_forward * q *
// P(undecided) * (ranks asked per forwarded segment):
//     q = sqrt( P(MH') c_local / (A * c_forward * P(undecided) * k) ),  A = V(1-V) - P(MH'),
// clamped to [q_min, 1] (efficiencyOptimalQ of estimate/roulette.h, the single-process
// roulette's own optimum); q = 1 where A <= 0 (the proxies' errors dominate) or nothing has been
// learned yet. P(MH') = P(undecided) x (visible + 1) / (forwarded + 2) (Laplace's rule: a few
// forwards all blocked do not send q to q_min). q for a round uses only earlier rounds, so every
// estimate stays unbiased.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace proxyvis {

class RouletteForwarding {
 public:
  RouletteForwarding(size_t regions, double q_min);

  // One decided segment of region `region`: its estimate, whether the proxies left it undecided,
  // whether it was forwarded (then `forwards` ranks were asked and `visible` is its answer).
  void add(uint32_t region, double estimate, bool undecided, bool forwarded, uint32_t forwards,
           bool visible);
  // Costs measured so far on this rank, in microseconds: per segment of local work, per forward.
  void setMeasuredCosts(double local_us, double forward_us);
  // q per region for the next round; a cost < 0 takes the measured one.
  std::vector<double> probabilities(double forward_cost_us, double local_cost_us) const;

 private:
  struct Stats {
    double segments = 0, estimate_sum = 0, undecided = 0, forwarded = 0, visible = 0, forwards = 0;
  };
  std::vector<Stats> stats_;
  double q_min_;
  double local_us_ = 1, forward_us_ = 1;
};

}  // namespace proxyvis
