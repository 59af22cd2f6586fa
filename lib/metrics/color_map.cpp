#include "metrics/color_map.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <string>

#include "util/error.h"

namespace proxyvis {

std::vector<float> colorMapRgb(std::span<const float> unit_values, std::string_view map_name) {
  if (unit_values.empty()) return {};
  // One row of single-channel pixels: OIIO maps channel 0 through the named map.
  OIIO::ImageSpec spec(int(unit_values.size()), 1, 1, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf src(spec);
  std::vector<float> clamped(unit_values.begin(), unit_values.end());
  for (float& t : clamped) t = t > 0 ? std::min(t, 1.0f) : 0.0f;  // also NaN to 0
  src.set_pixels(src.roi(), OIIO::TypeDesc::FLOAT, clamped.data());
  OIIO::ImageBuf dst = OIIO::ImageBufAlgo::color_map(src, 0, map_name);
  PV_CHECK_MSG(!dst.has_error() && dst.nchannels() == 3,
               "OpenImageIO color_map(" + std::string(map_name) + "): " + dst.geterror());
  std::vector<float> rgb(unit_values.size() * 3);
  dst.get_pixels(dst.roi(), OIIO::TypeDesc::FLOAT, rgb.data());
  return rgb;
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
