// Memory and ray cost of an instanced scene as its prototypes and instances grow, for the
// film-scale page (docs/film_scale.md). Each case is one child process (its own peak RSS):
// the scene with its instanced prototypes listed K times and its instance list copied N times onto
// tiles around the original (instance_variants.h), loaded with instanced BVHs. Per case it prints
// the peak RSS, Embree's peak and retained bytes (TraceDevice), the load time, and on one thread
// the CPU ns per exact shadow ray (the renderer's segments) and a render's cost per pixel and per
// light sample; then fits bytes = a * prototype triangles + b * instances + c.
//
//   build/bin/bench_instancing out/ecosys/proxies/scene.json [--no-proxies]
//       [--cases 1x1,1x10,1x30,1x100,4x1,4x10,16x1]
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../proxy_gen/child_process.h"
#include "instance_variants.h"
#include "linear_fit.h"
#include "mesh/io/mesh_io.h"
#include "render/render_options.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace pv = proxyvis;
using nlohmann::json;

namespace {

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// A line "Key:   123 kB" of /proc/self/status, in bytes (0 if absent).
double procStatusBytes(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return 1024.0 * std::stod(line.substr(key.size() + 1));
  return 0;
}

pv::SceneDesc variant(const std::string& scene_file, int prototype_copies, int copies) {
  return pv::bench::withInstanceCopies(
      pv::bench::withPrototypeCopies(pv::loadSceneDesc(scene_file), prototype_copies), copies);
}

// One case, in this process: prints one JSON object.
int runCase(const std::string& scene_file, int prototype_copies, int copies, bool proxies,
            int spp) {
  const double rss_start = procStatusBytes("VmRSS");
  pv::SceneDesc desc = variant(scene_file, prototype_copies, copies);
  const size_t instances = desc.instances.size();
  pv::RenderSceneOptions options;
  options.instance_build = pv::InstanceBuild::kInstanced;
  options.use_proxies = proxies;
  options.quiet = true;
  const pv::Stopwatch load_watch;
  std::unique_ptr<pv::RenderScene> scene = pv::loadRenderScene(desc, options);
  const double load_seconds = load_watch.seconds();
  desc = {};  // our copy of the instance list; the scene keeps its own
  json out = {{"instances", instances},
              {"objects", scene->objects().size()},
              {"load_seconds", load_seconds},
              {"rss_start", rss_start},
              {"rss_after_load", procStatusBytes("VmRSS")},
              {"rss_peak_load", procStatusBytes("VmHWM")},
              {"embree_peak", scene->device().peakBytes()},
              {"embree_in_use", scene->device().bytesInUse()},
              {"original_triangles", scene->originalTriangles()},
              {"proxy_triangles", scene->proxyTriangles()}};

  // Per core: one thread from here on.
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  pv::RenderSettings settings;
  settings.quiet = true;
  std::vector<pv::Segment> segs;
  for (int p = 0; p < 4; ++p) {
    pv::PassSegments ps = pv::passSegments(*scene, settings, p);
    segs.insert(segs.end(), ps.segments.begin(), ps.segments.end());
  }
  std::vector<uint8_t> blocked(segs.size());
  double best = 1e30;
  for (int r = 0; r < 3; ++r) {
    const double c0 = cpuSeconds();
    scene->originals().occluded(segs, blocked);
    best = std::min(best, cpuSeconds() - c0);
  }
  uint64_t n_blocked = 0;
  for (uint8_t b : blocked) n_blocked += b;
  // Render cost by CPU time (one thread: not inflated by other jobs the way wall time is): a
  // 1-spp and an spp render; their difference is the light samples, the rest the primary rays.
  settings.spp = 1;
  const pv::RenderResult r1 = pv::render(*scene, settings);
  settings.spp = spp;
  const pv::RenderResult r = pv::render(*scene, settings);
  const double pixels = double(scene->camera().width()) * double(scene->camera().height());
  const double sample_cpu = (r.cpu_seconds - r1.cpu_seconds) / (pixels * double(r.spp - r1.spp));
  out["segments"] = segs.size();
  out["blocked"] = double(n_blocked) / double(std::max<size_t>(segs.size(), 1));
  out["shadow_ns_cpu"] = 1e9 * best / double(std::max<size_t>(segs.size(), 1));
  out["pixels"] = pixels;
  out["spp"] = r.spp;
  out["primary_ns_per_pixel"] = 1e9 * (r1.cpu_seconds - sample_cpu * pixels) / pixels;
  out["sample_ns"] = 1e9 * sample_cpu;
  out["render_cpu_seconds"] = r.cpu_seconds;
  out["render_seconds"] = r.seconds;
  out["rss_peak"] = procStatusBytes("VmHWM");
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

struct Case {
  int prototype_copies = 1, copies = 1;
};

std::vector<Case> parseCases(const std::string& list) {
  std::vector<Case> cases;
  for (const std::string& item : pv::splitCommaList(list)) {
    Case c;
    if (std::sscanf(item.c_str(), "%dx%d", &c.prototype_copies, &c.copies) != 2 ||
        c.prototype_copies < 1 || c.prototype_copies > 1000 || c.copies < 1 || c.copies > 10000)
      throw pv::Error({}, "--cases: '" + item + "' is not KxN", "",
                      "prototype copies x instance copies, each from 1, e.g. 4x10");
    cases.push_back(c);
  }
  return cases;
}

// Triangles of a case's prototypes: every mesh entry once (placed meshes and each copy of an
// instanced one), and of the proxies the renderer uses (the first listed, as RenderSceneOptions).
struct PrototypeTriangles {
  uint64_t originals = 0, proxies = 0;
};
PrototypeTriangles prototypeTriangles(const pv::SceneDesc& desc) {
  PrototypeTriangles t;
  for (const pv::SceneMeshDesc& m : desc.meshes) {
    t.originals += pv::loadMesh(m.file).numTriangles();
    if (!m.proxies.empty()) t.proxies += pv::loadMesh(m.proxies.front().file).numTriangles();
  }
  return t;
}

double mib(double bytes) {
  return bytes / (1024.0 * 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Memory and ray cost of an instanced scene as prototypes and instances grow");
  std::string scene, cases_text = "1x1,1x10,1x30,1x100,4x1,4x10,16x1";
  bool no_proxies = false;
  int spp = 16, child_case = -1, child_copies = 1;
  app.add_option("scene", scene, "scene file with instances (and proxies)")->required();
  app.add_option("--cases", cases_text,
                 "comma-separated KxN: prototypes listed K times, instances N times");
  app.add_flag("--no-proxies", no_proxies, "load without proxies (originals only)");
  app.add_option("--spp", spp, "light samples per pixel of the timed render")
      ->check(pv::integerIn(2, 4096));
  // Internal: run one case in this process (the parent starts one child per case).
  app.add_option("--child", child_case, "")->group("");
  app.add_option("--child-copies", child_copies, "")->group("");
  CLI11_PARSE(app, argc, argv);
  try {
    if (child_case > 0) return runCase(scene, child_case, child_copies, !no_proxies, spp);
    std::printf(
        "scene %s, instanced BVHs, %s; rays and exact renders (1 and %d spp) on 1 thread, ns of "
        "CPU time; bytes: peak RSS of the child (process start included), Embree's peak and "
        "retained bytes; load s: wall, all threads\n\n",
        scene.c_str(), no_proxies ? "no proxies" : "with proxies", spp);
    std::printf(
        "| instanced prototypes | prototype tris (M) | proxy tris (k) | instances | instanced tris "
        "(M) | "
        "load s | peak RSS MiB | RSS after load MiB | Embree peak MiB | Embree kept MiB | "
        "shadow ns/ray | Mrays/s/core | primary ns/px | ns/sample | blocked |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::vector<double> proto_tris, instances, rss, embree, load;
    for (const Case& c : parseCases(cases_text)) {
      const pv::SceneDesc desc = variant(scene, c.prototype_copies, 1);
      const int prototypes = pv::bench::instancedMeshCount(desc);
      PrototypeTriangles t = prototypeTriangles(desc);
      if (no_proxies) t.proxies = 0;
      // This very binary, in child mode.
      std::vector<std::string> args = {std::filesystem::read_symlink("/proc/self/exe").string(),
                                       scene,
                                       "--spp",
                                       std::to_string(spp),
                                       "--child",
                                       std::to_string(c.prototype_copies),
                                       "--child-copies",
                                       std::to_string(c.copies)};
      if (no_proxies) args.push_back("--no-proxies");
      const pv::bench::ChildResult r = pv::bench::runChild(args, 3600);
      if (r.exit_code != 0) {
        std::printf("| %dx%d | failed: exit %d, signal %d%s |\n", c.prototype_copies, c.copies,
                    r.exit_code, r.signal, r.timed_out ? ", timed out" : "");
        continue;
      }
      const json j = json::parse(r.output);
      const double peak = double(r.peak_rss_kb) * 1024.0;
      const double n_inst = j["instances"].get<double>();
      std::printf(
          "| %d | %.2f | %.1f | %.0f | %.1f | %.2f | %.0f | %.0f | %.0f | %.0f | %.0f | %.2f | "
          "%.0f | %.0f | %.2f |\n",
          prototypes, double(t.originals) / 1e6, double(t.proxies) / 1e3, n_inst,
          j["original_triangles"].get<double>() / 1e6, j["load_seconds"].get<double>(), mib(peak),
          mib(j["rss_after_load"].get<double>()), mib(j["embree_peak"].get<double>()),
          mib(j["embree_in_use"].get<double>()), j["shadow_ns_cpu"].get<double>(),
          1e3 / j["shadow_ns_cpu"].get<double>(), j["primary_ns_per_pixel"].get<double>(),
          j["sample_ns"].get<double>(), j["blocked"].get<double>());
      std::fflush(stdout);
      proto_tris.push_back(double(t.originals));
      instances.push_back(n_inst);
      rss.push_back(peak);
      embree.push_back(j["embree_peak"].get<double>());
      load.push_back(j["load_seconds"].get<double>());
    }
    const auto print_fit = [&](const char* what, const std::vector<double>& y, bool seconds) {
      const auto fit = pv::bench::fitLinear2(proto_tris, instances, y);
      if (!fit) {
        std::printf("\n%s: the cases do not determine the fit (vary K and N)\n", what);
        return;
      }
      if (seconds)
        std::printf("\n%s = %.2f us x prototype triangle + %.2f us x instance + %.2f s", what,
                    1e6 * fit->a, 1e6 * fit->b, fit->c);
      else
        std::printf("\n%s = %.1f B x prototype triangle + %.0f B x instance + %.1f MiB", what,
                    fit->a, fit->b, mib(fit->c));
      std::printf(" (max residual %.1f %%)\n", 100 * fit->max_relative_residual);
    };
    print_fit("peak RSS", rss, false);
    print_fit("Embree peak", embree, false);
    print_fit("load (wall)", load, true);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_instancing: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
