#include "metrics/heat_map.h"

#include <algorithm>
#include <cmath>

namespace proxyvis {

namespace {

double mapToUnit(double v, const HeatMapRange& range) {
  if (range.log_scale) {
    if (!(v > range.lo)) return 0;
    double a = std::log10(range.lo), b = std::log10(range.hi);
    return b > a ? (std::log10(v) - a) / (b - a) : 1;
  }
  return range.hi > range.lo ? (v - range.lo) / (range.hi - range.lo) : 0;
}

}  // namespace

std::vector<float> heatMapUnit(std::span<const float> values, const HeatMapRange& range) {
  std::vector<float> out;
  out.reserve(values.size());
  for (float v : values) {
    double t = mapToUnit(v, range);
    out.push_back(t > 0 ? float(std::min(t, 1.0)) : 0.0f);  // also maps NaN to 0
  }
  return out;
}

HeatMapRange robustLogRange(std::span<const float> values) {
  std::vector<float> positive;
  for (float v : values)
    if (v > 0 && std::isfinite(v)) positive.push_back(v);
  if (positive.empty()) return {1e-6, 1, true};
  // Two order statistics, not a full sort: the same values at a fraction of the cost on the
  // millions of values of a table's maps.
  auto at = [&](double q) {
    const auto k = positive.begin() + std::ptrdiff_t(q * double(positive.size() - 1));
    std::nth_element(positive.begin(), k, positive.end());
    return double(*k);
  };
  double lo = at(0.02), hi = at(0.995);
  if (!(hi > lo)) hi = lo * 10;
  return {lo, hi, true};
}

}  // namespace proxyvis
