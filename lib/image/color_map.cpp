#include "image/color_map.h"

#include <algorithm>

#include "image/oiio_module.h"

namespace proxyvis {

std::vector<float> colorMapRgb(std::span<const float> unit_values, std::string_view map_name) {
  return oiioModule().color_map_rgb(unit_values, map_name);
}

std::vector<float> heatMapRgb(std::span<const float> values, const HeatMapRange& range) {
  return colorMapRgb(heatMapUnit(values, range));
}

std::vector<float> colorBarRgb(int width, int height, std::string_view map_name) {
  std::vector<float> ramp(size_t(std::max(width, 0)));
  for (int x = 0; x < width; ++x) ramp[size_t(x)] = width > 1 ? float(x) / float(width - 1) : 0.0f;
  std::vector<float> row = colorMapRgb(ramp, map_name), out;
  out.reserve(row.size() * size_t(std::max(height, 0)));
  for (int y = 0; y < height; ++y) out.insert(out.end(), row.begin(), row.end());
  return out;
}

}  // namespace proxyvis
