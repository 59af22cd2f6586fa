// Instanced against flattened tracing of a whole scene file: for each build, the load time, the
// bytes Embree allocated (its memory monitor: peak and after the build) per flattened triangle,
// and the shadow-ray cost on the renderer's own segments (primary hits to light samples, as
// render() draws them), in ns of CPU time per ray and ns of wall time per ray at the run's
// threads, with the builds' repetitions interleaved. The bytes per triangle is the constant of
// --build auto's memory estimate (lib/render/render_scene_build.h).
//
//   build/bin/bench_scene_trace scenes/ecosys.json [--passes 8] [--threads 2] [--builds
//   flat,instanced]
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <ctime>
#include <memory>
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

struct Loaded {
  const char* name;
  std::unique_ptr<pv::RenderScene> scene;
  double load_seconds = 0;
  std::vector<pv::Segment> segs;
  double best_cpu = 1e30, best_wall = 1e30;
  uint64_t blocked = 0;
};

Loaded load(const std::string& scene_file, pv::InstanceBuild build, const char* name, int passes) {
  pv::RenderSceneOptions options;
  options.instance_build = build;
  options.quiet = true;
  Loaded l;
  l.name = name;
  const pv::Stopwatch watch;
  l.scene = pv::loadRenderScene(scene_file, options);
  l.load_seconds = watch.seconds();
  pv::RenderSettings settings;
  for (int p = 0; p < passes; ++p) {
    pv::PassSegments ps = pv::passSegments(*l.scene, settings, p);
    l.segs.insert(l.segs.end(), ps.segments.begin(), ps.segments.end());
  }
  return l;
}

void traceOnce(Loaded& l) {
  std::vector<uint8_t> out(l.segs.size());
  const double c0 = cpuSeconds();
  const pv::Stopwatch wall;
  l.scene->originals().occluded(l.segs, out);
  l.best_wall = std::min(l.best_wall, wall.seconds());
  l.best_cpu = std::min(l.best_cpu, cpuSeconds() - c0);
  l.blocked = 0;
  for (uint8_t o : out) l.blocked += o;
}

void print(const Loaded& l) {
  const pv::TraceDevice& device = l.scene->device();
  const uint64_t flat = l.scene->buildChoice().flat_triangles;
  const double n = double(l.segs.size());
  std::printf("| %s | %.2f | %.1f | %.0f | %.0f | %.0f | %zu | %.2f | %.1f | %.1f |\n", l.name,
              double(flat) / 1e6, l.load_seconds, double(device.peakBytes()) / 1e6,
              double(device.bytesInUse()) / 1e6, double(device.peakBytes()) / double(flat),
              l.segs.size(), double(l.blocked) / n, 1e9 * l.best_cpu / n, 1e9 * l.best_wall / n);
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
    std::vector<Loaded> loaded;
    for (const std::string& b : pv::splitCommaList(builds)) {
      if (b == "instanced")
        loaded.push_back(load(scene, pv::InstanceBuild::kInstanced, "instanced", passes));
      else if (b == "flat")
        loaded.push_back(load(scene, pv::InstanceBuild::kFlat, "flat", passes));
      else
        throw pv::Error({}, "--builds: unknown build '" + b + "'", "", "instanced or flat");
    }
    // Interleaved repetitions (A B A B ...), the best of each: a machine whose load changes
    // during the run then affects every build alike.
    for (int r = 0; r < reps; ++r)
      for (Loaded& l : loaded) traceOnce(l);
    for (const Loaded& l : loaded) print(l);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_scene_trace: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
