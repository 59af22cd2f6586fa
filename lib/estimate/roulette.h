#pragma once
// Correction by roulette (docs/design.md): always trace the proxy; where its answer can be wrong,
// trace the original with probability q_i (i = V'):
//   V' = 0:  V~ = V / q0 with probability q0, else 0
//   V' = 1:  V~ = 1 - (1 - V) / q1 with probability q1, else 1
// Unbiased for any q_i > 0 where the error class (MH' for i = 0, HM' for i = 1) is possible.
//   Var  = V(1-V) + P(MH')(1/q0 - 1) + P(HM')(1/q1 - 1)
//   Cost = c_s + sum_i P(V'=i) (c_p|i + q_i c_o|i)     (c_s = ClassCosts::per_sample)
// Costs are per class of V' (docs/design.md, measured costs: where the proxy blocks, both rays cost
// several times more than where it does not; one average cost overstates the gain).
#include "estimate/class_probabilities.h"

namespace proxyvis {

// Mean cost of one ray (any unit, e.g. ns or cycles) given the proxy's answer V' = i.
struct ClassCosts {
  double proxy[2] = {1, 1};     // c_p | V' = 0, c_p | V' = 1
  double original[2] = {1, 1};  // c_o | V' = 0, c_o | V' = 1
  // Paid by every light sample whatever the estimator: light sampling, shading, accumulation,
  // the primary ray's share (docs/design.md, costs point 4). Added to both exact and roulette
  // costs; the larger it is, the more variance matters against ray savings.
  double per_sample = 0;

  bool operator==(const ClassCosts&) const = default;
};

struct RouletteQ {
  double q0 = 1, q1 = 1;
};

// What the roulette optimum depends on. For one shading point, var_exact = V(1-V); for a region
// of points, the mean of V_p(1-V_p) over its samples (the variance exact visibility leaves in each
// pixel; the pooled V_avg(1-V_avg) would overstate it by the spread between points).
struct RouletteModel {
  double var_exact = 0;
  double p_mh = 0, p_hm = 0;  // P(MH'), P(HM')
  double p_blocked = 0;       // P(V' = 0)
  ClassCosts costs;
  static RouletteModel fromPoint(const ClassProbabilities& c, const ClassCosts& costs);
};

// Var as above; an error class with probability > 0 and q = 0 gives +infinity (biased).
double rouletteVariance(const RouletteModel& m, const RouletteQ& q);
double rouletteCost(const RouletteModel& m, const RouletteQ& q);
// Exact visibility: one original ray per sample, c_s + sum_i P(V'=i) c_o|i.
double exactCost(const RouletteModel& m);

// The q in [q_min, 1] minimising (base_variance + error_variance / q) * (base_cost + cost_per_q *
// q): variance x cost of one roulette choice whose correction, taken with probability q, costs
// cost_per_q and adds error_variance (1/q - 1) to the variance. The product is convex in q and
// stationary at sqrt(error_variance * base_cost / (base_variance * cost_per_q)). q_min where
// error_variance <= 0 (nothing to correct), 1 where base_variance <= 0 or cost_per_q <= 0 (the
// product falls with q everywhere). Both roulettes derive their q from it: per proxy-answer class
// here (optimalRouletteQ) and per region for forwarded segments (lib/distributed).
double efficiencyOptimalQ(double base_variance, double error_variance, double base_cost,
                          double cost_per_q, double q_min);

// The q minimising Var x Cost over [q_min, 1]^2, with q1 = 0 exactly for a verified outside proxy
// and q0 = 0 for a verified inside one (that error class cannot occur). An error class that is
// possible but estimated at 0 gets q_min, which keeps the estimate unbiased when the statistics
// are wrong. Unclamped and with var_exact > P(MH') + P(HM') the optimum is
//   q_i = sqrt( P(error | V'=i) * cbar_p / (c_o|i * (V(1-V) - P(MH') - P(HM'))) ),
// cbar_p = c_s + sum_i P(V'=i) c_p|i; the product is convex in each q_i separately, so coordinate
// descent with that closed form per coordinate also handles the clamped cases.
RouletteQ optimalRouletteQ(const RouletteModel& m, ProxyClass cls, double q_min);

// Efficiency relative to exact: var_exact * exactCost / (rouletteVariance * rouletteCost);
// > 1 means roulette wins. With var_exact = 0 (nothing to estimate): the cost ratio
// exactCost / rouletteCost if roulette adds no variance either, else 0.
double rouletteEfficiencyVsExact(const RouletteModel& m, const RouletteQ& q);

}  // namespace proxyvis
