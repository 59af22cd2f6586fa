// The direct-illumination integrator (contract in renderer.h). Each pass runs in two parallel
// phases over screen tiles, timed separately: (A) light sampling, producing one segment and
// weight per light sample; (B) visibility estimation, where the estimator decides which rays to
// trace, and accumulation. Separating them lets render-compare and bench_render report shading
// cost and shadow-ray cost apart (docs/design.md, measured costs, point 4).
#include "render/renderer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "render/internal/integrator.h"
#include "render/render_scene.h"
#include "render/scene_tracer.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

using namespace detail;

namespace {

void validate(const RenderSettings& s) {
  if (s.tile_size < 1 || s.tile_size > 4096)
    throw Error("", "tile size must be in [1, 4096]", "got " + std::to_string(s.tile_size));
  if (s.spp <= 0 && !(s.time_budget > 0))
    throw Error("", "nothing to render", "spp must be positive unless a time budget is given");
  if (s.time_budget < 0 || !std::isfinite(s.time_budget))
    throw Error("", "time budget must be a finite number of seconds >= 0");
  if (s.samples_per_pass < 0) throw Error("", "samples per pass must be >= 0");
}

// Light samples per pixel per pass for estimators with probes under a time budget: probes are
// drawn per shading point and call, so fewer, larger passes amortise them, while 16 still lets
// the budget end the render within a few percent of its time.
constexpr int kProbePassSamplesUnderBudget = 16;

int samplesPerPass(const RenderSettings& s, int probes) {
  if (s.samples_per_pass > 0) return s.samples_per_pass;
  if (probes <= 0) return 1;
  return s.time_budget > 0 ? kProbePassSamplesUnderBudget : std::max(1, s.spp);
}

// Per-pixel sums, one cache line per pixel: phase B touches one line per pixel, not four.
struct alignas(64) PixelSums {
  Vec3d radiance;
  double vis_sum = 0;
  RayCounts rays;
  uint32_t vis_n = 0;
};
struct Accumulators {
  std::vector<PixelSums> px;
  explicit Accumulators(size_t n) : px(n) {}
};

// Per-thread scratch for phase B.
struct Scratch {
  std::vector<uint32_t> order;
  std::vector<Segment> segments, probes;
  std::vector<double> estimates;
};

// The learning region of a query: screen tile x light x whether the shading point's own object
// uses a proxy. Points on such an object trace their own original in both V and V' (the
// self-shadowing rule), so their proxy rays cost more and they must not share a cost model with
// the points beside them (the ground under the dragon).
uint32_t regionOf(const RenderScene& scene, const ShadingPoint& sp, uint32_t tile, uint32_t light) {
  const uint32_t self = scene.objects()[sp.object].proxy >= 0 ? 1u : 0u;
  return (tile * uint32_t(scene.lights().numLights()) + light) * 2u + self;
}

// Phase B for one pixel: groups its samples by light (one query per learning region), asks the
// estimator, accumulates.
void estimatePixel(const RenderScene& scene, VisibilityEstimator& estimator, const ShadingPoint& sp,
                   const PreparedSample* samples, int count, uint32_t pixel, int pass,
                   uint64_t seed, uint32_t tile, int probes, Scratch& scratch, Accumulators& acc) {
  if (!sp.valid) return;
  const uint32_t num_lights = uint32_t(scene.lights().numLights());
  if (count == 1 && probes == 0) {
    // The common case (one sample per pass, no probes): no grouping, no copies.
    const PreparedSample& ps = samples[0];
    if (!(ps.weight.x > 0 || ps.weight.y > 0 || ps.weight.z > 0)) return;
    const SceneTracer tracer(scene, sp.object);
    Rng rng = Rng::deferred(seed, pixel, uint64_t(pass), 1);
    ShadingPointQuery query;
    query.segments = std::span<const Segment>(&ps.segment, 1);
    query.tracer = &tracer;
    query.region = regionOf(scene, sp, tile, ps.light);
    query.point = pixel * num_lights + ps.light;
    double v = 0;
    RayCounts counts;
    estimator.estimate(query, rng, std::span<double>(&v, 1), counts);
    PixelSums& sums = acc.px[pixel];
    sums.radiance += Vec3d(ps.weight) * v;
    sums.vis_sum += v;
    sums.vis_n += 1;
    sums.rays += counts;
    return;
  }
  scratch.order.clear();
  for (int j = 0; j < count; ++j)
    if (samples[j].weight.x > 0 || samples[j].weight.y > 0 || samples[j].weight.z > 0)
      scratch.order.push_back(uint32_t(j));
  if (scratch.order.empty()) return;
  // In-place sort by (light, index): std::stable_sort would allocate a buffer per pixel.
  if (scratch.order.size() > 1)
    std::sort(scratch.order.begin(), scratch.order.end(), [&](uint32_t a, uint32_t b) {
      return samples[a].light != samples[b].light ? samples[a].light < samples[b].light : a < b;
    });

  const SceneTracer tracer(scene, sp.object);
  Rng rng = Rng::deferred(seed, pixel, uint64_t(pass), 1);
  RayCounts counts;
  for (size_t begin = 0; begin < scratch.order.size();) {
    const uint32_t light = samples[scratch.order[begin]].light;
    size_t end = begin;
    scratch.segments.clear();
    while (end < scratch.order.size() && samples[scratch.order[end]].light == light)
      scratch.segments.push_back(samples[scratch.order[end++]].segment);
    scratch.probes.clear();
    if (probes > 0) {
      // Probes come from the region's own light, from a stream of their own.
      Rng prng(seed, hashKeys(pixel, uint64_t(pass), 2 + uint64_t(light)));
      for (int k = 0; k < probes; ++k) {
        const float u0 = prng.uniformFloat(), u1 = prng.uniformFloat(), u2 = prng.uniformFloat();
        Segment s;
        if (makeSegment(scene, sp, scene.lights().sampleLight(light, u0, u1, u2).point, s))
          scratch.probes.push_back(s);
      }
    }
    scratch.estimates.assign(scratch.segments.size(), 0.0);
    ShadingPointQuery query;
    query.segments = scratch.segments;
    query.tracer = &tracer;
    query.region = regionOf(scene, sp, tile, light);
    query.point = pixel * num_lights + light;
    query.probes = scratch.probes;
    estimator.estimate(query, rng, scratch.estimates, counts);
    for (size_t i = begin; i < end; ++i) {
      const double v = scratch.estimates[i - begin];
      const Vec3f& w = samples[scratch.order[i]].weight;
      acc.px[pixel].radiance += Vec3d(w) * v;
      acc.px[pixel].vis_sum += v;
      acc.px[pixel].vis_n += 1;
    }
    begin = end;
  }
  acc.px[pixel].rays += counts;
}

}  // namespace

namespace detail {

int passSamplesWithinBudget(double seconds_left, int full_pass, int pass, double last_seconds,
                            int last_count, int probes) {
  if (pass == 0) return full_pass;  // nothing measured yet
  const double fixed_units = 2.0 * probes;
  const double unit_seconds = last_seconds / (fixed_units + last_count);
  if (!(unit_seconds > 0)) return full_pass;
  const double fit = seconds_left / unit_seconds - fixed_units;
  if (fit >= full_pass) return full_pass;
  if (fit >= 1) return int(fit);
  const double one_sample_seconds = unit_seconds * (fixed_units + 1);
  return seconds_left >= 0.5 * one_sample_seconds ? 1 : 0;
}

}  // namespace detail

EstimatorSetup estimatorSetupFor(const RenderScene& scene, const RenderSettings& settings) {
  EstimatorSetup setup = settings.estimator;
  const detail::Tiling tiling(scene.camera().width(), scene.camera().height(),
                              std::max(1, settings.tile_size));
  setup.num_regions = uint32_t(tiling.count()) * uint32_t(scene.lights().numLights()) * 2u;
  setup.num_points = uint32_t(scene.camera().width()) * uint32_t(scene.camera().height()) *
                     uint32_t(scene.lights().numLights());
  setup.proxy_class = settings.force_general_proxies ? ProxyClass::kGeneral : scene.proxyClass();
  return setup;
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings) {
  const auto estimator = makeEstimator(estimatorSetupFor(scene, settings));
  return render(scene, settings, *estimator);
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings,
                    VisibilityEstimator& estimator) {
  validate(settings);
  const Stopwatch whole;
  const int w = scene.camera().width(), h = scene.camera().height();
  const size_t num_pixels = size_t(w) * h;
  const Tiling tiling(w, h, settings.tile_size);
  const int probes = estimator.probesPerPoint();
  const int batch = samplesPerPass(settings, probes);
  const int spp_cap = settings.spp > 0 ? settings.spp : INT_MAX;

  RenderResult result;
  result.proxy_class = estimatorSetupFor(scene, settings).proxy_class;
  const std::vector<ShadingPoint> points = shadingPoints(scene, tiling);
  result.primary_seconds = whole.seconds();
  result.primary_rays = num_pixels;

  Accumulators acc(num_pixels);
  std::vector<PreparedSample> samples(num_pixels * size_t(batch));
  tbb::enumerable_thread_specific<Scratch> scratch;
  const uint64_t total_passes =
      settings.time_budget > 0 ? 0 : uint64_t((spp_cap + batch - 1) / batch);
  // Work is tiles rendered, or milliseconds of the time budget spent.
  const uint64_t budget_ms = uint64_t(std::ceil(settings.time_budget * 1000));
  Progress progress("render",
                    settings.time_budget > 0 ? budget_ms : total_passes * uint64_t(tiling.count()),
                    settings.quiet);
  uint64_t reported_ms = 0;
  double sampling_seconds = 0;
  const double threads = double(tbb::this_task_arena::max_concurrency());
  const bool timed = settings.time_budget > 0;
  int taken = 0, pass = 0, last_count = 0;
  double last_pass_seconds = 0;
  while (taken < spp_cap && (pass == 0 || !timed || whole.seconds() < settings.time_budget)) {
    int count = std::min(batch, spp_cap - taken);
    if (timed && batch > 1) {
      count = passSamplesWithinBudget(settings.time_budget - whole.seconds(), count, pass,
                                      last_pass_seconds, last_count, probes);
      if (count == 0) break;
    }
    const Stopwatch pass_clock, sampling;
    tbb::parallel_for(0, tiling.count(), [&](int t) {
      tiling.forEachPixel(t, [&](int, int, uint32_t pixel) {
        prepareSamples(scene, points[pixel], settings.seed, pixel, pass, count,
                       &samples[size_t(pixel) * batch]);
      });
    });
    sampling_seconds += sampling.seconds();

    const Stopwatch visibility;
    estimator.beginPass(pass);
    tbb::parallel_for(0, tiling.count(), [&](int t) {
      Scratch& s = scratch.local();
      tiling.forEachPixel(t, [&](int, int, uint32_t pixel) {
        estimatePixel(scene, estimator, points[pixel], &samples[size_t(pixel) * batch], count,
                      pixel, pass, settings.seed, uint32_t(t), probes, s, acc);
      });
      if (!timed) progress.update();
    });
    estimator.endPass();
    result.visibility_seconds += visibility.seconds();
    taken += count;
    last_count = count;
    last_pass_seconds = pass_clock.seconds();
    ++pass;
    if (timed) {
      const uint64_t spent_ms = std::min(budget_ms, uint64_t(whole.seconds() * 1000));
      if (spent_ms > reported_ms) progress.update(spent_ms - reported_ms);
      reported_ms = std::max(reported_ms, spent_ms);
    }
    if (!settings.estimator.fixed_costs) {
      // What every light sample costs outside visibility, in CPU ns per sample (the unit of the
      // learned ray costs): light sampling plus the primary ray's share so far.
      const double cpu_seconds = (result.primary_seconds + sampling_seconds) * threads;
      estimator.setPerSampleCost(1e9 * cpu_seconds / (double(num_pixels) * taken));
    }
  }
  progress.done();

  result.learned = estimator.learnedSummary();
  result.spp = taken;
  result.passes = pass;
  result.radiance = Image{w, h, 3, std::vector<float>(num_pixels * 3)};
  result.visibility = Image{w, h, 1, std::vector<float>(num_pixels)};
  result.cost = Image{w, h, 3, std::vector<float>(num_pixels * 3)};
  for (size_t i = 0; i < num_pixels; ++i) {
    const PixelSums& sums = acc.px[i];
    for (int c = 0; c < 3; ++c) result.radiance.pixels[i * 3 + c] = float(sums.radiance[c] / taken);
    result.visibility.pixels[i] = sums.vis_n ? float(sums.vis_sum / sums.vis_n) : 0.0f;
    result.cost.pixels[i * 3 + 0] = float(sums.rays.proxy);
    result.cost.pixels[i * 3 + 1] = float(sums.rays.original);
    result.cost.pixels[i * 3 + 2] = float(sums.rays.probe);
    result.rays += sums.rays;
    result.shadow_segments += sums.vis_n;
  }
  result.shading_seconds = result.primary_seconds + sampling_seconds;
  result.seconds = whole.seconds();
  return result;
}

PassSegments passSegments(const RenderScene& scene, const RenderSettings& settings, int pass) {
  validate(settings);
  const int w = scene.camera().width(), h = scene.camera().height();
  const Tiling tiling(w, h, settings.tile_size);
  const int batch = settings.samples_per_pass > 0 ? settings.samples_per_pass : 1;
  const std::vector<ShadingPoint> points = shadingPoints(scene, tiling);
  std::vector<PreparedSample> samples(points.size() * size_t(batch));
  tbb::parallel_for(size_t(0), points.size(), [&](size_t pixel) {
    prepareSamples(scene, points[pixel], settings.seed, uint32_t(pixel), pass, batch,
                   &samples[pixel * batch]);
  });
  PassSegments out;
  for (size_t i = 0; i < samples.size(); ++i) {
    const Vec3f& wt = samples[i].weight;
    if (!(wt.x > 0 || wt.y > 0 || wt.z > 0)) continue;
    out.segments.push_back(samples[i].segment);
    out.pixels.push_back(uint32_t(i / size_t(batch)));
    out.objects.push_back(points[i / size_t(batch)].object);
  }
  return out;
}

}  // namespace proxyvis
