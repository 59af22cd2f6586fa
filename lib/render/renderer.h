#pragma once
// Direct-illumination renderer. DRAFT CONTRACT: lib/render owns this file and may extend it;
// render-compare (apps/) and the benches call render() and read RenderResult.
//
// Per pixel: one primary ray (its jitter keyed on the pixel only, so every estimator, seed and the
// reference shade the same points and MSE measures visibility estimation alone), then `spp`
// light samples (area sampling over all lights, cosine terms, Lambertian BRDF), visibility from
// the chosen estimator. Light samples run in passes (one sample per pixel per pass) so that
// learning estimators (roulette) can use passes < k for pass k. TBB over tiles; bit-identical
// output for a seed at any thread count.
#include <cstdint>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"

namespace proxyvis {

class RenderScene;  // loaded meshes, proxies, Embree scenes, lights, camera (lib/render)

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, top row first, interleaved channels
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

struct RenderSettings {
  EstimatorSetup estimator;
  int spp = 16;                 // light samples per pixel (upper bound when time_budget > 0)
  double time_budget = 0;       // seconds; > 0: render passes until the budget is spent
  uint64_t seed = 0;
  int tile_size = 16;           // also the learning-region size (regions = tiles x lights)
  bool quiet = false;           // no progress bar
};

struct RenderResult {
  Image radiance;    // linear RGB
  Image visibility;  // 1 channel: mean estimated visibility per pixel
  Image cost;        // 3 channels: proxy, original, probe rays per pixel
  int spp = 0;       // light samples per pixel actually taken
  double seconds = 0;          // wall time of the whole render
  double shading_seconds = 0;  // primary rays and shading setup (measured separately)
  RayCounts rays;
  uint64_t primary_rays = 0;
};

RenderResult render(const RenderScene& scene, const RenderSettings& settings);

}  // namespace proxyvis
