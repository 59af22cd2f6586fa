#pragma once
// Direct-illumination renderer. lib/render owns this file; render-compare (apps/) and the
// benches call render() (or run a RenderSession) and read RenderResult.
//
// Per pixel: one primary ray (its jitter keyed on the pixel only, so every estimator, seed and the
// reference shade the same points and MSE measures visibility estimation alone), then `spp`
// light samples (area sampling over all lights, uniform by area; cosine terms; Lambertian BRDF),
// visibility from the chosen estimator:
//     L = albedo/pi * L_e * cos(theta_x) * cos(theta_y) / dist^2 / pdf_area * V~
// Lights emit on both sides and are not visible to camera rays (primary misses are black).
// Light samples run in passes (samples_per_pass per pixel per pass) so that learning estimators
// (roulette) use passes < k for pass k. TBB over tiles; light samples are keyed on
// (seed, pixel, pass) and estimator randomness on (seed, pixel, pass, 1): bit-identical output
// for a seed at any thread count (as long as the estimator's own learning is deterministic).
// Learning regions are screen tile x light x self: region = (tile_index * num_lights + light) * 2
// + (1 if the shading point's object uses a proxy, else 0); each query also names its
// (pixel, light) point = pixel * num_lights + light (< num_points).
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"
#include "util/image.h"

namespace proxyvis {

class RenderScene;  // render/render_scene.h: meshes, proxies, Embree scenes, lights, camera

struct RenderSettings {
  // kind, probes_per_point, q_min and fixed_costs are used; num_regions, num_points and
  // proxy_class are set by the renderer (tiles x lights, pixels x lights, and
  // RenderScene::proxyClass()).
  EstimatorSetup estimator;
  int spp = 16;  // light samples per pixel (upper bound when time_budget > 0; <= 0 = none)
  double time_budget = 0;  // seconds; > 0: render passes until the budget is spent
  uint64_t seed = 0;
  int tile_size = 16;  // also the learning-region size (regions = tiles x lights x 2)
  // Light samples per pixel per pass. 0 = automatic: 1, except for estimators with probe rays
  // (probes are drawn per shading point and call), which get all spp in one pass (16 per pass
  // under a time budget).
  int samples_per_pass = 0;
  // Ignore the scene's verified proxy class and tell the estimator "general".
  bool force_general_proxies = false;
  bool quiet = false;  // no progress bar
};

struct RenderResult {
  Image radiance;    // linear RGB
  Image visibility;  // 1 channel: mean estimated visibility over the pixel's traced light samples
  Image cost;        // 3 channels: proxy, original, probe rays per pixel (totals)
  int spp = 0;       // light samples per pixel actually taken
  int passes = 0;
  double seconds = 0;             // wall time on the render's own clock (after scene loading)
  double cpu_seconds = 0;         // process CPU time (all threads) over the same intervals
  double shading_seconds = 0;     // primary rays + light sampling (primary_seconds included)
  double primary_seconds = 0;     // primary rays alone
  double visibility_seconds = 0;  // estimator calls (shadow rays, probes) and accumulation
  RayCounts rays;
  uint64_t primary_rays = 0;
  uint64_t shadow_segments = 0;                   // light samples that needed a visibility estimate
  ProxyClass proxy_class = ProxyClass::kGeneral;  // what the estimator was told
  LearnedSummary learned;                         // estimator.learnedSummary() after the last pass

  bool operator==(const RenderResult&) const = default;
};

// A result's numbers in a unit result's header (lib/plan), exactly: "spp", "passes", "seconds",
// "cpu_seconds", "shading_seconds", "primary_seconds", "visibility_seconds", "rays" [proxy,
// original, probe], "primary_rays", "shadow_segments", "proxy_class" (its name), "learned". The
// images are not in it (the unit file stores them as raw floats); from_json leaves them empty.
void to_json(nlohmann::json& j, const RenderResult& r);
void from_json(const nlohmann::json& j, RenderResult& r);

// The EstimatorSetup render() uses: settings.estimator with num_regions and proxy_class filled
// in for this scene.
EstimatorSetup estimatorSetupFor(const RenderScene& scene, const RenderSettings& settings);

// Renders with makeEstimator(estimatorSetupFor(scene, settings)). Throws Error for bad settings.
// A RenderSession (render_session.h) run to its end: the same render in resumable slices.
RenderResult render(const RenderScene& scene, const RenderSettings& settings);
// Renders with a caller-made estimator (which must accept estimatorSetupFor(...).num_regions
// regions); settings.estimator is then only used for its probe count.
RenderResult render(const RenderScene& scene, const RenderSettings& settings,
                    VisibilityEstimator& estimator);

// The shadow segments of pass `pass`, exactly as render() draws them for an estimator without
// probes (samples_per_pass 0 means 1 here), with the object each leaves from. For benches and
// tests.
struct PassSegments {
  std::vector<Segment> segments;
  std::vector<uint32_t> objects;  // RenderObject index of the shading point
  std::vector<uint32_t> pixels;   // y * width + x
};
PassSegments passSegments(const RenderScene& scene, const RenderSettings& settings, int pass);

}  // namespace proxyvis
