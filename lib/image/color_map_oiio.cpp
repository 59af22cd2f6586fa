#include "image/color_map_oiio.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <string>

#include "util/error.h"

namespace proxyvis {

std::vector<float> colorMapRgbOiio(std::span<const float> unit_values, std::string_view map_name) {
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

}  // namespace proxyvis
