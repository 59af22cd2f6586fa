#include "util/rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxyvis {
namespace {

TEST(Rng, SameKeySameStream) {
  Rng a(42, 7), b(42, 7);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.nextU32(), b.nextU32());
}

TEST(Rng, DifferentIndexDifferentStream) {
  Rng a(42, 7), b(42, 8);
  int equal = 0;
  for (int i = 0; i < 100; ++i) equal += a.nextU32() == b.nextU32();
  EXPECT_LT(equal, 3);
}

TEST(Rng, UniformMeanAndVarianceWithinFiveSigma) {
  Rng r(3, 0);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    double u = r.uniformFloat();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum2 += u * u;
  }
  double mean = sum / n, var = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(var, 1.0 / 12, 0.002);
}

}  // namespace
}  // namespace proxyvis
