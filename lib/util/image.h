#pragma once
// A float image: what the renderer produces, image files hold (image/image_io.h) and the
// metrics compare. Plain data, so reading or writing images needs no renderer.
#include <cstddef>
#include <vector>

namespace proxyvis {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, top row first, interleaved channels
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
  bool operator==(const Image&) const = default;
};

}  // namespace proxyvis
