// render: one image of a scene with one visibility estimator, at a number of light samples per
// pixel or for a time budget; no reference. The plain counterpart of render-compare (same flags,
// same renderer, same seeds: `render --seed S --spp N` gives render-compare's first-seed image of
// that estimator at N spp).
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <climits>
#include <cstdio>

#include "image/image_io.h"
#include "image/oiio_module.h"
#include "proxies/check/class_trust.h"
#include "render/image_metadata.h"
#include "render/render_options.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render_data_parallel.h"
#include "render_image.h"
#include "render_out_of_core.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  fs::path scene;
  fs::path output;
  std::string estimator = "exact";
  int spp = 16;
  double seconds = 0;  // --time; > 0 replaces --spp
  RenderFlags render;
  DataParallelFlags data_parallel;
  OutOfCoreFlags out_of_core;
  CommonOptions common;
};

void addOptions(CLI::App& app, RenderOptions& o) {
  app.add_option("scene", o.scene, "Scene file (JSON, scenes/FORMAT.md)")->required();
  app.add_option("-o,--output", o.output,
                 "Image to write: .exr (linear RGB + AOV layers visibility.Y, rays.*) or .png "
                 "(tone-mapped sRGB); missing folders are created")
      ->required();
  app.add_option("--estimator", o.estimator, "Visibility estimator: " + allEstimatorNames(", "))
      ->capture_default_str();
  auto* spp = app.add_option("--spp", o.spp, "Light samples per pixel")
                  ->check(integerIn(1, kMaxSpp))
                  ->capture_default_str();
  auto* time = app.add_option("--time", o.seconds,
                              "Render for this many seconds instead (as many samples as fit)")
                   ->check(numberIn(0.001, kMaxRenderSeconds));
  spp->excludes(time);
  addRenderFlags(app, o.render);
  addDataParallelFlags(app, o.data_parallel, false);
  addOutOfCoreFlags(app, o.out_of_core);
  addCommonOptions(app, o.common);
}

int runRender(RenderOptions& o) {
  if (o.data_parallel.enabled) {
    DataParallelRenderRequest request{o.scene,   o.output, o.estimator,     o.spp,
                                      o.seconds, o.render, o.data_parallel, o.common};
    if (!o.out_of_core.geometry_budget.empty())
      throw Error("", "--geometry-budget is not available with --data-parallel", {},
                  "render out of core on one machine, or data-parallel in core");
    return runDataParallelRender(request);
  }
  if (!o.out_of_core.geometry_budget.empty()) {
    OutOfCoreRenderRequest request{o.scene,   o.output, o.estimator,   o.spp,
                                   o.seconds, o.render, o.out_of_core, o.common};
    return runOutOfCoreRender(request);
  }
  if (o.output == "-")
    throw Error("-o -", "an image cannot be written to stdout", {}, "name an .exr or .png file");
  checkOutputs({o.scene.string()}, {{"-o", o.output.string()}, {"--json", o.common.json_path}});
  const RenderImageFormat format = renderImageFormat(o.output);
  // The image writer, while the scene loads.
  std::future<void> image_module = preloadOiioModuleFor(o.output);
  const EstimatorKind kind = parseEstimatorName(o.estimator);
  o.render.resolve();
  SceneDesc desc = loadSceneDesc(o.scene);
  o.render.applyTo(desc);
  TrustedRenderScene loaded =
      loadTrustedRenderScene(desc, o.render.sceneOptions(o.common.quiet), "render");
  if (kind != EstimatorKind::kExact && !loaded.scene->usesProxies() && !o.common.quiet)
    std::fprintf(stderr,
                 "render: warning: %s: no mesh of this scene has a proxy: %s traces the "
                 "originals only (generate proxies with proxy-gen)\n",
                 desc.path.filename().string().c_str(), estimatorName(kind));

  image_module.get();  // a missing image module fails now, not after the render

  RenderSettings settings;
  settings.estimator = o.render.estimatorSetup(kind);
  settings.spp = o.seconds > 0 ? INT_MAX : o.spp;
  settings.time_budget = o.seconds;
  // Seed index 0 of --seed, as render-compare's first seed: the two programs' images agree.
  settings.seed = hashKeys(o.common.seed, 0);
  settings.quiet = o.common.quiet;
  const RenderResult result = render(*loaded.scene, settings);

  RenderMetadata meta{"render", estimatorName(kind), result.spp, result.seconds, o.common.seed, {}};
  if (o.seconds > 0) meta.extra.push_back({"proxyvis:time_budget", float(o.seconds)});
  const RenderImageFile file = renderImageFile(
      format, result.radiance, [&] { return exrWithAovs(result); }, exrWithAovsChannelNames(),
      renderAttributes(desc, meta));
  RenderRun run{
      estimatorName(kind),
      o.common.seed,
      o.seconds,
      int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)),
      loaded.scene->buildChoice().name(),
      loaded.scene->buildChoice().reason};
  const nlohmann::json summary = renderSummary(desc, run, result, o.output);

  OutputSet outputs(MissingFolders::kCreate);
  outputs.add(o.output, [&](const fs::path& tmp) { writeImage(file.image, tmp, file.write); });
  if (!o.common.json_path.empty()) outputs.addText(o.common.json_path, summary.dump(2) + "\n");
  outputs.commit();

  printHumanReport(o.common,
                   fmt::format("render: wrote {}: {}, {} spp in {:.2f} s; shadow rays: {} "
                               "proxy, {} original, {} probe\n",
                               o.output.string(), estimatorName(kind), result.spp, result.seconds,
                               result.rays.proxy, result.rays.original, result.rays.probe));
  return kExitOk;
}

}  // namespace
}  // namespace proxyvis

int main(int argc, char** argv) {
  CLI::App app{
      "render: render a scene with one visibility estimator at a number of samples per pixel or "
      "for a time budget, and write the image (EXR with AOV layers, or PNG)",
      "render"};
  proxyvis::RenderOptions options;
  proxyvis::addOptions(app, options);
  return proxyvis::runApp(app, argc, argv, options.common, [&] {
    proxyvis::refuseDataParallelFlagsAlone(app, options.data_parallel);
    proxyvis::refuseOutOfCoreFlagsAlone(app, options.out_of_core,
                                        {"--ooc-policy", "--batch-passes"});
    return proxyvis::runRender(options);
  });
}
