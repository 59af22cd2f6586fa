#include "util/rng.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// Streams with the same index and different seeds (the K seeds of render-compare) must be
// uncorrelated, not just different: the standard error over seeds assumes independence.
// For n independent pairs the sample correlation has standard deviation 1/sqrt(n).
TEST(Rng, SameIndexDifferentSeedsUncorrelated) {
  const int n = 100000;
  double worst = 0;
  for (uint64_t seed_b = 1; seed_b <= 16; ++seed_b) {
    for (uint64_t index : {0ull, 1ull, 12345ull}) {
      Rng a(0, index), b(seed_b, index);
      double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
      for (int i = 0; i < n; ++i) {
        const double x = a.uniformDouble(), y = b.uniformDouble();
        sa += x, sb += y, sab += x * y, saa += x * x, sbb += y * y;
      }
      const double cov = sab / n - sa / n * sb / n;
      const double corr =
          cov / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
      worst = std::max(worst, std::abs(corr));
    }
  }
  // 48 pairs: a 4.5 sigma bound keeps the false-alarm rate below 1e-3 (Sidak).
  EXPECT_LT(worst, 4.5 / std::sqrt(double(n)));
}

TEST(Rng, DeferredEqualsEagerStream) {
  Rng eager(7, hashKeys(3, 4, 5));
  Rng deferred = Rng::deferred(7, 3, 4, 5);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(eager.nextU32(), deferred.nextU32());
  Rng other = Rng::deferred(7, 3, 4, 6);  // teeth: another key, another stream
  Rng again(7, hashKeys(3, 4, 5));
  int equal = 0;
  for (int i = 0; i < 100; ++i) equal += other.nextU32() == again.nextU32();
  EXPECT_LT(equal, 3);
}

}  // namespace
}  // namespace proxyvis
