#include "metrics/log_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

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

size_t countOf(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(LogLogPlot, ErrorBarsOnlyWherePointsHaveThemAndAxesCoverThem) {
  LogLogPlot p;
  // y = 1e-3 ± 5e-3: the bar's lower end is not positive, so it stops at the axis; its upper end
  // (6e-3) is covered by the y axis, which therefore reaches 1e-2.
  p.series.push_back({"a", {{1, 1e-3, "", 5e-3}, {2, 5e-4, "", 0}}});
  std::string svg = logLogPlotSvg(p);
  EXPECT_EQ(countOf(svg, "class=\"error-bar\""), 1u);
  EXPECT_NE(svg.find(">0.01</text>"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(LogLogPlot, SeriesDifferInColourAndMarkerShape) {
  for (size_t i = 0; i < 7; ++i)
    for (size_t j = 0; j < i; ++j) {
      EXPECT_NE(seriesColor(i), seriesColor(j));
      EXPECT_NE(seriesMarker(i), seriesMarker(j));
    }
  LogLogPlot p;
  p.series.push_back({"a", {{1, 1, ""}}});
  p.series.push_back({"b", {{2, 2, ""}}});
  std::string svg = logLogPlotSvg(p);
  EXPECT_NE(svg.find("<circle class=\"marker\""), std::string::npos);
  EXPECT_NE(svg.find("<rect class=\"marker\""), std::string::npos);
  EXPECT_EQ(countOf(svg, "class=\"legend\""), 2u);
}

TEST(LogLogPlot, PointsAreJoinedInXOrder) {
  LogLogPlot p;
  p.width = 300, p.height = 200;
  p.series.push_back({"a", {{10, 1, ""}, {1, 10, ""}, {100, 0.1, ""}}});
  std::string svg = logLogPlotSvg(p);
  size_t at = svg.find("<polyline points=\"");
  ASSERT_NE(at, std::string::npos);
  std::string points = svg.substr(at + 18, svg.find('"', at + 18) - at - 18);
  double x0 = 0, x1 = 0, x2 = 0, y;
  ASSERT_EQ(std::sscanf(points.c_str(), "%lf,%lf %lf,%lf %lf,%lf", &x0, &y, &x1, &y, &x2, &y), 6);
  EXPECT_LT(x0, x1);
  EXPECT_LT(x1, x2);
}

}  // namespace
}  // namespace proxyvis
