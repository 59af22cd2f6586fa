#pragma once
// The steps of render() (RenderSession) shared with passSegments(): settings checks, shading
// points from primary rays, and the light samples of one pass.
#include <vector>

#include "render/render_scene.h"
#include "render/renderer.h"

namespace proxyvis::detail {

struct ShadingPoint {
  Vec3f p;  // hit point, offset along the normal by RenderScene::epsilon()
  Vec3f n;  // unit geometric normal facing the camera
  Vec3f albedo;
  uint32_t object = 0;
  bool valid = false;  // false: the primary ray missed (black pixel)
};

struct Tiling {
  int width = 0, height = 0, tile = 16, tiles_x = 0, tiles_y = 0;
  Tiling(int w, int h, int t) : width(w), height(h), tile(t) {
    tiles_x = (w + t - 1) / t;
    tiles_y = (h + t - 1) / t;
  }
  int count() const { return tiles_x * tiles_y; }
  template <typename F>  // f(x, y, pixel)
  void forEachPixel(int tile_index, F&& f) const {
    const int x0 = (tile_index % tiles_x) * tile, y0 = (tile_index / tiles_x) * tile;
    for (int y = y0; y < std::min(y0 + tile, height); ++y)
      for (int x = x0; x < std::min(x0 + tile, width); ++x) f(x, y, uint32_t(y * width + x));
  }
};

// One primary ray per pixel, jittered from a stream keyed on the pixel alone. Parallel over tiles.
std::vector<ShadingPoint> shadingPoints(const RenderScene& scene, const Tiling& tiling);

// The primary ray of pixel (x, y) (index `pixel`), as shadingPoints() traces it.
Segment primaryRay(const Camera& camera, int x, int y, uint32_t pixel);
// The shading point of a primary hit (invalid for a miss or a degenerate normal): the hit point
// offset by `epsilon` along the normal that faces the camera. The data-parallel renderer calls it
// with the same hit on the rank that owns the geometry, so both renderers shade alike.
ShadingPoint shadingPointOf(const Segment& ray, const Hit& hit, float epsilon, const Vec3f& albedo);

// A light sample prepared for visibility estimation; weight == 0 means it needs no visibility
// (back-facing, or the pixel has no shading point).
struct PreparedSample {
  Segment segment;
  Vec3f weight;  // albedo/pi * L_e * cos_x * cos_y / dist^2 / pdf_area
  uint32_t light = 0;
};

// Light samples [first, first + count) of `pass` for one shading point, from the stream keyed
// on (seed, pixel, pass).
void prepareSamples(const RenderScene& scene, const ShadingPoint& sp, uint64_t seed, uint32_t pixel,
                    int pass, int count, PreparedSample* out);
void prepareSamples(const LightSampler& lights, const ShadingPoint& sp, uint64_t seed,
                    uint32_t pixel, int pass, int count, PreparedSample* out);

// A segment from the shading point to a point on a light, or false when the geometry term is
// zero (the light is behind the surface).
bool makeSegment(const RenderScene& scene, const ShadingPoint& sp, const Vec3f& light_point,
                 Segment& out);
bool makeSegment(const ShadingPoint& sp, const Vec3f& light_point, Segment& out);

// The learning region of a query: screen tile x light x whether the shading point's own object
// uses a proxy. Points on such an object trace their own original in both V and V' (the
// self-shadowing rule), so their proxy rays cost more and they must not share a cost model with
// the points beside them (the ground under the dragon).
inline uint32_t learningRegion(const RenderScene& scene, uint32_t object, uint32_t tile,
                               uint32_t light) {
  const uint32_t self = scene.objects()[object].proxy >= 0 ? 1u : 0u;
  return (tile * uint32_t(scene.lights().numLights()) + light) * 2u + self;
}

// Throws Error for settings no render can run with (tile size, nothing to render, budget).
void validateRenderSettings(const RenderSettings& settings);

// Under a time budget, the samples per pixel of the next pass when passes hold several (estimators
// with probes): the first pass is whole (nothing is measured yet; a smaller one would pay the
// probes for fewer samples); later ones take as many samples as the time left allows at the last
// pass's rate, so that the render does not overshoot its budget by a whole pass. A pass costs
// about (2 x probes + samples) ray units: probes are drawn per pixel and pass, traced against
// proxy and original. 0 = stop (even one sample would overshoot by more than half its own time).
int passSamplesWithinBudget(double seconds_left, int full_pass, int pass, double last_seconds,
                            int last_count, int probes);

}  // namespace proxyvis::detail
