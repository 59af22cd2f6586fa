#pragma once
// Colours of heat-maps and of their colour bars, from OpenImageIO's perceptually uniform colour
// maps (library pv_color_map: the only part of metrics that uses OIIO, through the OIIO module
// loaded on first use, image/oiio_module.h).
#include <span>
#include <string_view>
#include <vector>

#include "metrics/heat_map.h"

namespace proxyvis {

// Perceptually ordered, strictly increasing in luminance (readable in greyscale) and
// distinguishable with every common colour-vision deficiency.
inline constexpr std::string_view kHeatMapColorMap = "inferno";

// RGB (3 floats per input) of OIIO's colour map `map_name` at each t in [0, 1] (values outside
// are clamped). The values are linear: written through the sRGB transfer curve (a PNG) they
// show the map's published colours.
std::vector<float> colorMapRgb(std::span<const float> unit_values,
                               std::string_view map_name = kHeatMapColorMap);

// colorMapRgb of heatMapUnit(values, range).
std::vector<float> heatMapRgb(std::span<const float> values, const HeatMapRange& range);

// A horizontal colour bar of `width` × `height` pixels (linear RGB, row-major): t runs
// from 0 at the left to 1 at the right, the same in every row.
std::vector<float> colorBarRgb(int width, int height, std::string_view map_name = kHeatMapColorMap);

}  // namespace proxyvis
