#include "metrics/image_error.h"

#include <gtest/gtest.h>

#include <vector>

#include "util/error.h"

namespace proxyvis {
namespace {

// A 2x1 RGB image and its reference, errors worked out by hand:
// differences 1,0,0 | 0,2,0.5 → squares 1,0,0,0,4,0.25 → sum 5.25, MSE = 5.25/6 = 0.875.
const std::vector<float> kImage = {1, 1, 1, 0, 2, 0.5f};
const std::vector<float> kReference = {0, 1, 1, 0, 0, 0};

TEST(ImageError, MseOnHandComputedImage) {
  EXPECT_DOUBLE_EQ(meanSquaredError(kImage, kReference), 0.875);
  EXPECT_DOUBLE_EQ(meanSquaredError(kReference, kReference), 0.0);
}

TEST(ImageError, RelMseUsesEpsilonOneHundredth) {
  EXPECT_DOUBLE_EQ(kRelMseEpsilon, 1e-2);
  // Terms: 1/(0+0.01) = 100, 0, 0, 0, 4/0.01 = 400, 0.25/0.01 = 25 → 525/6 = 87.5.
  EXPECT_NEAR(relativeMeanSquaredError(kImage, kReference), 87.5, 1e-9);
  // With a bright reference the relative error shrinks: (3-2)^2/(4+0.01).
  std::vector<float> a = {3}, r = {2};
  EXPECT_NEAR(relativeMeanSquaredError(a, r), 1.0 / 4.01, 1e-12);
}

TEST(ImageError, PerPixelMapsAverageChannels) {
  auto sq = squaredErrorPerPixel(kImage, kReference, 3);
  ASSERT_EQ(sq.size(), 2u);
  EXPECT_FLOAT_EQ(sq[0], 1.0f / 3);
  EXPECT_FLOAT_EQ(sq[1], 4.25f / 3);
  auto rel = relativeSquaredErrorPerPixel(kImage, kReference, 3);
  ASSERT_EQ(rel.size(), 2u);
  EXPECT_NEAR(rel[0], 100.0 / 3, 1e-4);
  EXPECT_NEAR(rel[1], 425.0 / 3, 1e-3);
}

TEST(ImageError, MismatchedSizesAreErrors) {
  std::vector<float> small = {1, 2, 3};
  EXPECT_THROW(meanSquaredError(kImage, small), Error);
  EXPECT_THROW(relativeMeanSquaredError({}, {}), Error);
  EXPECT_THROW(squaredErrorPerPixel(kImage, kReference, 4), Error);
  EXPECT_THROW(squaredErrorPerPixel(kImage, kReference, 0), Error);
}

}  // namespace
}  // namespace proxyvis
