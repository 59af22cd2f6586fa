// bench_ecosys_ceiling: the oracle ceiling of proxy-based shadow rays per light on a scene, for
// the scene's per-prototype proxies or for cluster proxies (one outside proxy per terrain cell,
// cluster_proxies.h). Every segment is traced against proxy (with the self-shadowing rule) and
// original, each ray timed with the TSC on one thread, the order alternating between segments so
// that neither ray always runs on warm caches. Prints one Markdown row per light and for the
// light mix; --tsv appends the same rows for run_comparison.sh to gather.
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <optional>

#include "ceiling_table.h"
#include "cluster_proxies.h"
#include "estimate/cpu_ticks.h"
#include "light_segments.h"
#include "proxies/check/class_trust.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/scene_tracer.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace proxyvis::ecosys {
namespace {

struct Options {
  std::string scene, label, proxy_kind, tsv;
  std::string light_names = "sun,sky";
  double max_ray_us = 100;
  int passes = 16, spp = 16, tile = 16, width = 0, height = 0;
  double q_min = 0.05;
  uint64_t seed = 11;
  ClusterOptions cluster;
  bool clusters = false;
};

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double ticksPerNanosecond() {
  const Stopwatch watch;
  const uint64_t c0 = cpuTicks();
  while (watch.seconds() < 0.05) {
  }
  return double(cpuTicks() - c0) / (1e9 * watch.seconds());
}

// Light selection by power (area x mean radiance): the share of samples each light gets.
std::vector<double> powerWeights(const SceneDesc& desc) {
  std::vector<double> w;
  for (const AreaLightDesc& l : desc.lights) {
    double area = 0;
    for (const auto& t : l.triangles) area += 0.5 * double(length(cross(t[1] - t[0], t[2] - t[0])));
    w.push_back(area * (l.radiance.x + l.radiance.y + l.radiance.z) / 3);
  }
  return w;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out(1);
  for (char c : s) {
    if (c == ',')
      out.emplace_back();
    else
      out.back().push_back(c);
  }
  return out;
}

int run(const Options& opt) {
  SceneDesc desc = loadSceneDesc(opt.scene);
  if (opt.width > 0) desc.camera.width = opt.width;
  if (opt.height > 0) desc.camera.height = opt.height;
  RenderSceneOptions ro;
  ro.proxy_kind = opt.proxy_kind;
  ro.quiet = true;
  for (const ProxyTrust& t : establishProxyClasses(desc, ro))
    if (t.trust.status == ClassStatus::kDowngraded)
      std::fprintf(stderr, "bench_ecosys_ceiling: warning: %s\n", describeProxyTrust(t).c_str());
  const Stopwatch load_watch;
  auto scene = loadRenderScene(desc, ro);
  const double load_seconds = load_watch.seconds();
  const int w = desc.camera.width, h = desc.camera.height;
  const int lights = int(desc.lights.size());
  std::vector<std::string> names = split(opt.light_names);
  for (int l = int(names.size()); l < lights; ++l) names.push_back("light" + std::to_string(l));

  std::vector<std::vector<LightSegment>> passes;
  for (int p = 0; p < opt.passes; ++p) passes.push_back(lightSegments(*scene, opt.seed, p));

  ProxyClass cls = scene->proxyClass();
  uint64_t proxy_triangles = scene->proxyTriangles();
  std::optional<ClusterTracer> cluster;
  if (opt.clusters) {
    std::vector<Vec3f> focus;
    for (const LightSegment& s : passes[0]) focus.push_back(s.segment.org);
    cluster.emplace(*scene, opt.cluster, focus);
    const ClusterSummary& cs = cluster->summary();
    std::printf(
        "cluster proxies: %d cells of %.1f units, %d built (%s), %d failed, %llu triangles, "
        "%.1f s%s%s\n",
        cs.cells, double(opt.cluster.cell), cs.built, opt.cluster.method.c_str(), cs.failed,
        (unsigned long long)cs.proxy_triangles, cs.build_seconds,
        cs.first_failure.empty() ? "" : "; first failure: ", cs.first_failure.c_str());
    cls = ProxyClass::kOutside;  // hulls and wraps of outside inputs contain their instances
    proxy_triangles = cs.proxy_triangles;
    for (const auto& pass : passes)
      for (const LightSegment& s : pass) cluster->prepare(cluster->cellOf(s.object, s.segment.org));
  }

  const double tpn = ticksPerNanosecond();
  // All shading points, then those on placed meshes (the terrain) and on instances (plants).
  const uint64_t cap = uint64_t(opt.max_ray_us * 1e3 * tpn);
  CeilingStats stats(lights, w, h, opt.tile, cap);
  CeilingStats by_surface[2] = {CeilingStats(lights, w, h, opt.tile, cap),
                                CeilingStats(lights, w, h, opt.tile, cap)};
  const char* surface_names[2] = {"terrain", "plants"};
  // The same split again by pass parity, for the held-out ceiling: [surface: all, terrain,
  // plants][even, odd].
  std::vector<std::vector<CeilingStats>> halves(3);
  for (auto& h2 : halves)
    for (int f = 0; f < 2; ++f) h2.emplace_back(lights, w, h, opt.tile, cap);
  // Regions keyed by (light, surface, tile), as a learner that keeps terrain and plant points
  // apart would have them: channel 2 * light + surface, in full and by pass parity.
  CeilingStats split(2 * lights, w, h, opt.tile, cap);
  std::vector<CeilingStats> split_halves;
  for (int f = 0; f < 2; ++f) split_halves.emplace_back(2 * lights, w, h, opt.tile, cap);
  std::vector<double> split_count(size_t(2 * lights), 0.0);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  uint64_t k = 0;
  for (size_t pi = 0; pi < passes.size(); ++pi)
    for (const LightSegment& s : passes[pi]) {
      bool vp = false, v = false;
      uint64_t tp = 0, to = 0;
      const SceneTracer tracer(*scene, s.object);
      const uint32_t cell = cluster ? cluster->cellOf(s.object, s.segment.org) : 0;
      auto traceProxy = [&] {
        const uint64_t a = cpuTicks();
        vp = cluster ? cluster->proxyVisible(s.segment, cell) : tracer.proxyVisible(s.segment);
        tp = cpuTicks() - a;
      };
      auto traceOriginal = [&] {
        const uint64_t a = cpuTicks();
        v = tracer.originalVisible(s.segment);
        to = cpuTicks() - a;
      };
      if (k++ % 2)
        traceProxy(), traceOriginal();
      else
        traceOriginal(), traceProxy();
      stats.add(s.light, s.pixel, vp, v, tp, to);
      const int surface = scene->objects()[s.object].instance >= 0;
      by_surface[surface].add(s.light, s.pixel, vp, v, tp, to);
      halves[0][pi % 2].add(s.light, s.pixel, vp, v, tp, to);
      halves[1 + surface][pi % 2].add(s.light, s.pixel, vp, v, tp, to);
      const uint32_t channel = 2 * s.light + uint32_t(surface);
      split.add(channel, s.pixel, vp, v, tp, to);
      split_halves[pi % 2].add(channel, s.pixel, vp, v, tp, to);
      split_count[channel] += 1;
    }
  stats.finish();
  for (CeilingStats& b : by_surface) b.finish();
  for (auto& h2 : halves)
    for (CeilingStats& b : h2) b.finish();
  split.finish();
  for (CeilingStats& b : split_halves) b.finish();

  // c_s: what a light sample costs outside visibility (primary ray share, light sampling), from
  // an exact render on the same single thread.
  RenderSettings rs;
  rs.spp = opt.spp;
  rs.quiet = true;
  // CPU time of this thread (TBB is limited to it), so that waiting on a shared machine is not
  // counted; the render's own wall-clock split gives the shading part of it.
  const double cpu0 = threadCpuSeconds();
  const RenderResult exact = render(*scene, rs);
  const double cpu = threadCpuSeconds() - cpu0;
  const double c_s_ns =
      cpu * (exact.shading_seconds / exact.seconds) * 1e9 / (double(w) * h * opt.spp);
  std::vector<CeilingRow> rows =
      ceilingRows(stats, names, powerWeights(desc), cls, opt.q_min, c_s_ns, tpn);
  auto heldOutFor = [&](std::vector<CeilingRow>& out, std::vector<CeilingStats>& h2,
                        const std::vector<std::string>& row_names,
                        const std::vector<double>& weights) {
    const auto a = ceilingRows(h2[1], row_names, weights, cls, opt.q_min, c_s_ns, tpn, &h2[0]);
    const auto b = ceilingRows(h2[0], row_names, weights, cls, opt.q_min, c_s_ns, tpn, &h2[1]);
    for (size_t i = 0; i < out.size() && i < a.size() && i < b.size(); ++i)
      out[i].ceiling_heldout = 0.5 * (a[i].ceiling_shadow + b[i].ceiling_shadow);
  };
  auto heldOut = [&](std::vector<CeilingRow>& out, std::vector<CeilingStats>& h2) {
    heldOutFor(out, h2, names, powerWeights(desc));
  };
  heldOut(rows, halves[0]);
  {
    // The light mix with regions split by surface: each (light, surface) channel weighted by its
    // light's power share times the surface's share of that light's samples.
    const std::vector<double> power = powerWeights(desc);
    std::vector<std::string> split_names;
    std::vector<double> split_weights;
    for (int l = 0; l < lights; ++l)
      for (int b = 0; b < 2; ++b) {
        split_names.push_back(names[size_t(l)] + " on " + surface_names[b]);
        const double n_l = split_count[size_t(2 * l)] + split_count[size_t(2 * l + 1)];
        split_weights.push_back(n_l > 0 ? power[size_t(l)] * split_count[size_t(2 * l + b)] / n_l
                                        : 0.0);
      }
    std::vector<CeilingRow> by_channel =
        ceilingRows(split, split_names, split_weights, cls, opt.q_min, c_s_ns, tpn);
    heldOutFor(by_channel, split_halves, split_names, split_weights);
    if (by_channel.size() > 1) {
      by_channel.back().light = "mix, regions split by surface";
      rows.push_back(by_channel.back());
    }
  }
  for (int b = 0; b < 2; ++b) {
    std::vector<CeilingRow> more =
        ceilingRows(by_surface[b], names, powerWeights(desc), cls, opt.q_min, c_s_ns, tpn);
    heldOut(more, halves[1 + b]);
    for (CeilingRow& r : more) {
      r.light += std::string(" on ") + surface_names[b];
      rows.push_back(r);
    }
  }

  std::printf(
      "## %s: %s (%dx%d, %d passes, proxy class %s, %llu proxy triangles, load %.1f s, "
      "c_s %.0f ns)\n\n",
      opt.label.c_str(), opt.scene.c_str(), w, h, opt.passes, proxyClassName(cls),
      (unsigned long long)proxy_triangles, load_seconds, c_s_ns);
  std::printf(
      "| light | share | segments | P(V'=0) | P(MH') | P(HM') | mean V(1-V) | c_p 0/1 (ns) | "
      "c_o 0/1 (ns) | q=1 | ceiling rays | ceiling render | held-out rays | roulette regions |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::FILE* tsv = opt.tsv.empty() ? nullptr : std::fopen(opt.tsv.c_str(), "a");
  if (!opt.tsv.empty() && !tsv)
    throw WriteError(opt.tsv, "cannot open for appending", std::strerror(errno),
                     "check the folder");
  for (const CeilingRow& r : rows) {
    std::printf(
        "| %s | %.3f | %llu | %.4f | %.4f | %.4f | %.4f | %.0f / %.0f | %.0f / %.0f | %.3f | "
        "%.3f | %.3f | %.3f | %d of %d |\n",
        r.light.c_str(), r.weight, (unsigned long long)r.segments, r.p_blocked, r.p_mh, r.p_hm,
        r.var_exact, r.c_p[0], r.c_p[1], r.c_o[0], r.c_o[1], r.culling_shadow, r.ceiling_shadow,
        r.ceiling_render, r.ceiling_heldout, r.regions_roulette, r.regions);
    if (tsv)
      std::fprintf(
          tsv,
          "%s\t%s\t%s\t%llu\t%.3f\t%.4f\t%.4f\t%.4f\t%.4f\t%.1f\t%.1f\t%.1f\t%.1f\t%.3f\t%.3f\t%"
          ".3f\t%d\t%d\t%.0f\t%.3f\n",
          opt.label.c_str(), proxyClassName(cls), r.light.c_str(),
          (unsigned long long)proxy_triangles, r.weight, r.p_blocked, r.p_mh, r.p_hm, r.var_exact,
          r.c_p[0], r.c_p[1], r.c_o[0], r.c_o[1], r.culling_shadow, r.ceiling_shadow,
          r.ceiling_render, r.regions_roulette, r.regions, c_s_ns, r.ceiling_heldout);
  }
  if (tsv) std::fclose(tsv);
  std::printf("\n%llu of %llu samples had a ray slower than %.0f us (preempted): not timed.\n",
              (unsigned long long)stats.preempted(), (unsigned long long)k, opt.max_ray_us);
  std::printf(
      "\nq=1: roulette with q = 1 where errors are possible (culling for outside proxies), "
      "shadow rays only. Ceilings: oracle per (tile, light) region choosing exact or "
      "roulette(q*), efficiency vs exact; 'render' adds c_s to every sample; 'held-out' decides "
      "on even passes and scores on odd ones and the reverse (mean of the two). Variance per "
      "light sample, not radiance-weighted; single-thread TSC timings.\n\n");
  return 0;
}

}  // namespace
}  // namespace proxyvis::ecosys

int main(int argc, char** argv) {
  CLI::App app{
      "bench_ecosys_ceiling: per-light oracle ceiling of per-prototype or cluster proxies"};
  proxyvis::ecosys::Options o;
  app.add_option("scene", o.scene, "Scene with proxies")->required();
  app.add_option("--label", o.label, "Name of this variant in the table")->required();
  app.add_option("--proxy-kind", o.proxy_kind, "Which proxy of each mesh (default: the first)");
  app.add_option("--passes", o.passes, "Samples per pixel and light traced for the statistics")
      ->check(proxyvis::integerIn(1, 4096))
      ->capture_default_str();
  app.add_option("--spp", o.spp, "Samples per pixel of the exact render that measures c_s")
      ->check(proxyvis::integerIn(1, 4096))
      ->capture_default_str();
  app.add_option("--tile", o.tile, "Region size in pixels")
      ->check(proxyvis::integerIn(1, 4096))
      ->capture_default_str();
  app.add_option("--width", o.width, "Override the image width")
      ->check(proxyvis::integerIn(1, proxyvis::kMaxImageSide));
  app.add_option("--height", o.height, "Override the image height")
      ->check(proxyvis::integerIn(1, proxyvis::kMaxImageSide));
  app.add_option("--q-min", o.q_min, "Roulette floor")
      ->check(proxyvis::numberIn(1e-6, 1))
      ->capture_default_str();
  app.add_option("--light-names", o.light_names, "Names of the lights, comma-separated")
      ->capture_default_str();
  app.add_option("--max-ray-us", o.max_ray_us,
                 "A ray timed longer than this was preempted: its sample is not timed")
      ->check(proxyvis::positiveNumber())
      ->capture_default_str();
  app.add_option("--tsv", o.tsv, "Append the rows to this tab-separated file");
  app.add_option("--cluster-cell", o.cluster.cell,
                 "Cluster proxies: one per square cell of this side (scene units)")
      ->check(proxyvis::positiveNumber());
  app.add_option("--cluster-method", o.cluster.method, "hull or wrap")
      ->check(CLI::IsMember({"hull", "wrap"}))
      ->capture_default_str();
  app.add_option("--cluster-alpha", o.cluster.alpha, "wrap: alpha (scene units)")
      ->check(proxyvis::positiveNumber())
      ->capture_default_str();
  app.add_option("--cluster-offset", o.cluster.offset, "wrap: offset (scene units)")
      ->check(proxyvis::positiveNumber())
      ->capture_default_str();
  app.add_option("--cluster-margin", o.cluster.margin,
                 "Build cells within this distance of a shading point (scene units)")
      ->check(proxyvis::positiveNumber())
      ->capture_default_str();
  app.add_flag(
      "--cluster-fused", o.cluster.fused,
      "Cluster proxies: one scene per cell (terrain, other cells' proxies, own originals)");
  app.add_flag("!--cluster-from-originals", o.cluster.from_proxies,
               "Cluster proxies from the instances' originals, not their proxies");
  proxyvis::CommonOptions common;
  proxyvis::addCommonOptions(app, common);
  return proxyvis::runApp(app, argc, argv, common, [&] {
    o.clusters = app.count("--cluster-cell") > 0;
    return proxyvis::ecosys::run(o);
  });
}
