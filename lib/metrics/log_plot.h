#pragma once
// Log-log line plots as inline SVG (no JavaScript, no external files): one <polyline> per
// series through its points in x order, a marker per point (shape and colour differ per series,
// so the series stay apart in greyscale and for colour-blind readers), optional ± error bars,
// decade grid lines and a legend.
#include <string>
#include <vector>

namespace proxyvis {

// Maps [lo, hi] (both > 0) logarithmically onto the pixel interval [px_lo, px_hi] (px_hi may be
// smaller than px_lo, as for an SVG y axis that grows downwards).
class LogAxis {
 public:
  LogAxis(double lo, double hi, double px_lo, double px_hi);
  // Widens [min_value, max_value] to whole decades (a single value gets one decade each side).
  static LogAxis covering(double min_value, double max_value, double px_lo, double px_hi);
  double map(double value) const;
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  // The powers of ten within [lo, hi].
  std::vector<double> decades() const;

 private:
  double lo_, hi_, px_lo_, px_hi_;
};

struct PlotPoint {
  double x = 0, y = 0;
  std::string label;  // tooltip (e.g. "16 spp"); may be empty
  double y_err = 0;   // half-length of the vertical error bar (e.g. a standard error); 0: none
};

struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;  // drawn in x order; points with x <= 0 or y <= 0 are skipped
};

struct LogLogPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  int width = 720, height = 440;
};

// The colour of series i: the Okabe-Ito palette (distinguishable with every common colour-vision
// deficiency) without its yellow, which is unreadable on white; cycles after 7.
std::string seriesColor(size_t i);

enum class MarkerShape { kCircle, kSquare, kTriangleUp, kDiamond, kTriangleDown, kPlus, kCross };
// The marker of series i; cycles after 7, out of step with the colours only past 7 series.
MarkerShape seriesMarker(size_t i);

// An SVG element drawing `shape` centred at (x, y), about 2·r across, filled with `color`.
std::string markerSvg(MarkerShape shape, double x, double y, double r, const std::string& color);

// An <svg> element; a plot without any positive point shows a "no data" note.
std::string logLogPlotSvg(const LogLogPlot& plot);

}  // namespace proxyvis
