#include "util/stats.h"

#include <gtest/gtest.h>

#include "util/rng.h"

namespace proxyvis {
namespace {

TEST(RunningStats, MatchesTwoPassMeanAndVariance) {
  const double xs[] = {1.5, 2.0, -3.0, 7.25, 0.0, 4.0};
  RunningStats s;
  double sum = 0;
  for (double x : xs) s.add(x), sum += x;
  double mean = sum / 6, ss = 0;
  for (double x : xs) ss += (x - mean) * (x - mean);
  EXPECT_NEAR(s.mean(), mean, 1e-12);
  EXPECT_NEAR(s.variance(), ss / 5, 1e-12);
}

TEST(RunningStats, MergeEqualsSequential) {
  Rng rng(1, 2);
  RunningStats all, a, b;
  for (int i = 0; i < 1000; ++i) {
    double x = rng.uniformDouble() * 10 - 3;
    all.add(x);
    (i % 3 == 0 ? a : b).add(x);
  }
  a.merge(b);
  EXPECT_EQ(a.count(), all.count());
  EXPECT_NEAR(a.mean(), all.mean(), 1e-12);
  EXPECT_NEAR(a.variance(), all.variance(), 1e-10);
}

TEST(Wilson, ZeroCountUpperBoundIsAboutThreeOverN) {
  Interval iv = wilsonInterval(0, 1000000);
  EXPECT_EQ(iv.lo, 0.0);
  EXPECT_NEAR(iv.hi * 1e6, 3.84, 0.01);
}

TEST(Wilson, KnownValue) {
  // Wilson interval for 10/100 at 95 %: [0.0552, 0.1744] (Newcombe 1998, Table I style check).
  Interval iv = wilsonInterval(10, 100);
  EXPECT_NEAR(iv.lo, 0.0552, 5e-4);
  EXPECT_NEAR(iv.hi, 0.1744, 5e-4);
}

TEST(NormalQuantile, StandardValues) {
  EXPECT_NEAR(normalQuantileTwoSided(0.95), 1.959964, 1e-6);
  EXPECT_NEAR(normalQuantileTwoSided(0.99), 2.575829, 1e-6);
  // Sidak over one test equals the plain two-sided quantile.
  EXPECT_NEAR(sidakZ(0.05, 1), 1.959964, 1e-6);
  EXPECT_GT(sidakZ(0.05, 1000), 4.0);
}

}  // namespace
}  // namespace proxyvis
