#pragma once
// False-colour maps for error and cost images (no image I/O here: the app writes the PNG).
#include <array>
#include <span>
#include <vector>

namespace proxyvis {

// The "inferno" colour map (Smith & van der Walt, matplotlib 2015), piecewise linear through 9
// of its samples: perceptually ordered, readable in greyscale. t is clamped to [0, 1]; returns
// RGB in [0, 1] (display-referred, already sRGB-encoded).
std::array<float, 3> infernoColor(double t);

struct HeatMapRange {
  double lo = 0, hi = 1;
  bool log_scale = false;  // log10 mapping; lo must then be > 0 (values below lo map to 0)
};

// Maps each value to t in [0, 1] by `range` and returns 3 floats per value (RGB, sRGB-encoded).
std::vector<float> heatMapRgb(std::span<const float> values, const HeatMapRange& range);

// A range that shows `values` well: log scale from the 2nd to the 99.5th percentile of the
// positive values (a few fireflies would flatten a linear map). {1e-6, 1, log} if none is > 0.
HeatMapRange robustLogRange(std::span<const float> values);

}  // namespace proxyvis
