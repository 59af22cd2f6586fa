#pragma once
// colorMapRgb's OpenImageIO implementation (image/color_map.h), built into the OIIO module
// (image/oiio_module.h) and reached through it.
#include <span>
#include <string_view>
#include <vector>

namespace proxyvis {

std::vector<float> colorMapRgbOiio(std::span<const float> unit_values, std::string_view map_name);

}  // namespace proxyvis
