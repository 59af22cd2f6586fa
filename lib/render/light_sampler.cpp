#include "render/light_sampler.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace proxyvis {

LightSampler::LightSampler(const std::vector<AreaLightDesc>& lights) {
  double sum = 0;
  for (uint32_t l = 0; l < lights.size(); ++l) {
    light_first_.push_back(tris_.size());
    double light_sum = 0;
    for (const auto& t : lights[l].triangles) {
      Tri tri;
      tri.v0 = t[0];
      tri.e1 = t[1] - t[0];
      tri.e2 = t[2] - t[0];
      const Vec3d c = cross(Vec3d(tri.e1), Vec3d(tri.e2));
      const double area = 0.5 * length(c);
      PV_CHECK_MSG(area > 0, "degenerate light triangles are rejected by the scene loader");
      tri.normal = Vec3f(c / length(c));
      tri.radiance = lights[l].radiance;
      tri.light = l;
      tris_.push_back(tri);
      sum += area;
      light_sum += area;
      cdf_.push_back(sum);
    }
    light_area_.push_back(light_sum);
  }
  total_area_ = sum;
  PV_CHECK(!tris_.empty());
}

size_t LightSampler::pick(size_t first, size_t last, double u) const {
  // Smallest i in [first, last) with cdf_[i] > target.
  const double base = first == 0 ? 0.0 : cdf_[first - 1];
  const double target = base + u * (cdf_[last - 1] - base);
  auto it = std::upper_bound(cdf_.begin() + long(first), cdf_.begin() + long(last), target);
  return std::min(size_t(it - cdf_.begin()), last - 1);
}

LightSample LightSampler::sampleTriangle(size_t i, float u1, float u2, double pdf) const {
  const Tri& t = tris_[i];
  const float su = std::sqrt(u1);
  const float b1 = 1.0f - su, b2 = u2 * su;
  LightSample s;
  s.point = t.v0 + t.e1 * b1 + t.e2 * b2;
  s.normal = t.normal;
  s.radiance = t.radiance;
  s.light = t.light;
  s.pdf_area = pdf;
  return s;
}

LightSample LightSampler::sample(float u0, float u1, float u2) const {
  return sampleTriangle(pick(0, tris_.size(), u0), u1, u2, 1.0 / total_area_);
}

LightSample LightSampler::sampleLight(uint32_t light, float u0, float u1, float u2) const {
  const size_t first = light_first_[light];
  const size_t last = light + 1 < light_first_.size() ? light_first_[light + 1] : tris_.size();
  return sampleTriangle(pick(first, last, u0), u1, u2, 1.0 / light_area_[light]);
}

}  // namespace proxyvis
