#include "image/color_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace proxyvis {
namespace {

float luma(const std::vector<float>& rgb, size_t i) {
  return 0.2126f * rgb[3 * i] + 0.7152f * rgb[3 * i + 1] + 0.0722f * rgb[3 * i + 2];
}

// sRGB 8-bit code to linear (IEC 61966-2-1), for colours published in sRGB.
float srgbCodeToLinear(int code) {
  float v = float(code) / 255.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// OIIO's maps give linear values; their sRGB encodings are the end colours of matplotlib's
// published inferno table, #000004 and #fcffa4.
TEST(ColorMap, InfernoEndsAreMatplotlibsInLinearValues) {
  std::vector<float> rgb = colorMapRgb(std::vector<float>{0.0f, 1.0f}, "inferno");
  ASSERT_EQ(rgb.size(), 6u);
  const int expected[6] = {0x00, 0x00, 0x04, 0xfc, 0xff, 0xa4};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(rgb[i], srgbCodeToLinear(expected[i]), 0.005f) << i;
}

TEST(ColorMap, BrightnessGrowsAlongTheMapAndOutsideValuesClamp) {
  std::vector<float> t;
  for (int i = 0; i <= 16; ++i) t.push_back(float(i) / 16);
  t.push_back(-3.0f);
  t.push_back(7.0f);
  std::vector<float> rgb = colorMapRgb(t);
  ASSERT_EQ(rgb.size(), t.size() * 3);
  for (size_t i = 1; i <= 16; ++i) EXPECT_GT(luma(rgb, i), luma(rgb, i - 1)) << "t = " << t[i];
  EXPECT_FLOAT_EQ(luma(rgb, 17), luma(rgb, 0));
  EXPECT_FLOAT_EQ(luma(rgb, 18), luma(rgb, 16));
}

TEST(ColorMap, HeatMapAndColorBarUseTheSameScale) {
  HeatMapRange range{1e-4, 1, true};
  std::vector<float> heat = heatMapRgb(std::vector<float>{1e-4f, 1.0f}, range);
  std::vector<float> bar = colorBarRgb(5, 2);
  ASSERT_EQ(bar.size(), 5u * 2u * 3u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(heat[c], bar[c]);              // lo: the bar's left end
    EXPECT_FLOAT_EQ(heat[3 + c], bar[4 * 3 + c]);  // hi: the bar's right end
    EXPECT_FLOAT_EQ(bar[c], bar[5 * 3 + c]);       // every row alike
  }
}

}  // namespace
}  // namespace proxyvis
