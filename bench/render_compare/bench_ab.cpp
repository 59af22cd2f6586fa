// A/B efficiency of two estimators (default: roulette against exact) at equal time, measured
// within one process so that both see the same machine: the scene is loaded once, a converged
// exact reference is rendered first, then the two estimators alternate, N times, each render
// given the same time budget and its own seed, or one seed per pair with --common-seed (the
// order within a pair alternates too, so a slow drift of the machine's load favours neither).
// Every render starts a fresh estimator, as render-compare does. Efficiency = 1 / (MSE x seconds)
// against the reference; the table gives the ratio B/A per pair and its mean, min, max and standard
// error (--common-seed gives both renders of a pair one seed, which cancels most of the noise the
// two share), with seconds of wall time (what equal time means) and with the process's CPU seconds
// over the render (on a shared, loaded machine the CPU share a render gets varies a lot, and the
// CPU ratio removes that).
// --spp N renders N samples per pixel instead of a time budget: at equal samples the ratio of
// CPU times isolates an estimator's per-sample overhead (where it traces the same rays).
//
// The reference's own noise adds the same amount to both MSEs and pulls the ratio towards 1; the
// output states that share (exact's 1-spp variance over the reference's spp, estimated from the
// A renders), so it can be kept small with --ref-seconds.
#include <fmt/core.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "metrics/image_error.h"
#include "proxies/check/class_trust.h"
#include "render/render_options.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"

namespace proxyvis {
namespace {

struct Options {
  std::string scene;
  std::string a = "exact", b = "roulette";
  double seconds = 1;
  int alternations = 10;
  double ref_seconds = 30;
  int spp = 0;  // > 0: equal samples instead of equal time
  // Both renders of a pair use the same seed (common random numbers): the light samples are keyed
  // on (seed, pixel, pass), so where B traces what A traces their errors cancel in the ratio.
  bool common_seed = false;
  bool show_pairs = true;
};

struct Run {
  int spp = 0;
  double seconds = 0, cpu_seconds = 0, mse = 0;
  RayCounts rays;
  uint64_t segments = 0;  // shadow segments estimated
  LearnedSummary learned;
};

// User + system CPU seconds of the whole process (every thread) so far.
double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

Run renderOnce(const RenderScene& scene, const RenderFlags& flags, EstimatorKind kind,
               const Options& o, uint64_t seed, const std::vector<float>& reference) {
  RenderSettings s;
  s.estimator = flags.estimatorSetup(kind);
  s.time_budget = o.spp > 0 ? 0 : o.seconds;
  s.spp = o.spp;
  s.seed = seed;
  s.quiet = true;
  const double cpu0 = processCpuSeconds();
  const RenderResult r = render(scene, s);
  const double cpu = processCpuSeconds() - cpu0;
  return {r.spp,  r.seconds,         cpu,      meanSquaredError(r.radiance.pixels, reference),
          r.rays, r.shadow_segments, r.learned};
}

double efficiencyOf(const Run& r, bool cpu) {
  const double t = cpu ? r.cpu_seconds : r.seconds;
  return r.mse > 0 && t > 0 ? 1 / (r.mse * t) : 0;
}

struct Summary {
  double mean = 0, min = 0, max = 0, se = 0;
};

Summary summarise(const std::vector<double>& x) {
  Summary s;
  const double n = double(x.size());
  for (double v : x) s.mean += v;
  s.mean /= n;
  double ss = 0;
  for (double v : x) ss += (v - s.mean) * (v - s.mean);
  s.se = n > 1 ? std::sqrt(ss / (n - 1) / n) : 0;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  s.min = *lo;
  s.max = *hi;
  return s;
}

int run(const Options& o, RenderFlags flags, uint64_t seed) {
  flags.resolve();
  SceneDesc desc = loadSceneDesc(o.scene);
  flags.applyTo(desc);
  const TrustedRenderScene loaded =
      loadTrustedRenderScene(desc, flags.sceneOptions(true), "bench_ab");
  const RenderScene& scene = *loaded.scene;
  const EstimatorKind a = parseEstimatorName(o.a), b = parseEstimatorName(o.b);

  // Warm-up (pages, caches, CPU clock), then the reference.
  RenderSettings warm;
  warm.time_budget = std::min(1.0, o.seconds);
  warm.spp = 0;
  warm.quiet = true;
  (void)render(scene, warm);
  RenderSettings ref;
  ref.time_budget = o.ref_seconds;
  ref.spp = 0;
  ref.seed = seed ^ 0x5eed5eedULL;
  ref.quiet = true;
  const RenderResult reference = render(scene, ref);

  const std::string budget =
      o.spp > 0 ? fmt::format("{} spp", o.spp) : fmt::format("{} s", o.seconds);
  fmt::print("## {}: {} vs {}, {} alternations of {} ({}x{}, proxy class {})\n\n", o.scene, o.b,
             o.a, o.alternations, budget, scene.camera().width(), scene.camera().height(),
             proxyClassName(scene.proxyClass()));
  if (o.show_pairs) {
    fmt::print(
        "| pair | {0} spp | {0} CPU s | {0} MSE | {1} spp | {1} CPU s | {1} MSE | {1} "
        "proxy, original rays / segment | {1} regions roulette | ratio (wall) | ratio (CPU) |\n",
        o.a, o.b);
    fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  }
  std::vector<double> wall, cpu;
  double var1_sum = 0, mse_a_sum = 0;  // A's per-sample variance (MSE x spp), A's MSE
  for (int i = 0; i < o.alternations; ++i) {
    const uint64_t seed_a = seed + 2 * uint64_t(i), seed_b = o.common_seed ? seed_a : seed_a + 1;
    const std::vector<float>& ref = reference.radiance.pixels;
    Run ra, rb;
    if (i % 2 == 0) {
      ra = renderOnce(scene, flags, a, o, seed_a, ref);
      rb = renderOnce(scene, flags, b, o, seed_b, ref);
    } else {
      rb = renderOnce(scene, flags, b, o, seed_b, ref);
      ra = renderOnce(scene, flags, a, o, seed_a, ref);
    }
    auto ratio = [&](bool by_cpu) {
      const double ea = efficiencyOf(ra, by_cpu);
      return ea > 0 ? efficiencyOf(rb, by_cpu) / ea : 0;
    };
    wall.push_back(ratio(false));
    cpu.push_back(ratio(true));
    var1_sum += ra.mse * ra.spp;
    mse_a_sum += ra.mse;
    const double segments = double(rb.segments);
    if (o.show_pairs)
      fmt::print(
          "| {} | {} | {:.2f} | {:.3e} | {} | {:.2f} | {:.3e} | {:.3f}, {:.3f} | {} of {} | {:.3f} "
          "| {:.3f} |\n",
          i + 1, ra.spp, ra.cpu_seconds, ra.mse, rb.spp, rb.cpu_seconds, rb.mse,
          double(rb.rays.proxy) / std::max(1.0, segments),
          double(rb.rays.original) / std::max(1.0, segments), rb.learned.regions_roulette,
          rb.learned.regions, wall.back(), cpu.back());
  }
  fmt::print("\n| scene | budget | pairs | efficiency {}/{} | mean | min | max | s.e. |\n", o.b,
             o.a);
  fmt::print("|---|---|---:|---|---:|---:|---:|---:|\n");
  for (const bool by_cpu : {false, true}) {
    const Summary x = summarise(by_cpu ? cpu : wall);
    fmt::print("| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", o.scene, budget,
               wall.size(), by_cpu ? "per CPU second" : "per wall second", x.mean, x.min, x.max,
               x.se);
  }
  const double n = double(wall.size());
  // The reference's variance (A's per-sample variance over its spp) as a share of A's MSE:
  // both MSEs contain it.
  const double ref_share = var1_sum / n / std::max(1, reference.spp) / (mse_a_sum / n);
  fmt::print(
      "\nReference: exact, {} spp in {:.1f} s; its own variance is about {:.1f} % of {}'s "
      "mean MSE (it pulls the ratios towards 1 by about that much).\n\n",
      reference.spp, reference.seconds, 100 * ref_share, o.a);
  return 0;
}

}  // namespace
}  // namespace proxyvis

int main(int argc, char** argv) {
  CLI::App app{"bench_ab: equal-time efficiency of two estimators, alternated in one process"};
  proxyvis::Options o;
  proxyvis::RenderFlags flags;
  app.add_option("scene", o.scene, "Scene with proxies")->required();
  app.add_option("--a", o.a, "Baseline estimator")->capture_default_str();
  app.add_option("--b", o.b, "Estimator compared with the baseline")->capture_default_str();
  app.add_option("--seconds", o.seconds, "Time budget of every render")
      ->check(proxyvis::numberIn(0.05, 600))
      ->capture_default_str();
  app.add_option("--alternations", o.alternations, "Pairs of renders (A, B)")
      ->check(proxyvis::integerIn(1, 1000))
      ->capture_default_str();
  app.add_option("--ref-seconds", o.ref_seconds, "Time budget of the exact reference")
      ->check(proxyvis::numberIn(0.1, 86400))
      ->capture_default_str();
  app.add_option("--spp", o.spp, "Equal samples per pixel instead of equal time (0 = time)")
      ->check(proxyvis::integerIn(0, 1 << 20))
      ->capture_default_str();
  app.add_flag("--common-seed", o.common_seed,
               "Both renders of a pair with the same seed (common random numbers: a far smaller "
               "spread where the MSE has heavy tails, e.g. a small bright light)");
  app.add_flag("!--no-pairs", o.show_pairs, "Print only the summary row");
  proxyvis::addRenderFlags(app, flags);
  proxyvis::CommonOptions common;
  proxyvis::addCommonOptions(app, common);
  return proxyvis::runApp(app, argc, argv, common,
                          [&] { return proxyvis::run(o, flags, common.seed); });
}
