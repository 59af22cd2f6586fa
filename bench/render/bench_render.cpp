// bench_render: where a render's time goes, per scene (docs/design.md, costs point 4), and whether
// the renderer's shadow rays cost what Embree costs (target: within 10 % of a bare loop).
//   primary ns/px    primary ray + shading-point setup, per pixel
//   sampling ns/smp  light sampling (segment + weight), per light sample
//   shadow ns/seg    the visibility phase with an exact estimator (one rtcOccluded1 per segment
//                    through SceneTracer + estimator call + accumulation), per segment
//   bare ns/seg      rtcOccluded1 over the same segments in a TBB loop, no renderer around it
//   no-trace ns/seg  the visibility phase with an estimator that traces nothing (overhead)
//   proxy ns/seg     the visibility phase tracing only V' (proxies + the self-shadowing rule)
//   c_p/c_o          proxy ns/seg over shadow ns/seg: what a proxy ray costs in this renderer
// Usage: bench_render [--spp N] [--repeats R] [SCENE.json ...] (default: dragon-plane, foliage)
#include <embree3/rtcore.h>
#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/scene_tracer.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace proxyvis {
namespace {

// Exact visibility with nothing else: the renderer's overhead over Embree is what is measured.
class BareExact final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out, RayCounts& c) override {
    for (size_t i = 0; i < q.segments.size(); ++i)
      out[i] = q.tracer->originalVisible(q.segments[i]) ? 1.0 : 0.0;
    c.original += q.segments.size();
  }
};

// V' only, through the renderer's SceneTracer (self-shadowing rule included).
class ProxyOnly final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out, RayCounts& c) override {
    for (size_t i = 0; i < q.segments.size(); ++i)
      out[i] = q.tracer->proxyVisible(q.segments[i]) ? 1.0 : 0.0;
    c.proxy += q.segments.size();
  }
};

// Traces nothing: the visibility phase's own cost (query, estimator call, accumulation, passes).
class NoTrace final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out, RayCounts&) override {
    for (size_t i = 0; i < q.segments.size(); ++i) out[i] = 1.0;
  }
};

double bareLoopSeconds(const TraceScene& scene, const std::vector<Segment>& segs, uint64_t& hits) {
  RTCScene handle = scene.handle();
  std::atomic<uint64_t> occluded{0};
  const Stopwatch watch;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, segs.size(), 256), [&](const auto& r) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    uint64_t n = 0;
    for (size_t i = r.begin(); i != r.end(); ++i) {
      const Segment& s = segs[i];
      RTCRay ray;
      ray.org_x = s.org.x, ray.org_y = s.org.y, ray.org_z = s.org.z;
      ray.dir_x = s.dir.x, ray.dir_y = s.dir.y, ray.dir_z = s.dir.z;
      ray.tnear = s.tnear, ray.tfar = s.tfar, ray.mask = ~0u, ray.flags = 0, ray.time = 0;
      rtcOccluded1(handle, &ctx, &ray);
      n += ray.tfar < 0;
    }
    occluded += n;
  });
  hits = occluded;
  return watch.seconds();
}

// Single-threaded ns per segment of V (originals) and V' (SceneTracer: proxies + self rule) for
// the segments of one group of shading points, split by the proxy's answer.
struct GroupCosts {
  uint64_t n = 0, blocked = 0;
  double v_ns[2] = {0, 0}, vp_ns[2] = {0, 0};  // sums by V'
};

GroupCosts groupCosts(const RenderScene& scene, const PassSegments& ps, bool self) {
  GroupCosts g;
  using Clock = std::chrono::steady_clock;
  for (size_t i = 0; i < ps.segments.size(); ++i) {
    const RenderObject& o = scene.objects()[ps.objects[i]];
    if ((o.proxy >= 0) != self) continue;
    const SceneTracer tracer(scene, ps.objects[i]);
    const auto t0 = Clock::now();
    const bool vp = tracer.proxyVisible(ps.segments[i]);
    const auto t1 = Clock::now();
    const bool v = tracer.originalVisible(ps.segments[i]);
    const auto t2 = Clock::now();
    (void)v;
    ++g.n;
    g.blocked += !vp;
    g.vp_ns[vp] += std::chrono::duration<double, std::nano>(t1 - t0).count();
    g.v_ns[vp] += std::chrono::duration<double, std::nano>(t2 - t1).count();
  }
  return g;
}

void printGroupTable(const std::string& name, const RenderScene& scene, const PassSegments& ps) {
  for (bool self : {false, true}) {
    const GroupCosts g = groupCosts(scene, ps, self);
    if (g.n == 0) continue;
    const double nb = double(g.blocked), nv = double(g.n - g.blocked);
    auto per = [](double sum, double n) { return n > 0 ? sum / n : 0.0; };
    const double cp = (g.vp_ns[0] + g.vp_ns[1]) / double(g.n);
    const double co = (g.v_ns[0] + g.v_ns[1]) / double(g.n);
    fmt::print(
        "| {} | {} | {} | {:.3f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.2f} "
        "|\n",
        name, self ? "own proxy (self rule)" : "no own proxy", g.n, nb / double(g.n),
        per(g.vp_ns[0], nb), per(g.vp_ns[1], nv), per(g.v_ns[0], nb), per(g.v_ns[1], nv), cp, co,
        cp / co);
  }
}

// The file's stem, or its folder's for proxy-gen's DIR/proxies/scene.json.
std::string sceneName(const std::string& path) {
  const std::filesystem::path p(path);
  if (p.stem() == "scene" && p.parent_path().has_parent_path())
    return p.parent_path().parent_path().filename().string();
  return p.stem().string();
}

int run(int argc, char** argv) {
  int spp = 16, repeats = 3;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--spp") && i + 1 < argc)
      spp = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc)
      repeats = std::stoi(argv[++i]);
    else
      scenes.push_back(argv[i]);
  }
  if (scenes.empty())
    scenes = {std::string(PROXYVIS_SCENES_DIR) + "/dragon-plane.json",
              std::string(PROXYVIS_SCENES_DIR) + "/foliage.json"};
  fmt::print(
      "| scene | pixels | spp | triangles | load s | primary ns/px | sampling ns/smp | "
      "shadow ns/seg | bare ns/seg | renderer/bare | no-trace ns/seg | proxy ns/seg | c_p/c_o | "
      "visible | total s |\n");
  fmt::print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : scenes) {
    const Stopwatch loading;
    const auto scene = loadRenderScene(path, {});
    const double load = loading.seconds();
    RenderSettings settings;
    settings.spp = spp;
    settings.quiet = true;
    BareExact exact;
    render(*scene, settings, exact);  // warm-up (page faults, BVH in cache)
    double best_primary = 1e30, best_sampling = 1e30, best_shadow = 1e30, best_bare = 1e30,
           best_loop = 1e30, best_proxy = 1e30, total = 0;
    NoTrace no_trace;
    ProxyOnly proxy_only;
    uint64_t segments = 0, pixels = 0, samples = 0, occluded = 0;
    std::vector<Segment> all;
    for (int p = 0; p < spp; ++p) {
      PassSegments ps = passSegments(*scene, settings, p);
      all.insert(all.end(), ps.segments.begin(), ps.segments.end());
    }
    for (int r = 0; r < repeats; ++r) {
      const RenderResult res = render(*scene, settings, exact);
      pixels = res.primary_rays;
      samples = pixels * uint64_t(res.spp);
      segments = res.shadow_segments;
      best_primary = std::min(best_primary, res.primary_seconds);
      best_sampling = std::min(best_sampling, res.shading_seconds - res.primary_seconds);
      best_shadow = std::min(best_shadow, res.visibility_seconds);
      total = res.seconds;
      best_bare = std::min(best_bare, bareLoopSeconds(scene->originals(), all, occluded));
      best_loop = std::min(best_loop, render(*scene, settings, no_trace).visibility_seconds);
      best_proxy = std::min(best_proxy, render(*scene, settings, proxy_only).visibility_seconds);
    }
    PV_CHECK(all.size() == segments);  // the same segments as the render
    const double shadow_ns = 1e9 * best_shadow / double(segments);
    const double bare_ns = 1e9 * best_bare / double(all.size());
    fmt::print(
        "| {} | {} | {} | {} | {:.2f} | {:.0f} | {:.1f} | {:.1f} | {:.1f} | {:.2f} | {:.1f} | "
        "{:.1f} | {:.2f} | {:.2f} | {:.3f} |\n",
        sceneName(path), pixels, spp, scene->originalTriangles(), load,
        1e9 * best_primary / double(pixels), 1e9 * best_sampling / double(samples), shadow_ns,
        bare_ns, shadow_ns / bare_ns, 1e9 * best_loop / double(segments),
        1e9 * best_proxy / double(segments), best_proxy / best_shadow,
        1.0 - double(occluded) / double(all.size()), total);
  }
  // Where a proxy ray costs less than an original one, per group of shading points (one thread,
  // pass 0's segments): the c_p/c_o the roulette estimator can hope for.
  fmt::print(
      "\n| scene | shading points | segments | P(V'=0) | c_p V'=0 | c_p V'=1 | c_o V'=0 | c_o V'=1 "
      "| "
      "c_p | c_o | c_p/c_o |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : scenes) {
    RenderSceneOptions quiet;
    quiet.quiet = true;
    const auto scene = loadRenderScene(path, quiet);
    RenderSettings settings;
    settings.spp = 1;
    settings.quiet = true;
    PassSegments ps = passSegments(*scene, settings, 0);
    for (int p = 1; p < 4; ++p) {
      PassSegments more = passSegments(*scene, settings, p);
      ps.segments.insert(ps.segments.end(), more.segments.begin(), more.segments.end());
      ps.objects.insert(ps.objects.end(), more.objects.begin(), more.objects.end());
    }
    groupCosts(*scene, ps, false);  // warm-up
    printGroupTable(sceneName(path), *scene, ps);
  }
  return 0;
}

}  // namespace
}  // namespace proxyvis

int main(int argc, char** argv) {
  try {
    return proxyvis::run(argc, argv);
  } catch (const proxyvis::Error& e) {
    fmt::print(stderr, "bench_render: error: {}\n", e.what());
    return 2;
  }
}
