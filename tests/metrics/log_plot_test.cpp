#include "metrics/log_plot.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxyvis {
namespace {

TEST(LogAxis, MapsDecadesLinearly) {
  LogAxis a(1e-3, 1e1, 0, 400);  // 4 decades over 400 px
  EXPECT_NEAR(a.map(1e-3), 0, 1e-9);
  EXPECT_NEAR(a.map(1e-2), 100, 1e-9);
  EXPECT_NEAR(a.map(1e1), 400, 1e-9);
  EXPECT_NEAR(a.map(std::sqrt(10.0) * 1e-3), 50, 1e-9);
  auto d = a.decades();
  ASSERT_EQ(d.size(), 5u);
  EXPECT_DOUBLE_EQ(d.front(), 1e-3);
}

TEST(LogAxis, InvertedPixelRangeForSvgY) {
  LogAxis y(1, 100, 300, 100);  // grows upwards on screen
  EXPECT_NEAR(y.map(1), 300, 1e-9);
  EXPECT_NEAR(y.map(10), 200, 1e-9);
  EXPECT_NEAR(y.map(100), 100, 1e-9);
}

TEST(LogAxis, CoveringRoundsOutToDecades) {
  LogAxis a = LogAxis::covering(3e-5, 2e-3, 0, 1);
  EXPECT_NEAR(std::log10(a.lo()), -5, 1e-9);
  EXPECT_NEAR(std::log10(a.hi()), -2, 1e-9);
  LogAxis single = LogAxis::covering(1e-2, 1e-2, 0, 1);
  EXPECT_LT(single.lo(), 1e-2);
  EXPECT_GT(single.hi(), 1e-2);
}

TEST(LogLogPlot, SkipsNonPositivePointsAndShowsNoData) {
  LogLogPlot p;
  p.series.push_back({"a", {{0, 1, ""}, {1, -1, ""}}});
  std::string svg = logLogPlotSvg(p);
  EXPECT_NE(svg.find("no data"), std::string::npos);
  p.series.push_back({"b", {{1, 1e-3, ""}, {2, 5e-4, ""}}});
  svg = logLogPlotSvg(p);
  EXPECT_EQ(svg.find("no data"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_NE(svg.find("data-series=\"b\""), std::string::npos);
}

}  // namespace
}  // namespace proxyvis
