#include "metrics/heat_map.h"

#include <gtest/gtest.h>

#include <vector>

namespace proxyvis {
namespace {

TEST(HeatMap, EndsAndMonotoneBrightness) {
  auto dark = infernoColor(0), bright = infernoColor(1);
  EXPECT_LT(dark[0] + dark[1] + dark[2], 0.05f);
  EXPECT_GT(bright[0] + bright[1] + bright[2], 2.5f);
  float last = -1;
  for (int i = 0; i <= 16; ++i) {
    auto c = infernoColor(i / 16.0);
    float luma = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    EXPECT_GT(luma, last) << "t = " << i / 16.0;
    last = luma;
  }
}

TEST(HeatMap, LogRangeMapsDecades) {
  HeatMapRange range{1e-4, 1, true};
  std::vector<float> v = {1e-6f, 1e-4f, 1e-2f, 1.0f, 10.0f};
  auto rgb = heatMapRgb(v, range);
  ASSERT_EQ(rgb.size(), 15u);
  auto mid = infernoColor(0.5);
  EXPECT_NEAR(rgb[6], mid[0], 1e-5);  // 1e-2 is halfway between 1e-4 and 1 in log10
  EXPECT_EQ(rgb[0], infernoColor(0)[0]);
  EXPECT_EQ(rgb[12], infernoColor(1)[0]);
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
