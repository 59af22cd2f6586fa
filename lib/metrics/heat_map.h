#pragma once
// The value-to-colour-scale mapping of error and cost heat-maps (no image I/O and no colours
// here: color_map.h turns the mapped values into colours, the app writes the PNG).
#include <span>
#include <vector>

namespace proxyvis {

struct HeatMapRange {
  double lo = 0, hi = 1;
  bool log_scale = false;  // log10 mapping; lo must then be > 0 (values below lo map to 0)
};

// Maps each value to its position t in [0, 1] on the colour scale of `range`: lo and below to 0,
// hi and above to 1, NaN to 0.
std::vector<float> heatMapUnit(std::span<const float> values, const HeatMapRange& range);

// A range that shows `values` well: log scale from the 2nd to the 99.5th percentile of the
// positive values (a few fireflies would flatten a linear map). {1e-6, 1, log} if none is > 0.
HeatMapRange robustLogRange(std::span<const float> values);

}  // namespace proxyvis
