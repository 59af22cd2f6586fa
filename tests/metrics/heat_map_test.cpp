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

}  // namespace
}  // namespace proxyvis
