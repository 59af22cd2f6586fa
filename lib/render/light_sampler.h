#pragma once
// Area sampling of all light triangles at once, uniform by area: pdf = 1 / (total area) per
// unit area, whichever light the point lies on. One discrete CDF over the triangles picks the
// triangle (with probability area / total), then a uniform point on it (Turk 1990, the sqrt
// parameterisation as in pbrt's SampleUniformTriangle).
#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene_desc.h"

namespace proxyvis {

struct LightSample {
  Vec3f point;
  Vec3f normal;  // unit; lights emit on both sides, so only |cos| matters
  Vec3f radiance;
  uint32_t light = 0;   // index into SceneDesc::lights
  double pdf_area = 0;  // with respect to area on the light
};

class LightSampler {
 public:
  explicit LightSampler(const std::vector<AreaLightDesc>& lights);

  // u0 picks the triangle, (u1, u2) the point; all in [0, 1).
  LightSample sample(float u0, float u1, float u2) const;
  // Samples only light `light` (pdf relative to that light's area): the probe segments of a
  // learning region (tile x light) come from the same distribution as its light samples.
  LightSample sampleLight(uint32_t light, float u0, float u1, float u2) const;

  size_t numLights() const { return light_first_.size(); }
  double totalArea() const { return total_area_; }
  double lightArea(uint32_t light) const { return light_area_[light]; }

 private:
  LightSample sampleTriangle(size_t tri, float u1, float u2, double pdf) const;
  size_t pick(size_t first, size_t last, double u) const;

  struct Tri {
    Vec3f v0, e1, e2, normal, radiance;
    uint32_t light;
  };
  std::vector<Tri> tris_;
  std::vector<double> cdf_;          // cumulative areas, cdf_[i] = sum of areas of tris [0, i]
  std::vector<size_t> light_first_;  // first triangle of each light (lights are contiguous)
  std::vector<double> light_area_;
  double total_area_ = 0;
};

}  // namespace proxyvis
