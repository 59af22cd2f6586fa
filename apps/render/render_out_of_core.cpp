#include "render_out_of_core.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <CLI/CLI.hpp>
#include <algorithm>

#include "image/image_io.h"
#include "image/oiio_module.h"
#include "outofcore/geometry_budget.h"
#include "outofcore/out_of_core_render.h"
#include "outofcore/out_of_core_scene.h"
#include "render/image_metadata.h"
#include "render_image.h"
#include "scene/scene_desc.h"
#include "util/build_info.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/peak_rss.h"
#include "util/rng.h"

namespace proxyvis {

namespace {

Image outOfCoreExr(const OutOfCoreResult& r) {
  const size_t n = size_t(r.radiance.width) * size_t(r.radiance.height);
  Image out{r.radiance.width, r.radiance.height, 4, std::vector<float>(n * 4)};
  for (size_t i = 0; i < n; ++i) {
    std::copy_n(&r.radiance.pixels[i * 3], 3, &out.pixels[i * 4]);
    out.pixels[i * 4 + 3] = r.visibility.pixels[i];
  }
  return out;
}

nlohmann::json summaryJson(const OutOfCoreRenderRequest& o, const SceneDesc& desc,
                           const OutOfCoreScene& scene, const OutOfCoreSettings& settings,
                           const OutOfCoreResult& r, uint64_t scan_peak) {
  const OutOfCoreStats& s = r.stats;
  return {
      {"program", "render"},
      {"scene", desc.path.string()},
      {"output", o.output.string()},
      {"estimator", settings.policy == OutOfCorePolicy::kProxiesRoulette ? "roulette" : "exact"},
      {"policy", outOfCorePolicyName(settings.policy)},
      {"spp", r.spp},
      {"seed", o.common.seed},
      {"width", r.radiance.width},
      {"height", r.radiance.height},
      {"threads",
       int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))},
      {"scene_build", scene.buildChoice().name()},
      {"geometry_budget", o.out_of_core.geometry_budget},
      {"geometry_budget_bytes", s.budget_bytes},
      {"in_core_bytes", scene.inCoreBytes()},
      {"proxy_bytes", scene.proxyBytes()},
      {"batch_passes", settings.batch_passes},
      {"page_cache", settings.cold_reads ? "cold" : "warm"},
      {"batches", s.batches},
      {"loads", s.cache.loads},
      {"loads_per_frame", s.cache.loads},
      {"hits", s.cache.hits},
      {"evictions", s.cache.evictions},
      {"bytes_read", s.cache.bytes_read},
      {"load_seconds", s.cache.loadSeconds()},
      {"read_seconds", s.cache.read_seconds},
      {"build_seconds", s.cache.build_seconds},
      {"peak_cache_bytes", s.cache.peak_resident_bytes},
      // The process's peak: the scan's or the render's.
      {"peak_rss_bytes", std::max(scan_peak, s.peak_rss_bytes)},
      {"scan_peak_rss_bytes", scan_peak},
      {"render_peak_rss_bytes", s.peak_rss_bytes},
      {"rss_before_bytes", s.rss_before_bytes},
      {"peak_rss_growth_bytes", s.peak_rss_growth_bytes},
      {"rss_growth",
       {{"primary_bytes", s.primary_rss_growth_bytes},
        {"route_bytes", s.route_rss_growth_bytes},
        {"trace_bytes", s.trace_rss_growth_bytes},
        {"load_bytes", s.load_rss_growth_bytes},
        {"load_over_built", s.load_growth_over_built}}},
      {"queue_bytes", s.queue_bytes},
      {"primary_queue_bytes", s.primary_queue_bytes},
      {"queue_cap_bytes", s.queue_cap_bytes},
      {"capped_batches", s.capped_batches},
      // The memory bound (docs/out_of_core.md, "Memory"): budget + proxies + image + overhead,
      // against the render's measured peak growth plus the proxies resident before it.
      {"image_bytes", s.image_bytes},
      {"overhead_bytes", s.overhead_bytes},
      {"rss_bound_bytes", s.rss_bound_bytes},
      {"bounded_peak_bytes", s.bounded_peak_bytes},
      {"within_rss_bound", s.withinRssBound()},
      {"peak_loading_bytes", s.cache.peak_loading_bytes},
      {"built_bytes", scene.builtBytes()},
      {"scan_seconds", scene.scanSeconds()},
      {"seconds", s.seconds},
      {"primary_seconds", s.primary_seconds},
      {"shadow_seconds", s.shadow_seconds},
      {"shadow_segments", s.shadow_segments},
      {"queued", s.queued},
      {"unqueued_segments", s.unqueued_segments},
      {"blocked_by_inside", s.blocked_by_inside},
      {"original_traces", s.original_traces},
      {"load_q", settings.policy != OutOfCorePolicy::kProxiesRoulette ? nlohmann::json(1.0)
                 : settings.learn_q                                   ? nlohmann::json("learned")
                                    : nlohmann::json(settings.load_q)},
      {"mean_load_q", s.q_draws ? s.q_sum / double(s.q_draws) : 1.0},
      {"skipped_queues", s.skipped_queues},
      {"roulette_added_variance", s.roulette_added_variance},
      {"build", buildText()},
      {"version", versionText()},
  };
}

}  // namespace

void addOutOfCoreFlags(CLI::App& app, OutOfCoreFlags& f) {
  addOutOfCoreCommonFlags(app, f, "Render out of core", "Out of core: ");
  app.add_option("--ooc-policy", f.policy,
                 "Out of core: exact-batched (segments queued on every mesh whose object box they "
                 "enter), proxies-exact (only where the proxies cannot decide) or "
                 "proxies-roulette (a mesh's queue traced with probability --load-q per batch, "
                 "else the proxies' answer, weighted to stay unbiased)")
      ->capture_default_str();
  app.add_option("--batch-passes", f.batch_passes,
                 "Out of core: passes whose segments are queued together before any mesh is "
                 "loaded (0: the whole frame)")
      ->check(CLI::Range(0, 1 << 20))
      ->capture_default_str();
}

int runOutOfCoreRender(OutOfCoreRenderRequest& o) {
  if (o.seconds > 0)
    throw Error("", "--time is not available with --geometry-budget", {}, "use --spp");
  if (o.estimator != "exact")
    throw Error("", "--estimator " + o.estimator + " is not available with --geometry-budget",
                "the out-of-core renderer decides visibility exactly (its policy says how)",
                "use --estimator exact with --ooc-policy exact-batched or proxies-exact");
  if (o.output == "-")
    throw Error("-o -", "an image cannot be written to stdout", {}, "name an .exr or .png file");
  const GeometryBudget budget = parseGeometryBudget(o.out_of_core.geometry_budget);
  OutOfCoreSettings settings;
  settings.policy = parseOutOfCorePolicy(o.out_of_core.policy);
  checkOutputs({o.scene.string()}, {{"-o", o.output.string()}, {"--json", o.common.json_path}});
  const RenderImageFormat format = renderImageFormat(o.output);
  std::future<void> image_module = preloadOiioModuleFor(o.output);
  o.render.resolve();
  SceneDesc desc = loadSceneDesc(o.scene);
  o.render.applyTo(desc);
  OutOfCoreSceneOptions scene_options;
  scene_options.scene = o.render.sceneOptions(o.common.quiet);
  scene_options.proxies = settings.policy != OutOfCorePolicy::kExactBatched;
  const auto scene = OutOfCoreScene::load(desc, scene_options);
  image_module.get();

  settings.spp = o.spp;
  // Seed index 0 of --seed, as render and render-compare: the images agree.
  settings.seed = hashKeys(o.common.seed, 0);
  settings.batch_passes = o.out_of_core.batch_passes;
  applyLoadQ(o.out_of_core.load_q, settings);
  settings.q_min = o.render.q_min;
  settings.cold_reads = o.out_of_core.cold_reads;
  settings.budget_bytes = budget.resolve(scene->inCoreBytes());
  settings.quiet = o.common.quiet;
  // The process's peak so far: the scan's (each original read and built alone) and the libraries'.
  const uint64_t scan_peak = peakRssBytes();
  const OutOfCoreResult result = renderOutOfCore(*scene, settings);

  RenderMetadata meta{"render",      outOfCorePolicyName(settings.policy),
                      result.spp,    result.stats.seconds,
                      o.common.seed, {}};
  meta.extra.push_back({"proxyvis:ooc_policy", std::string(outOfCorePolicyName(settings.policy))});
  if (settings.policy == OutOfCorePolicy::kProxiesRoulette)
    meta.extra.push_back({"proxyvis:load_q", loadQText(settings)});
  meta.extra.push_back({"proxyvis:geometry_budget", o.out_of_core.geometry_budget});
  const RenderImageFile file = renderImageFile(
      format, result.radiance, [&] { return outOfCoreExr(result); },
      {"R", "G", "B", "visibility.Y"}, renderAttributes(desc, meta));
  const nlohmann::json summary = summaryJson(o, desc, *scene, settings, result, scan_peak);
  OutputSet outputs(MissingFolders::kCreate);
  outputs.add(o.output,
              [&](const std::filesystem::path& tmp) { writeImage(file.image, tmp, file.write); });
  if (!o.common.json_path.empty()) outputs.addText(o.common.json_path, summary.dump(2) + "\n");
  outputs.commit();

  const OutOfCoreStats& s = result.stats;
  printHumanReport(
      o.common,
      fmt::format(
          "render: wrote {}: --ooc-policy {}, {} spp in {:.2f} s (scan {:.2f} s)\n"
          "  geometry budget {} = {:.1f} MiB of {:.1f} MiB in core; {} loads ({:.1f} MB "
          "read, {:.2f} s reading and building), {} hits, {} evictions, {} queues skipped\n"
          "  shadow segments {}: {} queued on meshes, {} decided without a load ({} "
          "blocked by inside proxies); peak RSS {:.1f} MiB\n"
          "  memory: the render grew RSS by {:.1f} MiB; with the proxies {:.1f} MiB against "
          "budget + proxies + image + overhead = {:.1f} MiB ({})\n",
          o.output.string(), outOfCorePolicyName(settings.policy), result.spp, s.seconds,
          scene->scanSeconds(), o.out_of_core.geometry_budget,
          double(s.budget_bytes) / double(1 << 20), double(scene->inCoreBytes()) / double(1 << 20),
          s.cache.loads, 1e-6 * double(s.cache.bytes_read), s.cache.loadSeconds(), s.cache.hits,
          s.cache.evictions, s.skipped_queues, s.shadow_segments, s.queued, s.unqueued_segments,
          s.blocked_by_inside, double(std::max(scan_peak, s.peak_rss_bytes)) / double(1 << 20),
          double(s.peak_rss_growth_bytes) / double(1 << 20),
          double(s.bounded_peak_bytes) / double(1 << 20),
          double(s.rss_bound_bytes) / double(1 << 20), s.withinRssBound() ? "within" : "over"));
  return kExitOk;
}

}  // namespace proxyvis
