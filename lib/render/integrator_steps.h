#pragma once
// The steps of direct illumination that the single-process renderer (render_session.cpp) and the
// data-parallel one (lib/distributed) both take, so that both shade the same points with the same
// light samples: primary rays, shading points, and the light samples of one pass keyed on (seed,
// pixel, pass). An exact data-parallel image equals the single-process one bit for bit only while
// both call these.
#include <algorithm>
#include <cstdint>

#include "render/camera.h"
#include "render/light_sampler.h"
#include "render/render_scene.h"
#include "trace/trace_scene.h"
#include "util/segment.h"

namespace proxyvis {

struct ShadingPoint {
  Vec3f p;  // hit point, offset along the normal by RenderScene::epsilon()
  Vec3f n;  // unit geometric normal facing the camera
  Vec3f albedo;
  uint32_t object = 0;
  bool valid = false;  // false: the primary ray missed (black pixel)
};

// Square screen tiles: the unit of parallel work and of the learning regions.
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

// The primary ray of pixel (x, y) (index `pixel`), jittered from a stream keyed on the pixel alone.
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
  // False for a zero weight: the sample adds nothing and its segment is never traced.
  bool needsVisibility() const { return weight.x > 0 || weight.y > 0 || weight.z > 0; }
};

// One pixel's sums of weighted visibility estimates. Every renderer adds a pixel's samples in the
// same order (pass by pass) through add(), so that their images agree bit for bit.
struct SampleSums {
  Vec3d radiance;
  double vis_sum = 0;
  uint32_t vis_n = 0;
  void add(const Vec3f& weight, double v) {
    radiance += Vec3d(weight) * v;
    vis_sum += v;
    vis_n += 1;
  }
  // The pixel's radiance (channel c) over `spp` light samples per pixel, and its mean visibility.
  float radianceMean(int c, int spp) const { return float(radiance[c] / spp); }
  float visibilityMean() const { return vis_n ? float(vis_sum / vis_n) : 0.0f; }
  // Both into an image's pixel: rgb[0..2] and *visibility (every renderer writes them so).
  void writeMeans(int spp, float* rgb, float* visibility) const {
    for (int c = 0; c < 3; ++c) rgb[c] = radianceMean(c, spp);
    *visibility = visibilityMean();
  }
};

// Light samples [first, first + count) of `pass` for one shading point, from the stream keyed
// on (seed, pixel, pass).
void prepareSamples(const LightSampler& lights, const ShadingPoint& sp, uint64_t seed,
                    uint32_t pixel, int pass, int count, PreparedSample* out);
void prepareSamples(const RenderScene& scene, const ShadingPoint& sp, uint64_t seed, uint32_t pixel,
                    int pass, int count, PreparedSample* out);

// A segment from the shading point to a point on a light, or false when the geometry term is
// zero (the light is behind the surface).
bool makeSegment(const ShadingPoint& sp, const Vec3f& light_point, Segment& out);
bool makeSegment(const RenderScene& scene, const ShadingPoint& sp, const Vec3f& light_point,
                 Segment& out);

}  // namespace proxyvis
