#include "metrics/log_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include "util/escape_html.h"

namespace proxyvis {

namespace {

// Plot area margins in pixels: room for tick labels, axis titles and the legend.
constexpr double kLeft = 78, kRight = 160, kTop = 36, kBottom = 52;

bool drawable(const PlotPoint& p) {
  return p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y);
}

// The error bar's half-length, 0 when absent or not a finite positive number.
double errorOf(const PlotPoint& p) {
  return p.y_err > 0 && std::isfinite(p.y_err) ? p.y_err : 0;
}

bool isDecade(double v) {
  double e = std::log10(v);
  return std::abs(e - std::round(e)) < 1e-9;
}

// 2 and 5 × a decade get labels when the axis spans two decades or less (else only decades):
// a short axis would otherwise carry only two numbers.
bool isMidLabel(double v) {
  double mantissa = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
  return std::abs(mantissa - 2) < 1e-6 || std::abs(mantissa - 5) < 1e-6;
}

// k × 10^e for k = 1..9 within [lo, hi] of the axis.
std::vector<double> gridValues(const LogAxis& axis) {
  std::vector<double> out;
  for (double d : axis.decades())
    for (int k = 1; k <= 9; ++k)
      if (k * d <= axis.hi() * (1 + 1e-9)) out.push_back(k * d);
  return out;
}

std::string tickLabel(double v) {
  int e = int(std::floor(std::log10(v) + 1e-9));
  if (e >= -2 && e <= 3) return fmt::format("{:g}", v);
  double mantissa = v / std::pow(10.0, e);
  if (std::abs(mantissa - 1) < 1e-6) return fmt::format("1e{}", e);
  return fmt::format("{:.0f}e{}", mantissa, e);
}

}  // namespace

LogAxis::LogAxis(double lo, double hi, double px_lo, double px_hi)
    : lo_(lo), hi_(hi), px_lo_(px_lo), px_hi_(px_hi) {}

LogAxis LogAxis::covering(double min_value, double max_value, double px_lo, double px_hi) {
  double a = std::floor(std::log10(min_value)), b = std::ceil(std::log10(max_value));
  if (b <= a) a -= 1, b += 1;
  return LogAxis(std::pow(10.0, a), std::pow(10.0, b), px_lo, px_hi);
}

double LogAxis::map(double value) const {
  double t = (std::log10(value) - std::log10(lo_)) / (std::log10(hi_) - std::log10(lo_));
  return px_lo_ + t * (px_hi_ - px_lo_);
}

std::vector<double> LogAxis::decades() const {
  std::vector<double> out;
  for (int e = int(std::ceil(std::log10(lo_) - 1e-9)); e <= int(std::floor(std::log10(hi_) + 1e-9));
       ++e)
    out.push_back(std::pow(10.0, e));
  return out;
}

std::string seriesColor(size_t i) {
  static const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#000000"};
  return kPalette[i % 7];
}

MarkerShape seriesMarker(size_t i) {
  static const MarkerShape kShapes[] = {MarkerShape::kCircle,       MarkerShape::kSquare,
                                        MarkerShape::kTriangleUp,   MarkerShape::kDiamond,
                                        MarkerShape::kTriangleDown, MarkerShape::kPlus,
                                        MarkerShape::kCross};
  return kShapes[i % 7];
}

std::string markerSvg(MarkerShape shape, double x, double y, double r, const std::string& color) {
  auto polygon = [&](std::initializer_list<std::pair<double, double>> corners) {
    std::string points;
    for (auto [dx, dy] : corners) points += fmt::format("{:.1f},{:.1f} ", x + dx * r, y + dy * r);
    return fmt::format("<polygon class=\"marker\" points=\"{}\" fill=\"{}\"/>", points, color);
  };
  auto strokes = [&](const std::string& d) {
    return fmt::format(
        "<path class=\"marker\" d=\"{}\" stroke=\"{}\" stroke-width=\"2.2\" fill=\"none\"/>", d,
        color);
  };
  switch (shape) {
    case MarkerShape::kCircle:
      return fmt::format(
          "<circle class=\"marker\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"{}\"/>", x, y,
          r, color);
    case MarkerShape::kSquare:
      return fmt::format(
          "<rect class=\"marker\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
          "fill=\"{}\"/>",
          x - 0.9 * r, y - 0.9 * r, 1.8 * r, 1.8 * r, color);
    case MarkerShape::kTriangleUp:
      return polygon({{0, -1.2}, {1.1, 0.8}, {-1.1, 0.8}});
    case MarkerShape::kDiamond:
      return polygon({{0, -1.3}, {1.1, 0}, {0, 1.3}, {-1.1, 0}});
    case MarkerShape::kTriangleDown:
      return polygon({{0, 1.2}, {1.1, -0.8}, {-1.1, -0.8}});
    case MarkerShape::kPlus:
      return strokes(fmt::format("M{:.1f} {:.1f}H{:.1f}M{:.1f} {:.1f}V{:.1f}", x - 1.2 * r, y,
                                 x + 1.2 * r, x, y - 1.2 * r, y + 1.2 * r));
    case MarkerShape::kCross:
      return strokes(fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}M{:.1f} {:.1f}L{:.1f} {:.1f}", x - r,
                                 y - r, x + r, y + r, x - r, y + r, x + r, y - r));
  }
  return {};
}

namespace {

// Grid lines (decades, and 2..9 x decade lighter) and tick labels.
std::string gridSvg(const LogAxis& xa, const LogAxis& ya, double left, double right, double top,
                    double bottom) {
  std::string svg;
  const bool x_mid_labels = xa.hi() / xa.lo() <= 100.5, y_mid_labels = ya.hi() / ya.lo() <= 100.5;
  for (double v : gridValues(xa)) {
    bool decade = isDecade(v);
    svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"{3}\"/>",
                       xa.map(v), top, bottom, decade ? "#d4d4d4" : "#efefef");
    if (decade || (x_mid_labels && isMidLabel(v)))
      svg +=
          fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\" fill=\"#444\">{}</text>",
                      xa.map(v), bottom + 16, tickLabel(v));
    svg += "\n";
  }
  for (double v : gridValues(ya)) {
    bool decade = isDecade(v);
    svg += fmt::format("<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"{3}\"/>",
                       ya.map(v), left, right, decade ? "#d4d4d4" : "#efefef");
    if (decade || (y_mid_labels && isMidLabel(v)))
      svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\" fill=\"#444\">{}</text>",
                         left - 6, ya.map(v) + 4, tickLabel(v));
    svg += "\n";
  }
  return svg;
}

// One series: error bars, the line through the points in x order (even a single point, so a
// reader can count series), markers with tooltips, and a legend entry with line and marker.
std::string seriesSvg(const PlotSeries& s, size_t i, const LogAxis& xa, const LogAxis& ya,
                      double top, double right) {
  std::string svg;
  std::vector<PlotPoint> pts;
  for (const PlotPoint& p : s.points)
    if (drawable(p)) pts.push_back(p);
  std::stable_sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.x < b.x; });
  const std::string color = seriesColor(i);
  const MarkerShape shape = seriesMarker(i);
  std::string name = escapeHtml(s.name);
  svg += fmt::format("<g class=\"series\" data-series=\"{}\">\n", name);
  for (const PlotPoint& p : pts) {
    double err = errorOf(p);
    if (!(err > 0)) continue;
    double x = xa.map(p.x), y_hi = ya.map(p.y + err);
    double y_lo = ya.map(p.y - err > ya.lo() ? p.y - err : ya.lo());
    svg += fmt::format(
        "<path class=\"error-bar\" d=\"M{0:.1f} {1:.1f}V{2:.1f}M{3:.1f} {1:.1f}H{4:.1f}M{3:.1f} "
        "{2:.1f}H{4:.1f}\" stroke=\"{5}\" stroke-width=\"1.2\" fill=\"none\"/>\n",
        x, y_lo, y_hi, x - 4, x + 4, color);
  }
  std::string coords;
  for (const PlotPoint& p : pts) coords += fmt::format("{:.1f},{:.1f} ", xa.map(p.x), ya.map(p.y));
  svg += fmt::format(
      "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.8\" "
      "stroke-opacity=\"0.85\"/>\n",
      coords, color);
  for (const PlotPoint& p : pts) {
    std::string tip =
        fmt::format("{}: {}x = {:.3g}, y = {:.3g}", name,
                    p.label.empty() ? std::string() : escapeHtml(p.label) + ", ", p.x, p.y);
    if (errorOf(p) > 0) tip += fmt::format(" ± {:.2g}", p.y_err);
    svg += fmt::format("<g><title>{}</title>{}</g>\n", tip,
                       markerSvg(shape, xa.map(p.x), ya.map(p.y), 4.5, color));
  }
  double ly = top + 10 + 20.0 * double(i);
  svg += fmt::format(
      "<g class=\"legend\"><line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" "
      "stroke=\"{3}\" stroke-width=\"1.8\"/>{4}<text x=\"{5}\" y=\"{6:.1f}\">{7}</text></g>\n",
      right + 12, ly, right + 40, color, markerSvg(shape, right + 26, ly, 4.5, color), right + 46,
      ly + 4, name);
  svg += "</g>\n";
  return svg;
}

}  // namespace

std::string logLogPlotSvg(const LogLogPlot& plot) {
  const double w = plot.width, h = plot.height;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"#fff\"/>\n"
      "<text x=\"{2}\" y=\"20\" font-size=\"14\" font-weight=\"bold\">{3}</text>\n",
      w, h, kLeft, escapeHtml(plot.title));
  // The axes cover every point with its error bar (the lower end only where it stays positive).
  double x_min = std::numeric_limits<double>::infinity(), x_max = 0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = 0;
  for (const PlotSeries& s : plot.series)
    for (const PlotPoint& p : s.points)
      if (drawable(p)) {
        double err = errorOf(p);
        x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
        y_min = std::min(y_min, p.y - err > 0 ? p.y - err : p.y);
        y_max = std::max(y_max, p.y + err);
      }
  if (!(x_max > 0)) {
    svg += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#888\">no data</text>\n</svg>\n", w / 2 - 30,
                       h / 2);
    return svg;
  }
  const double left = kLeft, right = w - kRight, top = kTop, bottom = h - kBottom;
  LogAxis xa = LogAxis::covering(x_min, x_max, left, right);
  LogAxis ya = LogAxis::covering(y_min, y_max, bottom, top);

  svg += gridSvg(xa, ya, left, right, top, bottom);
  svg += fmt::format(
      "<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"#888\"/>\n"
      "<text x=\"{4}\" y=\"{5}\" text-anchor=\"middle\">{6}</text>\n"
      "<text transform=\"translate(16 {7}) rotate(-90)\" text-anchor=\"middle\">{8}</text>\n",
      left, top, right - left, bottom - top, (left + right) / 2, h - 12, escapeHtml(plot.x_label),
      (top + bottom) / 2, escapeHtml(plot.y_label));

  for (size_t i = 0; i < plot.series.size(); ++i)
    svg += seriesSvg(plot.series[i], i, xa, ya, top, right);
  svg += "</svg>\n";
  return svg;
}

}  // namespace proxyvis
