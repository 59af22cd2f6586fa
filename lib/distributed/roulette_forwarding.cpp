#include "distributed/roulette_forwarding.h"

#include <algorithm>

#include "estimate/roulette.h"

namespace proxyvis {

RouletteForwarding::RouletteForwarding(size_t regions, double q_min)
    : stats_(regions), q_min_(q_min) {}

void RouletteForwarding::add(uint32_t region, double estimate, bool undecided, bool forwarded,
                             uint32_t forwards, bool visible) {
  Stats& s = stats_[region];
  s.segments += 1;
  s.estimate_sum += estimate;
  if (undecided) s.undecided += 1;
  if (forwarded) {
    s.forwarded += 1;
    s.forwards += forwards;
    if (visible) s.visible += 1;
  }
}

void RouletteForwarding::setMeasuredCosts(double local_us, double forward_us) {
  local_us_ = std::max(local_us, 1e-3);
  forward_us_ = std::max(forward_us, 1e-3);
}

std::vector<double> RouletteForwarding::probabilities(double forward_cost_us,
                                                      double local_cost_us) const {
  const double c_forward = forward_cost_us >= 0 ? std::max(forward_cost_us, 1e-3) : forward_us_;
  const double c_local = local_cost_us >= 0 ? std::max(local_cost_us, 1e-3) : local_us_;
  std::vector<double> q(stats_.size(), 1.0);
  for (size_t i = 0; i < stats_.size(); ++i) {
    const Stats& s = stats_[i];
    if (s.forwarded == 0 || s.segments == 0) continue;  // nothing learned: forward all
    const double p_undecided = s.undecided / s.segments;
    // Laplace's rule for the share of forwarded segments found visible: a region whose first
    // few forwards were all blocked must not drop to q_min, where one visible segment later
    // weighs 1/q_min.
    const double p_mh = p_undecided * ((s.visible + 1) / (s.forwarded + 2));
    const double v = s.estimate_sum / s.segments;
    // Var = A + P(MH') / q with A = V(1-V) - P(MH'); cost = c_local + c_forward P(undecided) k q.
    const double a = v * (1 - v) - p_mh;
    const double k = s.forwards / s.forwarded;
    q[i] = efficiencyOptimalQ(a, p_mh, c_local, c_forward * p_undecided * k, q_min_);
  }
  return q;
}

}  // namespace proxyvis
