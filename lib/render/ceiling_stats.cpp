#include "render/ceiling_stats.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <ctime>

#include "estimate/cpu_ticks.h"
#include "render/internal/integrator.h"
#include "render/render_scene.h"
#include "render/scene_tracer.h"
#include "util/stopwatch.h"

namespace proxyvis {

using namespace detail;

namespace {

// One light sample of one pixel in one pass. weight 0: no shadow segment.
struct SampleRecord {
  Vec3f weight{0, 0, 0};
  uint32_t light = 0;
  bool segment = false;
  bool visible = false;
};

// A ray timed longer than this was preempted (a time slice is milliseconds; the dearest rays of a
// 12 M-triangle scene take microseconds, and the tick counter runs at a few GHz): it is traced
// and timed again, up to kRetimes times, and the shortest time is kept. On a shared, loaded
// machine a capped time would still add a slice's worth to one ray in a few thousand.
constexpr uint64_t kPreemptedTicks = 250'000;
constexpr int kRetimes = 4;

// f^2 of a sample: the mean of its squared RGB channels (the MSE averages over channels).
double meanSquare(const Vec3d& v) {
  return (v.x * v.x + v.y * v.y + v.z * v.z) / 3;
}

// Times one ray; the result is written to `visible`.
template <class F>
uint64_t timed(F&& trace, bool& visible) {
  uint64_t best = ~uint64_t(0);
  for (int attempt = 0; attempt <= kRetimes; ++attempt) {
    const uint64_t a = cpuTicks();
    visible = trace();
    best = std::min<uint64_t>(best, cpuTicks() - a);
    if (best < kPreemptedTicks) break;
  }
  return best;
}

// The renderer's own learning region of a sample.
CeilingRegionStats& regionOf(CeilingMeasurement& out, const RenderScene& scene, int tile,
                             uint32_t light, uint32_t object) {
  return out.regions[learningRegion(scene, object, uint32_t(tile), light)];
}

// Each sample's share of its pixel's variance, unbiased over the n passes: n/(n-1) times its
// squared deviation from the pixel's mean (f V per RGB channel; V alone for the unweighted one).
void addPixelVariances(const RenderScene& scene, const Tiling& tiling,
                       const std::vector<ShadingPoint>& points,
                       const std::vector<SampleRecord>& records, int passes,
                       CeilingMeasurement& out) {
  const size_t num_pixels = points.size();
  tbb::parallel_for(0, tiling.count(), [&](int t) {
    tiling.forEachPixel(t, [&](int, int, uint32_t pixel) {
      if (!points[pixel].valid) return;
      Vec3d mean_fv{0, 0, 0};
      double v_sum = 0, v_n = 0;
      for (int p = 0; p < passes; ++p) {
        const SampleRecord& r = records[size_t(p) * num_pixels + pixel];
        if (r.visible) mean_fv += Vec3d(r.weight);
        if (r.segment) v_sum += r.visible, v_n += 1;
      }
      mean_fv *= 1.0 / passes;
      const double n = passes, correction = n / (n - 1);
      const double v_mean = v_n > 0 ? v_sum / v_n : 0;
      const double v_var = v_n > 1 ? v_n / (v_n - 1) * v_mean * (1 - v_mean) : 0;
      for (int p = 0; p < passes; ++p) {
        const SampleRecord& r = records[size_t(p) * num_pixels + pixel];
        CeilingRegionStats& s = regionOf(out, scene, t, r.light, points[pixel].object);
        const Vec3d fv = r.visible ? Vec3d(r.weight) : Vec3d{0, 0, 0};
        s.var_fv += correction * meanSquare(fv - mean_fv);
        if (r.segment) s.visibility_var += v_var;
      }
    });
  });
}

}  // namespace

CeilingMeasurement measureCeilingStats(const RenderScene& scene, const RenderSettings& settings,
                                       int max_passes, double max_seconds) {
  const Stopwatch clock;
  const uint64_t start_ticks = cpuTicks();
  const double start_cpu = processCpuSeconds();
  const int w = scene.camera().width(), h = scene.camera().height();
  const size_t num_pixels = size_t(w) * h;
  const Tiling tiling(w, h, std::max(1, settings.tile_size));
  const uint32_t num_lights = uint32_t(scene.lights().numLights());
  CeilingMeasurement out;
  out.num_lights = num_lights;
  if (num_lights == 0) return out;  // nothing lit: no segments, no regions
  out.regions.resize(size_t(tiling.count()) * num_lights * 2);
  for (size_t r = 0; r < out.regions.size(); ++r)
    out.regions[r].light = uint32_t(r / 2 % num_lights);

  const std::vector<ShadingPoint> points = shadingPoints(scene, tiling);
  std::vector<SampleRecord> records;
  std::vector<double> ticks_proxy(out.regions.size() * 2, 0), ticks_original(ticks_proxy.size(), 0);
  int passes = 0;
  while (passes < std::max(2, max_passes) && (passes < 2 || clock.seconds() < max_seconds)) {
    const int pass = passes++;
    records.resize(size_t(passes) * num_pixels);
    SampleRecord* rec = &records[size_t(pass) * num_pixels];
    // Each tile writes only its own regions and pixels: no two threads share a sum.
    tbb::parallel_for(0, tiling.count(), [&](int t) {
      tiling.forEachPixel(t, [&](int, int, uint32_t pixel) {
        const ShadingPoint& sp = points[pixel];
        SampleRecord& r = rec[pixel];
        if (!sp.valid) return;
        PreparedSample ps;
        prepareSamples(scene, sp, settings.seed, pixel, pass, 1, &ps);
        r.light = ps.light;
        r.weight = ps.weight;
        if (!ps.needsVisibility()) return;
        r.segment = true;
        const SceneTracer tracer(scene, sp.object);
        bool vp = false, v = false;
        uint64_t tp = 0, to = 0;
        // Alternate which ray goes first, so neither always finds the caches warmed by the other.
        if (pass % 2 == 0) {
          tp = timed([&] { return tracer.proxyVisible(ps.segment); }, vp);
          to = timed([&] { return tracer.originalVisible(ps.segment); }, v);
        } else {
          to = timed([&] { return tracer.originalVisible(ps.segment); }, v);
          tp = timed([&] { return tracer.proxyVisible(ps.segment); }, vp);
        }
        r.visible = v;
        CeilingRegionStats& s = regionOf(out, scene, t, ps.light, sp.object);
        const size_t index = size_t(&s - out.regions.data()) * 2 + (vp ? 1 : 0);
        s.segments += 1;
        s.blocked += vp ? 0 : 1;
        if (v && !vp) s.mh += 1, s.f2_mh += meanSquare(Vec3d(ps.weight));
        if (!v && vp) s.hm += 1, s.f2_hm += meanSquare(Vec3d(ps.weight));
        ticks_proxy[index] += double(tp);
        ticks_original[index] += double(to);
      });
    });
  }

  addPixelVariances(scene, tiling, points, records, passes, out);

  out.passes = passes;
  out.seconds = clock.seconds();
  const double threads = double(tbb::this_task_arena::max_concurrency());
  out.cpu_per_wall =
      out.seconds > 0 ? std::clamp((processCpuSeconds() - start_cpu) / out.seconds, 0.05, threads)
                      : threads;
  const double elapsed_ns = 1e9 * out.seconds;
  out.ticks_per_ns = elapsed_ns > 0 ? double(cpuTicks() - start_ticks) / elapsed_ns : 1;
  const double ns_per_tick = out.ticks_per_ns > 0 ? 1 / out.ticks_per_ns : 1;
  for (size_t r = 0; r < out.regions.size(); ++r) {
    CeilingRegionStats& s = out.regions[r];
    for (int i = 0; i < 2; ++i) {
      s.cost_proxy[i] = ticks_proxy[r * 2 + i] * ns_per_tick;
      s.cost_original[i] = ticks_original[r * 2 + i] * ns_per_tick;
    }
    out.segments += uint64_t(s.segments);
  }
  return out;
}

double shadingNsPerSegment(const std::vector<const RenderResult*>& exact_renders,
                           const CeilingMeasurement& m) {
  double original_ns = 0, segments = 0;
  for (const CeilingRegionStats& r : m.regions)
    original_ns += r.cost_original[0] + r.cost_original[1], segments += r.segments;
  const double ray_ns = segments > 0 ? original_ns / segments : 0;
  double shading = 0, visibility = 0, render_segments = 0;
  for (const RenderResult* r : exact_renders) {
    shading += r->shading_seconds;
    visibility += r->visibility_seconds;
    render_segments += double(r->shadow_segments);
  }
  if (!(visibility > 0) || !(render_segments > 0)) return 0;
  // ns of one exact render's visibility per second of it, applied to its shading seconds.
  const double ns_per_second = ray_ns * render_segments / visibility;
  return ns_per_second * shading / render_segments;
}

CeilingInput ceilingInput(const RenderScene& scene, const CeilingMeasurement& m,
                          double per_sample_ns, double q_min) {
  CeilingInput in;
  in.regions = m.regions;
  in.num_lights = m.num_lights;
  in.per_sample_ns = per_sample_ns;
  in.proxy_class = scene.proxyClass();
  in.q_min = q_min;
  in.uses_proxies = scene.usesProxies();
  return in;
}

}  // namespace proxyvis
