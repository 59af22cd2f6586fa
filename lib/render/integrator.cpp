#include "render/integrator_steps.h"

#include "render/internal/integrator.h"
#include "render/shading_points.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "util/rng.h"

namespace proxyvis {

namespace {
// Primary-ray jitter is keyed on the pixel only, never on the seed: every estimator, seed and the
// reference shade the same points.
constexpr uint64_t kJitterSeed = 0x6a09e667f3bcc908ULL;
constexpr float kInvPi = 0.318309886183790671f;
}  // namespace

Segment primaryRay(const Camera& camera, int x, int y, uint32_t pixel) {
  Rng rng(kJitterSeed, pixel);
  const float jx = rng.uniformFloat(), jy = rng.uniformFloat();
  Segment ray;
  ray.org = camera.eye();
  ray.dir = normalize(camera.direction(float(x) + jx, float(y) + jy));
  ray.tnear = 0;
  ray.tfar = std::numeric_limits<float>::infinity();
  return ray;
}

ShadingPoint shadingPointOf(const Segment& ray, const Hit& hit, float epsilon,
                            const Vec3f& albedo) {
  ShadingPoint sp;
  if (!hit.hit || !(length(hit.ng) > 0)) return sp;
  Vec3f n = normalize(hit.ng);
  if (dot(n, ray.dir) > 0) n = -n;  // two-sided surfaces: shade the side the camera sees
  sp.n = n;
  sp.p = ray.org + ray.dir * hit.t + n * epsilon;
  sp.object = hit.user_id;
  sp.albedo = albedo;
  sp.valid = true;
  return sp;
}

bool makeSegment(const ShadingPoint& sp, const Vec3f& light_point, Segment& out) {
  const Vec3f wi = light_point - sp.p;
  if (!(dot(sp.n, wi) > 0)) return false;
  out.org = sp.p;
  out.dir = wi;
  out.tnear = 0;
  // Stop just short of the light: lights are not geometry, but a light lying on a surface (a
  // ceiling lamp) must not be shadowed by that surface.
  out.tfar = 1.0f - 1e-4f;
  return true;
}

bool makeSegment(const RenderScene&, const ShadingPoint& sp, const Vec3f& light_point,
                 Segment& out) {
  return makeSegment(sp, light_point, out);
}

void prepareSamples(const RenderScene& scene, const ShadingPoint& sp, uint64_t seed, uint32_t pixel,
                    int pass, int count, PreparedSample* out) {
  prepareSamples(scene.lights(), sp, seed, pixel, pass, count, out);
}

void prepareSamples(const LightSampler& lights, const ShadingPoint& sp, uint64_t seed,
                    uint32_t pixel, int pass, int count, PreparedSample* out) {
  Rng rng(seed, hashKeys(pixel, uint64_t(pass)));
  for (int j = 0; j < count; ++j) {
    PreparedSample& s = out[j];
    s.weight = {0, 0, 0};
    // Always draw three numbers, so sample j of a pass does not depend on earlier samples' fate.
    const float u0 = rng.uniformFloat(), u1 = rng.uniformFloat(), u2 = rng.uniformFloat();
    if (!sp.valid) continue;
    const LightSample ls = lights.sample(u0, u1, u2);
    s.light = ls.light;
    if (!makeSegment(sp, ls.point, s.segment)) continue;
    const Vec3f wi = s.segment.dir;
    const float d2 = dot(wi, wi);
    const float d = std::sqrt(d2);
    const float cos_x = dot(sp.n, wi) / d;
    const float cos_y = std::abs(dot(ls.normal, wi)) / d;
    if (!(cos_y > 0) || !(d2 > 0)) continue;
    const float g = float(double(cos_x) * cos_y / d2 / ls.pdf_area);
    s.weight = sp.albedo * ls.radiance * (kInvPi * g);
  }
}

std::vector<ShadingPoint> shadingPoints(const RenderScene& scene, const Tiling& tiling) {
  std::vector<ShadingPoint> points(size_t(tiling.width) * tiling.height);
  const float eps = scene.epsilon();
  tbb::parallel_for(0, tiling.count(), [&](int t) {
    tiling.forEachPixel(t, [&](int x, int y, uint32_t pixel) {
      const Segment ray = primaryRay(scene.camera(), x, y, pixel);
      const Hit hit = scene.originals().intersect(ray);
      if (!hit.hit) return;
      points[pixel] = shadingPointOf(ray, hit, eps,
                                     scene.desc().meshes[scene.objects()[hit.user_id].mesh].albedo);
    });
  });
  return points;
}

}  // namespace proxyvis
