// The ceiling of docs/design.md, costs point 3: how much more efficient than exact visibility any
// estimator built on these proxies can be, given what the scene measures.
//
// For P passes of one light sample per pixel (the renderer's own segments, passSegments()), every
// segment is traced against both the proxy (with the self-shadowing rule) and the original, each
// ray timed with the TSC. Per learning region (screen tile) that gives the roulette model of
// estimate/roulette.h: P(MH'), P(HM'), P(V'=0), per-class costs c_p|V', c_o|V', and the variance
// exact visibility leaves per pixel, mean_p V_p(1-V_p) (from the P passes, bias-corrected). An
// oracle that knows these exactly picks per region exact or roulette with its optimal q; the
// ceiling is (Var x cost) of exact over that of the oracle, for shadow rays alone and for the
// whole render (primary rays and shading measured by render() at --spp, which the proxies cannot
// speed up). Simplification, stated in the output: visibility variance is not weighted by each
// sample's radiance contribution (that weight is the same for every estimator at one point).
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "estimate/cpu_ticks.h"
#include "estimate/roulette.h"
#include "proxies/check/class_trust.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/scene_tracer.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"
#include "util/stopwatch.h"

namespace proxyvis {
namespace {

struct RegionStats {
  uint64_t n[2][2] = {{0, 0}, {0, 0}};  // [V'][V]
  double ticks_p[2] = {0, 0}, ticks_o[2] = {0, 0};
  double var_sum = 0;  // sum over samples of the pixel's V_p(1-V_p)
  uint64_t samples() const { return n[0][0] + n[0][1] + n[1][0] + n[1][1]; }
};

double ticksPerNanosecond() {
  const Stopwatch watch;
  uint64_t c0 = cpuTicks();
  while (watch.seconds() < 0.05) {
  }
  const double ns = 1e9 * watch.seconds();
  return double(cpuTicks() - c0) / ns;
}

RouletteModel modelOf(const RegionStats& r, const ClassCosts& global) {
  RouletteModel m;
  double n = double(r.samples());
  m.p_mh = r.n[0][1] / n;
  m.p_hm = r.n[1][0] / n;
  m.p_blocked = (r.n[0][0] + r.n[0][1]) / n;
  m.var_exact = r.var_sum / n;
  for (int i = 0; i < 2; ++i) {
    double ni = double(r.n[i][0] + r.n[i][1]);
    // A class seen in few samples borrows the scene-wide cost (its weight is small anyway).
    m.costs.proxy[i] = ni >= 16 ? r.ticks_p[i] / ni : global.proxy[i];
    m.costs.original[i] = ni >= 16 ? r.ticks_o[i] / ni : global.original[i];
  }
  return m;
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
  const int w = desc.camera.width, h = desc.camera.height;
  const int tiles_x = (w + tile - 1) / tile, tiles_y = (h + tile - 1) / tile;
  const ProxyClass cls = scene->proxyClass();

  RenderSettings settings;
  settings.spp = 1;
  settings.seed = 11;
  std::vector<std::vector<uint8_t>> v_of_pass;  // [pass][segment] V
  std::vector<std::vector<uint32_t>> pixel_of_pass;
  std::vector<RegionStats> regions(size_t(tiles_x) * tiles_y);
  std::vector<double> v_sum(size_t(w) * h, 0.0);
  std::vector<uint32_t> v_n(size_t(w) * h, 0);
  for (int pass = 0; pass < passes; ++pass) {
    PassSegments ps = passSegments(*scene, settings, pass);
    std::vector<uint8_t> vs(ps.segments.size());
    for (size_t i = 0; i < ps.segments.size(); ++i) {
      SceneTracer tracer(*scene, ps.objects[i]);
      uint64_t a = cpuTicks();
      bool vp = tracer.proxyVisible(ps.segments[i]);
      uint64_t b = cpuTicks();
      bool v = tracer.originalVisible(ps.segments[i]);
      uint64_t c = cpuTicks();
      uint32_t px = ps.pixels[i];
      RegionStats& r = regions[size_t((px / w) / tile) * tiles_x + (px % w) / tile];
      r.n[vp][v]++;
      r.ticks_p[vp] += double(b - a);
      r.ticks_o[vp] += double(c - b);
      v_sum[px] += v;
      v_n[px]++;
      vs[i] = v;
    }
    v_of_pass.push_back(std::move(vs));
    pixel_of_pass.push_back(std::move(ps.pixels));
  }
  // Per-pixel V_p(1-V_p), unbiased from n samples: n/(n-1) m(1-m); credited to each sample.
  for (size_t p = 0; p < pixel_of_pass.size(); ++p)
    for (uint32_t px : pixel_of_pass[p]) {
      double n = v_n[px], m = v_sum[px] / n;
      double var = n > 1 ? n / (n - 1) * m * (1 - m) : 0;
      regions[size_t((px / w) / tile) * tiles_x + (px % w) / tile].var_sum += var;
    }

  RegionStats all;
  for (const RegionStats& r : regions) {
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) all.n[i][j] += r.n[i][j];
    for (int i = 0; i < 2; ++i) all.ticks_p[i] += r.ticks_p[i], all.ticks_o[i] += r.ticks_o[i];
    all.var_sum += r.var_sum;
  }
  if (all.samples() == 0) {
    std::printf("no shadow segments (nothing lit in view)\n");
    return 0;
  }
  ClassCosts global;
  for (int i = 0; i < 2; ++i) {
    double ni = std::max<double>(1, all.n[i][0] + all.n[i][1]);
    global.proxy[i] = all.ticks_p[i] / ni;
    global.original[i] = all.ticks_o[i] / ni;
  }
  // Oracle: per region, the cheaper of exact and optimal roulette in Var x cost; totals are
  // sample-weighted sums (the MSE and the time of a render add over regions).
  double var_exact = 0, cost_exact = 0, var_oracle = 0, cost_oracle = 0;
  double var_single = 0, cost_single = 0;  // one roulette q for the whole scene, no fallback
  RouletteModel gm = modelOf(all, global);
  RouletteQ gq = optimalRouletteQ(gm, cls, q_min);
  int regions_roulette = 0, regions_used = 0;
  for (const RegionStats& r : regions) {
    double n = double(r.samples());
    if (n == 0) continue;
    ++regions_used;
    RouletteModel m = modelOf(r, global);
    RouletteQ q = optimalRouletteQ(m, cls, q_min);
    double ve = m.var_exact, ce = exactCost(m);
    double vr = rouletteVariance(m, q), cr = rouletteCost(m, q);
    var_exact += n * ve, cost_exact += n * ce;
    bool use = vr * cr < ve * ce;
    regions_roulette += use;
    var_oracle += n * (use ? vr : ve), cost_oracle += n * (use ? cr : ce);
    var_single += n * rouletteVariance(m, gq), cost_single += n * rouletteCost(m, gq);
  }

  // Shading time (primary rays, light sampling) at --spp, which no visibility estimator changes.
  RenderSettings rs;
  rs.spp = spp;
  rs.quiet = true;
  RenderResult exact = render(*scene, rs);
  const double t_shade = exact.shading_seconds, t_vis = exact.seconds - exact.shading_seconds;
  auto whole = [&](double var, double cost) {
    double t = t_shade + t_vis * cost / cost_exact;
    return (var_exact * (t_shade + t_vis)) / (var * t);
  };
  const double tpn = ticksPerNanosecond();
  const double n = double(all.samples());
  std::printf("## %s (%dx%d, %d passes, %llu segments, proxy class %s)\n\n", scene_file.c_str(), w,
              h, passes, (unsigned long long)all.samples(), proxyClassName(cls));
  std::printf("| quantity | value |\n|---|---:|\n");
  std::printf("| P(V'=0) | %.4f |\n| P(MH') | %.4f |\n| P(HM') | %.4f |\n", gm.p_blocked,
              all.n[0][1] / n, all.n[1][0] / n);
  std::printf("| mean V_p(1-V_p) | %.4f |\n", gm.var_exact);
  std::printf("| c_p given V'=0 / V'=1 (ns) | %.1f / %.1f |\n", global.proxy[0] / tpn,
              global.proxy[1] / tpn);
  std::printf("| c_o given V'=0 / V'=1 (ns) | %.1f / %.1f |\n", global.original[0] / tpn,
              global.original[1] / tpn);
  std::printf("| shading / visibility time at %d spp (s) | %.3f / %.3f |\n", spp, t_shade, t_vis);
  std::printf("| regions using roulette (oracle) | %d of %d |\n\n", regions_roulette, regions_used);
  std::printf("| ceiling (efficiency vs exact) | shadow rays only | whole render at %d spp |\n",
              spp);
  std::printf("|---|---:|---:|\n");
  std::printf("| oracle: per tile exact or roulette(q*) | %.3f | %.3f |\n",
              (var_exact * cost_exact) / (var_oracle * cost_oracle),
              whole(var_oracle, cost_oracle));
  std::printf("| one roulette q for the scene (q0=%.3f, q1=%.3f) | %.3f | %.3f |\n", gq.q0, gq.q1,
              (var_exact * cost_exact) / (var_single * cost_single),
              whole(var_single, cost_single));
  std::printf(
      "\nVariance per light sample, not weighted by radiance; costs are single-ray TSC timings "
      "(1 thread), c_o measured after the proxy ray (warm caches).\n\n");
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
      ->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel for the whole-render ceiling")
      ->capture_default_str();
  app.add_option("--width", width, "Override the image width");
  app.add_option("--height", height, "Override the image height");
  app.add_option("--tile", tile, "Region size in pixels")->capture_default_str();
  app.add_option("--q-min", q_min, "Roulette floor")->capture_default_str();
  app.add_option("--proxy-kind", proxy_kind, "Which proxy of each mesh");
  proxyvis::CommonOptions common;
  proxyvis::addCommonOptions(app, common);
  return proxyvis::runApp(app, argc, argv, common, [&] {
    return proxyvis::run(scene, passes, spp, width, height, tile, q_min, proxy_kind);
  });
}
