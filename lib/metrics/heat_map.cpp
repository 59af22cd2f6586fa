#include "metrics/heat_map.h"

#include <algorithm>
#include <cmath>

namespace proxyvis {

namespace {

// Samples of matplotlib's inferno at t = 0, 1/8, ..., 1.
constexpr std::array<std::array<float, 3>, 9> kInferno = {{
    {0.001f, 0.000f, 0.014f},
    {0.122f, 0.047f, 0.283f},
    {0.335f, 0.060f, 0.429f},
    {0.536f, 0.134f, 0.420f},
    {0.735f, 0.216f, 0.330f},
    {0.902f, 0.361f, 0.188f},
    {0.978f, 0.557f, 0.035f},
    {0.976f, 0.790f, 0.197f},
    {0.988f, 0.998f, 0.645f},
}};

double mapToUnit(double v, const HeatMapRange& range) {
  if (range.log_scale) {
    if (!(v > range.lo)) return 0;
    double a = std::log10(range.lo), b = std::log10(range.hi);
    return b > a ? (std::log10(v) - a) / (b - a) : 1;
  }
  return range.hi > range.lo ? (v - range.lo) / (range.hi - range.lo) : 0;
}

}  // namespace

std::array<float, 3> infernoColor(double t) {
  if (!(t > 0)) return kInferno.front();  // also maps NaN to the darkest colour
  if (t >= 1) return kInferno.back();
  double x = t * (kInferno.size() - 1);
  size_t i = size_t(x);
  float f = float(x - double(i));
  std::array<float, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = kInferno[i][k] * (1 - f) + kInferno[i + 1][k] * f;
  return c;
}

std::vector<float> heatMapRgb(std::span<const float> values, const HeatMapRange& range) {
  std::vector<float> rgb;
  rgb.reserve(values.size() * 3);
  for (float v : values) {
    auto c = infernoColor(mapToUnit(v, range));
    rgb.insert(rgb.end(), c.begin(), c.end());
  }
  return rgb;
}

HeatMapRange robustLogRange(std::span<const float> values) {
  std::vector<float> positive;
  for (float v : values)
    if (v > 0 && std::isfinite(v)) positive.push_back(v);
  if (positive.empty()) return {1e-6, 1, true};
  std::sort(positive.begin(), positive.end());
  auto at = [&](double q) { return double(positive[size_t(q * double(positive.size() - 1))]); };
  double lo = at(0.02), hi = at(0.995);
  if (!(hi > lo)) hi = lo * 10;
  return {lo, hi, true};
}

}  // namespace proxyvis
