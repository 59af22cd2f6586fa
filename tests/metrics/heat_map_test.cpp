#include "metrics/heat_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace proxyvis {
namespace {

TEST(HeatMap, LogRangeMapsDecades) {
  HeatMapRange range{1e-4, 1, true};
  std::vector<float> v = {1e-6f, 1e-4f, 1e-2f, 1.0f, 10.0f};
  auto t = heatMapUnit(v, range);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0], 0.0f);          // below the range
  EXPECT_EQ(t[1], 0.0f);          // lo
  EXPECT_NEAR(t[2], 0.5f, 1e-6);  // 1e-2 is halfway between 1e-4 and 1 in log10
  EXPECT_NEAR(t[3], 1.0f, 1e-6);  // hi
  EXPECT_EQ(t[4], 1.0f);          // above the range
}

TEST(HeatMap, LinearRangeClampsAndMapsNanToZero) {
  HeatMapRange range{2, 6, false};
  std::vector<float> v = {0, 3, 6, 9, std::numeric_limits<float>::quiet_NaN()};
  auto t = heatMapUnit(v, range);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0], 0.0f);
  EXPECT_NEAR(t[1], 0.25f, 1e-6);
  EXPECT_NEAR(t[2], 1.0f, 1e-6);
  EXPECT_EQ(t[3], 1.0f);
  EXPECT_EQ(t[4], 0.0f);
}

TEST(HeatMap, RobustRangeIgnoresFireflies) {
  std::vector<float> v(1000, 1e-3f);
  for (int i = 0; i < 1000; i += 2) v[i] = 1e-2f;
  v[0] = 1e6f;  // one firefly above the 99.5th percentile
  HeatMapRange r = robustLogRange(v);
  EXPECT_TRUE(r.log_scale);
  EXPECT_FLOAT_EQ(float(r.hi), 1e-2f);
  EXPECT_FLOAT_EQ(float(r.lo), 1e-3f);
  EXPECT_GT(robustLogRange(std::vector<float>(4, 0.0f)).hi, 0);
}

// The range is two order statistics of the positive finite values, whatever their order: 1..1000
// in a scrambled order among zeros, negatives and non-finite values, lo is the value at index
// floor(0.02 x 999) = 19 of the sorted list (20), hi at floor(0.995 x 999) = 994 (995).
TEST(HeatMap, RobustRangeIsOrderStatisticsOfPositiveValues) {
  std::vector<float> v;
  for (int i = 0; i < 1000; ++i) {
    v.push_back(float((i * 337) % 1000 + 1));  // 337 is coprime to 1000: a permutation
    if (i % 7 == 0) v.push_back(0.0f);
    if (i % 11 == 0) v.push_back(-5.0f);
    if (i % 13 == 0) v.push_back(std::numeric_limits<float>::infinity());
    if (i % 17 == 0) v.push_back(std::numeric_limits<float>::quiet_NaN());
  }
  HeatMapRange r = robustLogRange(v);
  EXPECT_TRUE(r.log_scale);
  EXPECT_EQ(r.lo, 20.0);
  EXPECT_EQ(r.hi, 995.0);
}

}  // namespace
}  // namespace proxyvis
