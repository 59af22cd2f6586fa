#include "estimate/roulette.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace proxyvis {

namespace {

// a (1/q - 1), with 0 for a = 0 and +inf for a > 0, q = 0.
double addedVariance(double a, double q) {
  if (a <= 0) return 0.0;
  return q > 0 ? a * (1 / q - 1) : std::numeric_limits<double>::infinity();
}

// Coordinate descent on (q0, q1): each step is exact per coordinate and the product is convex in
// each, so it settles in a handful of rounds; the cap only bounds a pathological oscillation.
constexpr int kMaxDescentRounds = 200;
// q changes below this are float noise (q lies in [q_min, 1]): the descent has converged.
constexpr double kDescentTolerance = 1e-13;

}  // namespace

double efficiencyOptimalQ(double base_variance, double error_variance, double base_cost,
                          double cost_per_q, double q_min) {
  if (error_variance <= 0) return q_min;
  if (base_variance <= 0 || cost_per_q <= 0) return 1;
  return std::clamp(std::sqrt(error_variance * base_cost / (base_variance * cost_per_q)), q_min,
                    1.0);
}

RouletteModel RouletteModel::fromPoint(const ClassProbabilities& c, const ClassCosts& costs) {
  const double v = c.vAvg();
  return {v * (1 - v), c.mh, c.hm, c.proxyBlocked(), costs};
}

double rouletteVariance(const RouletteModel& m, const RouletteQ& q) {
  return m.var_exact + addedVariance(m.p_mh, q.q0) + addedVariance(m.p_hm, q.q1);
}

double rouletteCost(const RouletteModel& m, const RouletteQ& q) {
  const double p0 = m.p_blocked, p1 = 1 - m.p_blocked;
  return m.costs.per_sample + p0 * (m.costs.proxy[0] + q.q0 * m.costs.original[0]) +
         p1 * (m.costs.proxy[1] + q.q1 * m.costs.original[1]);
}

double exactCost(const RouletteModel& m) {
  return m.costs.per_sample + m.p_blocked * m.costs.original[0] +
         (1 - m.p_blocked) * m.costs.original[1];
}

RouletteQ optimalRouletteQ(const RouletteModel& m, ProxyClass cls, double q_min) {
  PV_CHECK(q_min > 0 && q_min <= 1);
  const bool need0 = cls != ProxyClass::kInside;   // MH' possible
  const bool need1 = cls != ProxyClass::kOutside;  // HM' possible
  RouletteQ q{need0 ? 1.0 : 0.0, need1 ? 1.0 : 0.0};
  const double p0 = m.p_blocked, p1 = 1 - m.p_blocked;
  const double cbar_p = m.costs.per_sample + p0 * m.costs.proxy[0] + p1 * m.costs.proxy[1];
  const double b0 = p0 * m.costs.original[0], b1 = p1 * m.costs.original[1];
  const double base = m.var_exact - (need0 ? m.p_mh : 0) - (need1 ? m.p_hm : 0);
  for (int round = 0; round < kMaxDescentRounds; ++round) {
    const RouletteQ old = q;
    if (need0) {
      const double v0 = base + (need1 && m.p_hm > 0 ? m.p_hm / q.q1 : 0);
      q.q0 = efficiencyOptimalQ(v0, m.p_mh, cbar_p + q.q1 * b1, b0, q_min);
    }
    if (need1) {
      const double v0 = base + (need0 && m.p_mh > 0 ? m.p_mh / q.q0 : 0);
      q.q1 = efficiencyOptimalQ(v0, m.p_hm, cbar_p + q.q0 * b0, b1, q_min);
    }
    if (std::abs(q.q0 - old.q0) < kDescentTolerance && std::abs(q.q1 - old.q1) < kDescentTolerance)
      break;
  }
  return q;
}

double rouletteEfficiencyVsExact(const RouletteModel& m, const RouletteQ& q) {
  const double var = rouletteVariance(m, q);
  if (!(m.var_exact > 0)) return var > 0 ? 0.0 : exactCost(m) / rouletteCost(m, q);
  return m.var_exact * exactCost(m) / (var * rouletteCost(m, q));
}

}  // namespace proxyvis
