// The oracle ceiling (docs/performance.md, "The ceiling") of a scene, measured the way
// render-compare measures it, but with more passes and at a chosen size: how much more efficient
// than exact visibility any estimator built on these proxies can be.
//
// For P passes of one light sample per pixel (the renderer's own segments), every segment is
// traced against the proxies (with the self-shadowing rule) and the originals, each ray timed
// with the TSC (render/ceiling_stats.h). c_s, the cost every sample pays outside visibility, comes
// from an exact render at --spp. The oracle, its per-light table and the sentence on what limits
// the gain are estimate/ceiling.h's, shared with render-compare.
#include <fmt/core.h>
#include <tbb/task_arena.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "estimate/ceiling.h"
#include "proxies/check/class_trust.h"
#include "render/ceiling_stats.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"

namespace proxyvis {
namespace {

void printLine(const std::string& name, const CeilingSummary& s) {
  std::printf(
      "| %s | %.0f | %.3f | %.4f | %.4f | %.4f | %.1f / %.1f | %.1f / %.1f | %.1f | %d of %d | "
      "%.3f |\n",
      name.c_str(), s.segments, s.p_blocked, s.p_mh, s.p_hm, s.visibility_var, s.costs.proxy[0],
      s.costs.proxy[1], s.costs.original[0], s.costs.original[1], s.costs.per_sample,
      s.regions_roulette, s.regions, s.ceiling);
}

int run(const std::string& scene_file, int passes, int spp, int width, int height, int tile,
        double q_min, const std::string& proxy_kind) {
  SceneDesc desc = loadSceneDesc(scene_file);
  if (width > 0) desc.camera.width = width;
  if (height > 0) desc.camera.height = height;
  RenderSceneOptions ro;
  ro.proxy_kind = proxy_kind;
  // A claimed class is relied on only once proven (hash or exact check), as in render-compare.
  for (const ProxyTrust& t : establishProxyClasses(desc, ro))
    if (t.trust.status == ClassStatus::kDowngraded)
      std::fprintf(stderr, "bench_oracle_ceiling: warning: %s\n", describeProxyTrust(t).c_str());
  auto scene = loadRenderScene(desc, ro);

  RenderSettings settings;
  settings.seed = 11;
  settings.tile_size = tile;
  settings.quiet = true;
  const CeilingMeasurement m = measureCeilingStats(*scene, settings, passes, 1e30);
  settings.spp = spp;
  const RenderResult exact = render(*scene, settings);
  const double c_s = shadingNsPerSegment({&exact}, m);
  const CeilingResult r = computeCeiling(ceilingInput(*scene, m, c_s, q_min));

  std::printf("## %s (%dx%d, %d passes, %llu segments, proxy class %s, %.2f s)\n\n",
              scene_file.c_str(), desc.camera.width, desc.camera.height, m.passes,
              (unsigned long long)m.segments, proxyClassName(scene->proxyClass()), m.seconds);
  std::printf(
      "| light | segments | P(V'=0) | P(MH') | P(HM') | V(1-V) | c_p given V'=0 / 1 (ns) | c_o "
      "given V'=0 / 1 (ns) | c_s (ns) | roulette regions | ceiling |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < r.lights.size(); ++i) printLine(std::to_string(i), r.lights[i]);
  printLine("all", r.scene);
  std::printf(
      "\n%s\n\nc_s from an exact render at %d spp (%.3f s shading, %.3f s visibility, "
      "%.2f cores used of %d); rays timed one by one (TSC), MSE-weighted variances.\n\n",
      r.explanation.c_str(), spp, exact.shading_seconds, exact.visibility_seconds, m.cpu_per_wall,
      tbb::this_task_arena::max_concurrency());
  return 0;
}

}  // namespace
}  // namespace proxyvis

int main(int argc, char** argv) {
  CLI::App app{"bench_oracle_ceiling: efficiency ceiling of proxy-based visibility on a scene"};
  std::string scene;
  int passes = 16, spp = 16, width = 0, height = 0, tile = 16;
  double q_min = 0.05;
  std::string proxy_kind;
  app.add_option("scene", scene, "Scene with proxies")->required();
  app.add_option("--passes", passes, "Light samples per pixel traced for the statistics")
      ->capture_default_str()
      ->check(proxyvis::integerIn(2, 4096));
  app.add_option("--spp", spp, "Samples per pixel of the exact render that measures c_s")
      ->capture_default_str()
      ->check(proxyvis::integerIn(1, 1 << 20));
  app.add_option("--width", width, "Override the image width")
      ->check(proxyvis::integerIn(1, 16384));
  app.add_option("--height", height, "Override the image height")
      ->check(proxyvis::integerIn(1, 16384));
  app.add_option("--tile", tile, "Region size in pixels")
      ->capture_default_str()
      ->check(proxyvis::integerIn(1, 4096));
  app.add_option("--q-min", q_min, "Roulette floor")
      ->capture_default_str()
      ->check(proxyvis::numberIn(1e-6, 1));
  app.add_option("--proxy-kind", proxy_kind, "Which proxy of each mesh");
  proxyvis::CommonOptions common;
  proxyvis::addCommonOptions(app, common);
  return proxyvis::runApp(app, argc, argv, common, [&] {
    return proxyvis::run(scene, passes, spp, width, height, tile, q_min, proxy_kind);
  });
}
