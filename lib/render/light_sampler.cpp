#include "render/light_sampler.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace proxyvis {

double luminance(const Vec3f& rgb) {
  return 0.2126 * double(rgb.x) + 0.7152 * double(rgb.y) + 0.0722 * double(rgb.z);
}

LightSampler::LightSampler(const std::vector<AreaLightDesc>& lights) {
  double sum = 0;
  std::vector<double> power;
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
    power.push_back(std::max(0.0, luminance(lights[l].radiance)) * light_sum);
  }
  total_area_ = sum;
  PV_CHECK(!tris_.empty());

  // A scene whose lights are all black renders black whatever is sampled: choose by area then,
  // so that every pdf stays finite.
  double total_power = 0;
  for (double p : power) total_power += p;
  if (!(total_power > 0)) {
    power = light_area_;
    total_power = total_area_;
  }
  double cumulative = 0;
  for (double p : power) {
    light_prob_.push_back(p / total_power);
    cumulative += p;
    light_cdf_.push_back(cumulative / total_power);
  }
  light_cdf_.back() = 1.0;
}

size_t LightSampler::lastTriangle(uint32_t light) const {
  return light + 1 < light_first_.size() ? light_first_[light + 1] : tris_.size();
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
  // The light: smallest l with light_cdf_[l] > u0. A light of probability 0 has the same CDF
  // value as the one before it and is never the smallest such l.
  const auto it = std::upper_bound(light_cdf_.begin(), light_cdf_.end(), double(u0));
  const uint32_t light = uint32_t(std::min(size_t(it - light_cdf_.begin()), numLights() - 1));
  // u0 rescaled to [0, 1) within the light's interval picks the triangle: with one light
  // (base 0, probability 1) it is u0 itself.
  const double base = light == 0 ? 0.0 : light_cdf_[light - 1];
  const double u = std::clamp((double(u0) - base) / light_prob_[light], 0.0, 1.0);
  return sampleTriangle(pick(light_first_[light], lastTriangle(light), u), u1, u2,
                        light_prob_[light] / light_area_[light]);
}

LightSample LightSampler::sampleLight(uint32_t light, float u0, float u1, float u2) const {
  return sampleTriangle(pick(light_first_[light], lastTriangle(light), u0), u1, u2,
                        1.0 / light_area_[light]);
}

}  // namespace proxyvis
