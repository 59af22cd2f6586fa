// RouletteForwarding's q against the closed form of its header, and its edge cases; and a Monte
// Carlo check that V~ is unbiased with the variance V(1-V) + P(MH')(1/q - 1).
#include <gtest/gtest.h>

#include <cmath>

#include "distributed/roulette_forwarding.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

TEST(RouletteForwarding, ForwardsEverythingUntilItHasLearned) {
  RouletteForwarding r(3, 0.05);
  for (double q : r.probabilities(20, 1)) EXPECT_EQ(q, 1.0);
}

TEST(RouletteForwarding, ClosedFormQ) {
  RouletteForwarding r(1, 0.01);
  // 1000 segments: 400 undecided, all forwarded (1 rank each), 100 of them visible; the other
  // 600 visible without a forward. V = 0.7; P(MH') = 0.4 x 101/402 (Laplace's rule).
  for (int i = 0; i < 600; ++i) r.add(0, 1.0, false, false, 0, false);
  for (int i = 0; i < 400; ++i) r.add(0, i < 100 ? 1.0 : 0.0, true, true, 1, i < 100);
  const double c_local = 1, c_forward = 20;
  const double p_mh = 0.4 * 101.0 / 402.0, a = 0.7 * 0.3 - p_mh;
  const double expected = std::sqrt(p_mh * c_local / (a * c_forward * 0.4 * 1.0));
  EXPECT_NEAR(r.probabilities(c_forward, c_local)[0], expected, 1e-12);
  // Dearer forwards, smaller q; clamped at q_min.
  EXPECT_LT(r.probabilities(200, 1)[0], expected);
  EXPECT_EQ(r.probabilities(1e6, 1e-3)[0], 0.01);
}

TEST(RouletteForwarding, ProxyErrorsDominatingMeansForwardAll) {
  RouletteForwarding r(1, 0.05);
  // V = 0.5, P(MH') = 0.5 > V(1-V) = 0.25: A < 0, q = 1.
  for (int i = 0; i < 100; ++i) r.add(0, i % 2 ? 1.0 : 0.0, true, true, 1, i % 2);
  EXPECT_EQ(r.probabilities(1000, 1)[0], 1.0);
}

TEST(RouletteForwarding, FewBlockedForwardsDoNotSendQToTheFloor) {
  // Three forwards, all blocked: Laplace's rule still assumes visible ones are possible.
  RouletteForwarding few(1, 0.05), many(1, 0.05);
  for (int i = 0; i < 3; ++i) few.add(0, 0.0, true, true, 1, false);
  for (int i = 0; i < 7; ++i) few.add(0, 1.0, false, false, 0, false);
  for (int i = 0; i < 3000; ++i) many.add(0, 0.0, true, true, 1, false);
  for (int i = 0; i < 7000; ++i) many.add(0, 1.0, false, false, 0, false);
  const double q_few = few.probabilities(20, 1)[0], q_many = many.probabilities(20, 1)[0];
  EXPECT_GT(q_few, 0.1);
  EXPECT_LT(q_many, q_few);
  EXPECT_EQ(q_many, 0.05);
}

// The estimator itself: undecided segments (probability u) are visible with probability m/u;
// forwarded with probability q, worth V/q. Mean and variance against the closed form.
TEST(RouletteForwarding, EstimateIsUnbiasedWithTheClosedFormVariance) {
  const double v_clear = 0.5, u = 0.4, mh = 0.15, q = 0.3;  // P(visible, decided) = 0.5
  Rng rng(42, 0);
  const int n = 2'000'000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double a = rng.uniformDouble();
    double est;
    if (a < v_clear) {
      est = 1;
    } else if (a < v_clear + u) {
      const bool visible = a < v_clear + mh;
      est = rng.uniformDouble() < q ? (visible ? 1 / q : 0) : 0;
    } else {
      est = 0;
    }
    sum += est;
    sum2 += est * est;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  const double v = v_clear + mh;
  const double closed = v * (1 - v) + mh * (1 / q - 1);
  EXPECT_NEAR(mean, v, 4 * std::sqrt(closed / n));  // z-test at 4 sigma
  EXPECT_NEAR(var, closed, 0.01 * closed);
}

}  // namespace
}  // namespace proxyvis
