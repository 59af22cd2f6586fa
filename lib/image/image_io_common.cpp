// The parts of image/image_io.h that need no OpenImageIO: linked into the programs and into the
// OIIO module (image/oiio_module.h), whose PNG writer tone-maps with linearToSrgb.
#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "util/error.h"

namespace proxyvis {

float linearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void checkWritable(const Image& image, const ImageWriteOptions& options) {
  PV_CHECK(image.pixels.size() == size_t(image.width) * image.height * image.channels);
  PV_CHECK(options.channel_names.empty() || int(options.channel_names.size()) == image.channels);
}

std::string ImageHeader::attribute(const std::string& name) const {
  for (const auto& [key, value] : attributes)
    if (key == name) return value;
  return {};
}

float autoExposure(const Image& image) {
  std::vector<float> brightest;
  for (size_t p = 0; p + 2 < image.pixels.size(); p += 3)
    brightest.push_back(std::max({image.pixels[p], image.pixels[p + 1], image.pixels[p + 2]}));
  if (brightest.empty()) return 1;
  size_t k = size_t(0.99 * double(brightest.size() - 1));
  std::nth_element(brightest.begin(), brightest.begin() + k, brightest.end());
  return brightest[k] > 0 ? 1.0f / brightest[k] : 1.0f;
}

}  // namespace proxyvis
