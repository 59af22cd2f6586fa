#include "metrics/log_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxyvis {

namespace {

// Plot area margins in pixels: room for tick labels, axis titles and the legend.
constexpr double kLeft = 78, kRight = 160, kTop = 36, kBottom = 52;

bool drawable(const PlotPoint& p) {
  return p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y);
}

std::string decadeLabel(double v) {
  int e = int(std::lround(std::log10(v)));
  if (e >= -2 && e <= 3) return fmt::format("{:g}", v);
  return fmt::format("1e{}", e);
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
  static const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                   "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
  return kPalette[i % 8];
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string logLogPlotSvg(const LogLogPlot& plot) {
  const double w = plot.width, h = plot.height;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"#fff\"/>\n"
      "<text x=\"{2}\" y=\"20\" font-size=\"14\" font-weight=\"bold\">{3}</text>\n",
      w, h, kLeft, escapeHtml(plot.title));
  double x_min = std::numeric_limits<double>::infinity(), x_max = 0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = 0;
  for (const PlotSeries& s : plot.series)
    for (const PlotPoint& p : s.points)
      if (drawable(p)) {
        x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
        y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
      }
  if (!(x_max > 0)) {
    svg += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#888\">no data</text>\n</svg>\n", w / 2 - 30,
                       h / 2);
    return svg;
  }
  const double left = kLeft, right = w - kRight, top = kTop, bottom = h - kBottom;
  LogAxis xa = LogAxis::covering(x_min, x_max, left, right);
  LogAxis ya = LogAxis::covering(y_min, y_max, bottom, top);

  // Grid, ticks and axis titles.
  for (double d : xa.decades())
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/>"
        "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\" fill=\"#444\">{4}</text>\n",
        xa.map(d), top, bottom, bottom + 16, decadeLabel(d));
  for (double d : ya.decades())
    svg += fmt::format(
        "<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"#ddd\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\" fill=\"#444\">{5}</text>\n",
        ya.map(d), left, right, left - 6, ya.map(d) + 4, decadeLabel(d));
  svg += fmt::format(
      "<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"#888\"/>\n"
      "<text x=\"{4}\" y=\"{5}\" text-anchor=\"middle\">{6}</text>\n"
      "<text transform=\"translate(18 {7}) rotate(-90)\" text-anchor=\"middle\">{8}</text>\n",
      left, top, right - left, bottom - top, (left + right) / 2, h - 12, escapeHtml(plot.x_label),
      (top + bottom) / 2, escapeHtml(plot.y_label));

  // One polyline per series (even with a single point, so a reader can count series), markers
  // with tooltips, and a legend entry.
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    std::vector<PlotPoint> pts;
    for (const PlotPoint& p : s.points)
      if (drawable(p)) pts.push_back(p);
    std::sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.x < b.x; });
    std::string color = seriesColor(i);
    std::string coords;
    for (const PlotPoint& p : pts)
      coords += fmt::format("{:.1f},{:.1f} ", xa.map(p.x), ya.map(p.y));
    svg += fmt::format(
        "<polyline class=\"series\" data-series=\"{}\" points=\"{}\" fill=\"none\" "
        "stroke=\"{}\" stroke-width=\"2\"/>\n",
        escapeHtml(s.name), coords, color);
    for (const PlotPoint& p : pts)
      svg += fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"><title>{}: {}x = {:.3g}, "
          "y = {:.3g}</title></circle>\n",
          xa.map(p.x), ya.map(p.y), color, escapeHtml(s.name),
          p.label.empty() ? std::string() : escapeHtml(p.label) + ", ", p.x, p.y);
    double ly = top + 8 + 20.0 * double(i);
    svg += fmt::format(
        "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"3\"/><text x=\"{4}\" y=\"{5:.1f}\">{6}</text>\n",
        right + 14, ly, right + 38, color, right + 44, ly + 4, escapeHtml(s.name));
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace proxyvis
