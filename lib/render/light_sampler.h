#pragma once
// Area-light sampling in two steps: a light with probability proportional to its power
// (luminance of its radiance x its area; a light of zero power is never chosen), then a point
// uniform by area on it: pdf_area = P(light) / area(light). A small bright sun next to a large dim
// sky then gets the samples its contribution deserves, where uniform-by-area sampling of all
// light triangles would give the sun a share of area(sun) / area(all). Within a light, one
// discrete CDF over its triangles picks the triangle (area / light area), then a uniform point on
// it (Turk 1990, the sqrt parameterisation as in pbrt's SampleUniformTriangle). With one light
// this is exactly uniform by area (the same numbers, bit for bit, as a single CDF over all
// triangles).
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

// Rec. 709 luminance of a linear RGB radiance: the weight of a light's power in the light choice.
double luminance(const Vec3f& rgb);

class LightSampler {
 public:
  explicit LightSampler(const std::vector<AreaLightDesc>& lights);

  // u0 picks the light and then the triangle within it, (u1, u2) the point; all in [0, 1).
  LightSample sample(float u0, float u1, float u2) const;
  // Samples only light `light` (pdf relative to that light's area): the probe segments of a
  // learning region (tile x light) come from the same distribution as its light samples.
  LightSample sampleLight(uint32_t light, float u0, float u1, float u2) const;

  size_t numLights() const { return light_first_.size(); }
  double totalArea() const { return total_area_; }
  double lightArea(uint32_t light) const { return light_area_[light]; }
  // The probability that sample() picks light `light`.
  double lightProbability(uint32_t light) const { return light_prob_[light]; }

 private:
  LightSample sampleTriangle(size_t tri, float u1, float u2, double pdf) const;
  size_t pick(size_t first, size_t last, double u) const;
  size_t lastTriangle(uint32_t light) const;

  struct Tri {
    Vec3f v0, e1, e2, normal, radiance;
    uint32_t light;
  };
  std::vector<Tri> tris_;
  std::vector<double> cdf_;          // cumulative areas, cdf_[i] = sum of areas of tris [0, i]
  std::vector<size_t> light_first_;  // first triangle of each light (lights are contiguous)
  std::vector<double> light_area_;
  std::vector<double> light_prob_;  // P(light): power / total power
  std::vector<double> light_cdf_;   // light_cdf_[l] = P(0) + ... + P(l); the last is exactly 1
  double total_area_ = 0;
};

}  // namespace proxyvis
