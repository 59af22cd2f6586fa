#pragma once
// Pinhole camera from the scene's look-at description: vertical field of view, square pixels,
// pixel (0, 0) at the top left.
#include "scene/scene_desc.h"

namespace proxyvis {

class Camera {
 public:
  explicit Camera(const CameraDesc& desc);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3f& eye() const { return eye_; }

  // Direction (not normalized) through film position (fx, fy) in pixels: (0, 0) is the top-left
  // corner of the top-left pixel, (width, height) the bottom-right corner of the image.
  Vec3f direction(float fx, float fy) const {
    const float sx = (2.0f * fx / float(width_) - 1.0f) * half_w_;
    const float sy = (1.0f - 2.0f * fy / float(height_)) * half_h_;
    return forward_ + right_ * sx + up_ * sy;
  }

 private:
  Vec3f eye_, forward_, right_, up_;
  float half_w_ = 1, half_h_ = 1;  // tan(fov/2) * aspect, tan(fov/2)
  int width_ = 1, height_ = 1;
};

}  // namespace proxyvis
