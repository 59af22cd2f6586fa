// Instanced against flattened tracing of a whole scene file: for each build, the load time, the
// bytes Embree allocated (its memory monitor: peak and after the build) per flattened triangle,
// and the shadow-ray cost on the renderer's own segments (primary hits to light samples, as
// render() draws them), in ns of CPU time per ray and ns of wall time per ray at the run's
// threads. The bytes per triangle is the constant of --build auto's memory estimate
// (lib/render/render_scene_build.h).
//
//   build/bin/bench_scene_trace scenes/ecosys.json [--passes 8] [--threads 2] [--builds
//   flat,instanced]
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "render/render_options.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace pv = proxyvis;

namespace {

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void measure(const std::string& scene_file, pv::InstanceBuild build, const char* name, int passes,
             int reps) {
  pv::RenderSceneOptions options;
  options.instance_build = build;
  options.quiet = true;
  const pv::Stopwatch load;
  const auto scene = pv::loadRenderScene(scene_file, options);
  const double load_s = load.seconds();
  const pv::TraceDevice& device = scene->device();
  const uint64_t flat = scene->buildChoice().flat_triangles;
  std::vector<pv::Segment> segs;
  pv::RenderSettings settings;
  for (int p = 0; p < passes; ++p) {
    pv::PassSegments ps = pv::passSegments(*scene, settings, p);
    segs.insert(segs.end(), ps.segments.begin(), ps.segments.end());
  }
  std::vector<uint8_t> out(segs.size());
  double best_cpu = 1e30, best_wall = 1e30;
  for (int r = 0; r < reps; ++r) {
    const double c0 = cpuSeconds();
    const pv::Stopwatch wall;
    scene->originals().occluded(segs, out);
    best_wall = std::min(best_wall, wall.seconds());
    best_cpu = std::min(best_cpu, cpuSeconds() - c0);
  }
  uint64_t blocked = 0;
  for (uint8_t o : out) blocked += o;
  std::printf("| %s | %.1f | %.1f | %.0f | %.0f | %.0f | %zu | %.2f | %.1f | %.1f |\n", name,
              double(flat) / 1e6, load_s, double(device.peakBytes()) / 1e6,
              double(device.bytesInUse()) / 1e6, double(device.peakBytes()) / double(flat),
              segs.size(), double(blocked) / double(segs.size()),
              1e9 * best_cpu / double(segs.size()), 1e9 * best_wall / double(segs.size()));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Instanced vs flattened tracing of a scene: load time, Embree bytes, ns per ray");
  std::string scene, builds = "instanced,flat";
  int passes = 8, reps = 3, threads = 0;
  app.add_option("scene", scene, "scene file")->required();
  app.add_option("--passes", passes, "renderer passes of segments (1 per pixel each)")
      ->check(pv::integerIn(1, 4096));
  app.add_option("--reps", reps, "repetitions; the best is reported")->check(pv::integerIn(1, 100));
  app.add_option("--threads", threads, "threads (0 = all)")->check(pv::integerIn(0, 4096));
  app.add_option("--builds", builds, "comma-separated: instanced, flat");
  CLI11_PARSE(app, argc, argv);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  size_t(threads));
  std::printf(
      "| build | flattened triangles (M) | load (s) | Embree peak (MB) | Embree after build (MB) "
      "| peak bytes / flattened triangle | segments | blocked | ns CPU / ray | ns wall / ray |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for (const std::string& b : pv::splitCommaList(builds)) {
      if (b == "instanced")
        measure(scene, pv::InstanceBuild::kInstanced, "instanced", passes, reps);
      else if (b == "flat")
        measure(scene, pv::InstanceBuild::kFlat, "flat", passes, reps);
      else
        throw pv::Error({}, "--builds: unknown build '" + b + "'", "", "instanced or flat");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_scene_trace: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
