// The direct-illumination integrator's pass loop (contract in renderer.h), resumable between
// passes (render_session.h). Each pass runs in two parallel phases over screen tiles, timed
// separately: (A) light sampling, producing one segment and weight per light sample; (B)
// visibility estimation, where the estimator decides which rays to trace, and accumulation.
// Separating them lets render-compare and bench_render report shading cost and shadow-ray cost
// apart (docs/design.md, measured costs, point 4).
#include "render/render_session.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <ctime>
#include <optional>

#include "render/internal/integrator.h"
#include "render/render_scene.h"
#include "render/scene_tracer.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

using namespace detail;

namespace {

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
struct alignas(64) PixelSums : SampleSums {
  RayCounts rays;
};

// Per-thread scratch for phase B.
struct Scratch {
  std::vector<uint32_t> order;
  std::vector<Segment> segments, probes;
  std::vector<double> estimates;
};

// Phase B for one pixel: groups its samples by light (one query per learning region), asks the
// estimator, accumulates.
void estimatePixel(const RenderScene& scene, VisibilityEstimator& estimator, const ShadingPoint& sp,
                   const PreparedSample* samples, int count, uint32_t pixel, int pass,
                   uint64_t seed, uint32_t tile, int probes, Scratch& scratch, PixelSums& sums) {
  if (!sp.valid) return;
  const uint32_t num_lights = uint32_t(scene.lights().numLights());
  if (count == 1 && probes == 0) {
    // The common case (one sample per pass, no probes): no grouping, no copies.
    const PreparedSample& ps = samples[0];
    if (!ps.needsVisibility()) return;
    const SceneTracer tracer(scene, sp.object);
    Rng rng = Rng::deferred(seed, pixel, uint64_t(pass), 1);
    ShadingPointQuery query;
    query.segments = std::span<const Segment>(&ps.segment, 1);
    query.tracer = &tracer;
    query.region = learningRegion(scene, sp.object, tile, ps.light);
    query.point = pixel * num_lights + ps.light;
    double v = 0;
    RayCounts counts;
    estimator.estimate(query, rng, std::span<double>(&v, 1), counts);
    sums.add(ps.weight, v);
    sums.rays += counts;
    return;
  }
  scratch.order.clear();
  for (int j = 0; j < count; ++j)
    if (samples[j].needsVisibility()) scratch.order.push_back(uint32_t(j));
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
    query.region = learningRegion(scene, sp.object, tile, light);
    query.point = pixel * num_lights + light;
    query.probes = scratch.probes;
    estimator.estimate(query, rng, scratch.estimates, counts);
    for (size_t i = begin; i < end; ++i) {
      sums.add(samples[scratch.order[i]].weight, scratch.estimates[i - begin]);
    }
    begin = end;
  }
  sums.rays += counts;
}

}  // namespace

struct RenderSession::State {
  const RenderScene& scene;
  const RenderSettings settings;
  VisibilityEstimator& estimator;
  const Tiling tiling;
  const size_t num_pixels;
  const int probes, batch, spp_cap;
  const bool timed;
  const double threads;  // the arena's concurrency when the session began
  ProxyClass proxy_class = ProxyClass::kGeneral;
  std::vector<ShadingPoint> points;
  std::vector<PixelSums> sums;
  std::vector<PreparedSample> samples;  // one pass's light samples, batch per pixel
  tbb::enumerable_thread_specific<Scratch> scratch;
  std::optional<Progress> progress;
  uint64_t budget_ms = 0, reported_ms = 0;

  int taken = 0, pass = 0, last_count = 0;
  double last_pass_seconds = 0;
  bool stopped = false;  // a fitted pass would have had no sample: the budget is spent
  double primary_seconds = 0, sampling_seconds = 0, visibility_seconds = 0;

  // The session's clock: finished slices plus the open one.
  double closed_seconds = 0, closed_cpu = 0;
  std::optional<Stopwatch> slice;
  double slice_cpu_start = 0;

  State(const RenderScene& sc, const RenderSettings& s, VisibilityEstimator& e)
      : scene(sc),
        settings(s),
        estimator(e),
        tiling(sc.camera().width(), sc.camera().height(), s.tile_size),
        num_pixels(size_t(sc.camera().width()) * size_t(sc.camera().height())),
        probes(e.probesPerPoint()),
        batch(samplesPerPass(s, probes)),
        spp_cap(s.spp > 0 ? s.spp : INT_MAX),
        timed(s.time_budget > 0),
        threads(double(tbb::this_task_arena::max_concurrency())) {}

  double clock() const { return closed_seconds + (slice ? slice->seconds() : 0); }
  double cpu() const { return closed_cpu + (slice ? processCpuSeconds() - slice_cpu_start : 0); }
  void openSlice() {
    slice.emplace();
    slice_cpu_start = processCpuSeconds();
  }
  double closeSlice() {  // returns the slice's wall time
    const double spent = slice->seconds();
    closed_seconds += spent;
    closed_cpu += processCpuSeconds() - slice_cpu_start;
    slice.reset();
    if (finished()) progress->done();
    return spent;
  }

  // render()'s loop condition, on this session's clock.
  bool finished() const {
    return stopped || taken >= spp_cap || (pass > 0 && timed && clock() >= settings.time_budget);
  }

  // One pass; false (and nothing done) if the session is finished.
  bool runPass() {
    if (finished()) return false;
    int count = std::min(batch, spp_cap - taken);
    if (timed && batch > 1) {
      count = passSamplesWithinBudget(settings.time_budget - clock(), count, pass,
                                      last_pass_seconds, last_count, probes);
      if (count == 0) {
        stopped = true;
        return false;
      }
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
                      pixel, pass, settings.seed, uint32_t(t), probes, s, sums[pixel]);
      });
      if (!timed) progress->update();
    });
    estimator.endPass();
    visibility_seconds += visibility.seconds();
    taken += count;
    last_count = count;
    last_pass_seconds = pass_clock.seconds();
    ++pass;
    if (timed) {
      const uint64_t spent_ms = std::min(budget_ms, uint64_t(clock() * 1000));
      if (spent_ms > reported_ms) progress->update(spent_ms - reported_ms);
      reported_ms = std::max(reported_ms, spent_ms);
    }
    if (!settings.estimator.fixed_costs) {
      // What every light sample costs outside visibility, in CPU ns per sample (the unit of the
      // learned ray costs): light sampling plus the primary ray's share so far.
      const double cpu_seconds = (primary_seconds + sampling_seconds) * threads;
      estimator.setPerSampleCost(1e9 * cpu_seconds / (double(num_pixels) * taken));
    }
    return true;
  }
};

RenderSession::RenderSession(const RenderScene& scene, const RenderSettings& settings)
    : owned_(makeEstimator(estimatorSetupFor(scene, settings))) {
  start(scene, settings, *owned_);
}

RenderSession::RenderSession(const RenderScene& scene, const RenderSettings& settings,
                             VisibilityEstimator& estimator) {
  start(scene, settings, estimator);
}

void RenderSession::start(const RenderScene& scene, const RenderSettings& settings,
                          VisibilityEstimator& estimator) {
  validateRenderSettings(settings);
  state_ = std::make_unique<State>(scene, settings, estimator);
  State& s = *state_;
  s.openSlice();  // the primary rays and the buffers are the session's own time
  s.proxy_class = estimatorSetupFor(scene, settings).proxy_class;
  s.points = shadingPoints(scene, s.tiling);
  s.primary_seconds = s.slice->seconds();
  s.sums.resize(s.num_pixels);
  s.samples.resize(s.num_pixels * size_t(s.batch));
  const uint64_t total_passes = s.timed ? 0 : uint64_t((s.spp_cap + s.batch - 1) / s.batch);
  // Work is tiles rendered, or milliseconds of the time budget spent.
  s.budget_ms = uint64_t(std::ceil(settings.time_budget * 1000));
  s.progress.emplace("render", s.timed ? s.budget_ms : total_passes * uint64_t(s.tiling.count()),
                     settings.quiet);
  s.closeSlice();
}

RenderSession::~RenderSession() = default;

bool RenderSession::finished() const {
  return state_->finished();
}

int RenderSession::runPasses(int n) {
  State& s = *state_;
  if (n <= 0 || s.finished()) return 0;
  s.openSlice();
  int ran = 0;
  while (ran < n && s.runPass()) ++ran;
  s.closeSlice();
  return ran;
}

double RenderSession::runFor(double seconds) {
  State& s = *state_;
  if (s.finished()) return 0;
  s.openSlice();
  while (s.runPass() && s.slice->seconds() < seconds) {
  }
  return s.closeSlice();
}

void RenderSession::runToEnd() {
  State& s = *state_;
  if (s.finished()) return;
  s.openSlice();
  while (s.runPass()) {
  }
  s.closeSlice();
}

int RenderSession::passes() const {
  return state_->pass;
}
int RenderSession::spp() const {
  return state_->taken;
}
double RenderSession::seconds() const {
  return state_->clock();
}
double RenderSession::cpuSeconds() const {
  return state_->cpu();
}

RenderResult RenderSession::result() const {
  const State& s = *state_;
  const int w = s.scene.camera().width(), h = s.scene.camera().height();
  RenderResult result;
  result.proxy_class = s.proxy_class;
  result.primary_seconds = s.primary_seconds;
  result.primary_rays = s.num_pixels;
  result.visibility_seconds = s.visibility_seconds;
  result.learned = s.estimator.learnedSummary();
  result.spp = s.taken;
  result.passes = s.pass;
  result.radiance = Image{w, h, 3, std::vector<float>(s.num_pixels * 3)};
  result.visibility = Image{w, h, 1, std::vector<float>(s.num_pixels)};
  result.cost = Image{w, h, 3, std::vector<float>(s.num_pixels * 3)};
  const int taken = std::max(1, s.taken);  // no pass yet: a black image, not a NaN one
  for (size_t i = 0; i < s.num_pixels; ++i) {
    const PixelSums& sums = s.sums[i];
    sums.writeMeans(taken, &result.radiance.pixels[i * 3], &result.visibility.pixels[i]);
    result.cost.pixels[i * 3 + 0] = float(sums.rays.proxy);
    result.cost.pixels[i * 3 + 1] = float(sums.rays.original);
    result.cost.pixels[i * 3 + 2] = float(sums.rays.probe);
    result.rays += sums.rays;
    result.shadow_segments += sums.vis_n;
  }
  result.shading_seconds = s.primary_seconds + s.sampling_seconds;
  result.seconds = s.clock();
  result.cpu_seconds = s.cpu();
  return result;
}

std::vector<size_t> runInterleaved(std::span<RenderSession* const> sessions, double slice_seconds,
                                   size_t first) {
  std::vector<size_t> turns;
  const size_t n = sessions.size();
  for (size_t round = 0;; ++round) {
    bool any = false;
    for (size_t turn = 0; turn < n; ++turn) {
      const size_t i = (first + round + turn) % n;
      if (sessions[i]->finished()) continue;
      sessions[i]->runFor(slice_seconds);
      turns.push_back(i);
      any = true;
    }
    if (!any) return turns;
  }
}

}  // namespace proxyvis
