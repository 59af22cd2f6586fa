#include "light_segments.h"

#include "render/integrator_steps.h"
#include "render/shading_points.h"
#include "util/rng.h"

namespace proxyvis::ecosys {

std::vector<LightSegment> lightSegments(const RenderScene& scene, uint64_t seed, int pass) {
  const int w = scene.camera().width(), h = scene.camera().height();
  const Tiling tiling(w, h, 16);
  const std::vector<ShadingPoint> points = shadingPoints(scene, tiling);
  std::vector<LightSegment> out;
  const uint32_t lights = uint32_t(scene.lights().numLights());
  for (uint32_t pixel = 0; pixel < points.size(); ++pixel) {
    const ShadingPoint& sp = points[pixel];
    if (!sp.valid) continue;
    for (uint32_t l = 0; l < lights; ++l) {
      Rng rng(seed, hashKeys(pixel, uint64_t(pass), l));
      const float u0 = rng.uniformFloat(), u1 = rng.uniformFloat(), u2 = rng.uniformFloat();
      const LightSample ls = scene.lights().sampleLight(l, u0, u1, u2);
      LightSegment s;
      if (!makeSegment(scene, sp, ls.point, s.segment)) continue;
      s.object = sp.object;
      s.pixel = pixel;
      s.light = l;
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace proxyvis::ecosys
