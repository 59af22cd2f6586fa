#include "render/camera.h"

#include <cmath>

namespace proxyvis {

Camera::Camera(const CameraDesc& desc) : eye_(desc.eye), width_(desc.width), height_(desc.height) {
  forward_ = normalize(desc.look_at - desc.eye);
  right_ = normalize(cross(forward_, desc.up));
  up_ = cross(right_, forward_);
  half_h_ = std::tan(desc.fov_deg * 0.5f * 3.14159265358979f / 180.0f);
  half_w_ = half_h_ * float(width_) / float(height_);
}

}  // namespace proxyvis
