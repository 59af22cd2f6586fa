#include "metrics/image_variance.h"

#include <gtest/gtest.h>

#include <vector>

#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

TEST(ImageVariance, HandComputedTwoPixels) {
  // Pixel 0 partials 1, 3 → mean 2, s² = 2, var of mean 1. Pixel 1 constant → 0. Average 0.5.
  ImageVarianceAccumulator acc;
  acc.add(std::vector<float>{1, 5});
  acc.add(std::vector<float>{3, 5});
  EXPECT_EQ(acc.count(), 2);
  auto m = acc.mean();
  EXPECT_FLOAT_EQ(m[0], 2.0f);
  EXPECT_FLOAT_EQ(m[1], 5.0f);
  EXPECT_DOUBLE_EQ(acc.meanVarianceOfMean(), 0.5);
  EXPECT_THROW(acc.add(std::vector<float>{1}), Error);
}

TEST(ImageVariance, EstimatesTheMseOfTheMean) {
  // 64 partials of uniform noise (variance 1/12) per value: the variance of their mean is
  // 1/(12·64). Averaged over 4096 values the estimate's relative s.e. is about
  // sqrt(2/63)/sqrt(4096) ≈ 0.3 %, so a 5 % bound (17 s.e.) cannot fail by chance, while a
  // forgotten 1/K (64× too large) or a variance of the partials instead of the mean fails.
  const int kValues = 4096, kPartials = 64;
  ImageVarianceAccumulator acc;
  for (int k = 0; k < kPartials; ++k) {
    Rng rng(7, uint64_t(k));
    std::vector<float> p(kValues);
    for (float& v : p) v = rng.uniformFloat();
    acc.add(p);
  }
  double expected = 1.0 / 12.0 / kPartials;
  EXPECT_NEAR(acc.meanVarianceOfMean(), expected, 0.05 * expected);
}

}  // namespace
}  // namespace proxyvis
