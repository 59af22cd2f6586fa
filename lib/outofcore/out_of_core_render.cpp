// The out-of-core pass loop (contract in out_of_core_render.h).
#include "outofcore/out_of_core_render.h"

#include <fmt/core.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>

#include "outofcore/load_q_learner.h"
#include "outofcore/out_of_core_queue.h"
#include "render/integrator_steps.h"
#include "util/error.h"
#include "util/peak_rss.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

constexpr uint32_t kNoMesh = std::numeric_limits<uint32_t>::max();

class OutOfCoreRun {
 public:
  OutOfCoreRun(const OutOfCoreScene& scene, const OutOfCoreSettings& settings)
      : scene_(scene),
        settings_(settings),
        tiling_(scene.camera().width(), scene.camera().height(), settings.tile_size),
        pixels_(size_t(tiling_.width) * size_t(tiling_.height)),
        own_words_((size_t(settings.spp) + 63) / 64),
        cache_(
            scene.perMesh(&OutOfCoreMesh::built_bytes), settings.budget_bytes,
            [this](uint32_t m) { return measuredLoad(m); },
            scene.perMesh(&OutOfCoreMesh::load_peak_bytes)),
        learner_(scene.desc().meshes.size(), settings.q_min) {
    setMemoryBound(stats_, pixels_, settings, scene.proxyBytes());
  }

  OutOfCoreResult run() {
    const Stopwatch clock;
    const int batch = settings_.batch_passes > 0 ? std::min(settings_.batch_passes, settings_.spp)
                                                 : settings_.spp;
    Progress progress("render", uint64_t(settings_.spp) + 1, settings_.quiet);
    const Stopwatch primary;
    phase_growth_ = &stats_.primary_rss_growth_bytes;
    shadePoints();
    endPhase();
    stats_.primary_seconds = primary.seconds();
    progress.update();
    sums_.assign(pixels_, SampleSums{});
    if (settings_.learn_q) square_sums_.assign(pixels_, 0.0);
    const Stopwatch shadow;
    shadow_clock_.restart();
    for (int first = 0; first < settings_.spp;) {
      const int done = runBatch(first, std::min(batch, settings_.spp - first));
      first += done;
      progress.update(uint64_t(done));
    }
    stats_.shadow_seconds = shadow.seconds();
    stats_.seconds = clock.seconds();
    progress.done();
    return result();
  }

 private:
  // The current phase's peak growth, folded into its figure; the next phase starts from here.
  void endPhase() { *phase_growth_ = std::max(*phase_growth_, rss_.growth(rss_.endPhase())); }

  // One mesh's load (read, decode, build), its RSS growth measured apart. What the evictions
  // before it freed is handed back first, so that the process's RSS follows what the cache holds.
  GeometryLoad measuredLoad(uint32_t m) {
    endPhase();
    malloc_trim(0);
    const uint64_t before = currentRssBytes();
    GeometryLoad load = scene_.loadOriginal(m, settings_.cold_reads);
    const uint64_t peak = rss_.endPhase();
    const uint64_t growth = peak > before ? peak - before : 0;
    stats_.load_rss_growth_bytes = std::max(stats_.load_rss_growth_bytes, growth);
    // Over the mesh's built bytes where those are large enough for the ratio to mean something
    // (a small mesh's load grows RSS by pages and allocator blocks, whatever it holds).
    if (const uint64_t built = scene_.meshes()[m].built_bytes; built >= (uint64_t(1) << 20))
      stats_.load_growth_over_built =
          std::max(stats_.load_growth_over_built, double(growth) / double(built));
    *phase_growth_ = std::max(*phase_growth_, rss_.growth(peak));
    return load;
  }

  // Pixel `pixel`'s primary ray (the same function of the pixel as in every renderer).
  Segment rayOf(uint32_t pixel) const {
    return primaryRay(scene_.camera(), int(pixel % uint32_t(tiling_.width)),
                      int(pixel / uint32_t(tiling_.width)), pixel);
  }

  // Light sample `item` of a batch whose first pass is `first_pass`: drawn again, as the
  // integrator draws it (the same function of the shading point, the seed, the pixel and the
  // pass), rather than kept: a batch keeps a byte per sample, not the sample.
  PreparedSample sampleOf(uint32_t item, int first_pass) const {
    const uint32_t pixel = uint32_t(item % pixels_);
    const int pass = first_pass + int(item / pixels_);
    PreparedSample ps;
    prepareSamples(scene_.lights(), points_[pixel], settings_.seed, pixel, pass, 1, &ps);
    return ps;
  }
  uint8_t& flags(uint32_t item) { return flags_[item / pixels_][item % pixels_]; }
  bool ownBlocked(uint32_t pixel, int pass) const {
    return (own_blocked_[size_t(pixel) * own_words_ + size_t(pass) / 64] >> (pass % 64)) & 1u;
  }

  // Primary rays: queued on every mesh whose object boxes they enter; each mesh traced once.
  // The nearest hit wins, and of hits at the same distance the one of the lower mesh index, so
  // the answer does not depend on which meshes were resident. Per pixel only the nearest
  // distance and its mesh are kept; a mesh's hits live while it is visited.
  void shadePoints() {
    const size_t meshes = scene_.desc().meshes.size();
    std::vector<float> nearest(pixels_, 0.0f);
    std::vector<uint32_t> hit_mesh(pixels_, kNoMesh);
    own_blocked_.assign(pixels_ * own_words_, 0);
    points_.assign(pixels_, ShadingPoint{});  // set by ownMeshShadows, hit by hit
    QueueBuilder builder(meshes);
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      thread_local std::vector<LabelEntry> labels;
      tiling_.forEachPixel(t, [&](int x, int y, uint32_t pixel) {
        labels.clear();
        scene_.objectBoxes().labelsAlong(primaryRay(scene_.camera(), x, y, pixel), labels);
        for (const LabelEntry& e : labels) builder.add(e.label, pixel);
      });
    });
    const std::vector<uint64_t> counts = builder.counts(stats_.primary_queued);
    stats_.primary_queue_bytes = builder.bytes();
    for (uint32_t m : visitOrder(counts, cache_)) {
      const TraceScene& originals = cache_.acquire(m);
      const std::vector<uint32_t> queue = builder.take(m);
      std::vector<Hit> hits(queue.size());
      tbb::parallel_for(size_t(0), queue.size(), [&](size_t i) {
        const uint32_t pixel = queue[i];
        const Hit hit = hits[i] = originals.intersect(rayOf(pixel));
        if (!hit.hit) return;
        if (hit_mesh[pixel] == kNoMesh || hit.t < nearest[pixel] ||
            (hit.t == nearest[pixel] && m < hit_mesh[pixel])) {
          nearest[pixel] = hit.t;
          hit_mesh[pixel] = m;
        }
      });
      ownMeshShadows(m, originals, queue, hits, hit_mesh);
    }
  }

  // While mesh m is resident: the shading point of every pixel whose nearest hit so far is on it,
  // and every light sample of every pass of that point, traced against it. A point's own mesh (its
  // object and that mesh's other objects) is then never loaded again for its shadows; a nearer hit
  // on a mesh visited later overwrites the pixel's point and answers. The shading point and samples
  // are the ones the batches draw again (the same function of the hit, the seed, the pixel and the
  // pass), and the trace is against the same built scene, so the answers are the ones a queue would
  // give. `hits[i]`: queue[i]'s hit on m.
  void ownMeshShadows(uint32_t m, const TraceScene& originals, const std::vector<uint32_t>& queue,
                      const std::vector<Hit>& hits, const std::vector<uint32_t>& hit_mesh) {
    const float eps = scene_.epsilon();
    const int spp = settings_.spp;
    std::atomic<uint64_t> traces{0};
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, queue.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
          uint64_t local = 0;
          for (size_t i = r.begin(); i < r.end(); ++i) {
            const uint32_t pixel = queue[i];
            if (hit_mesh[pixel] != m) continue;
            const Vec3f& albedo = scene_.desc().meshes[m].albedo;
            const ShadingPoint& sp = points_[pixel] =
                shadingPointOf(rayOf(pixel), hits[i], eps, albedo);
            uint64_t* blocked = &own_blocked_[size_t(pixel) * own_words_];
            std::fill_n(blocked, own_words_, 0);
            for (int pass = 0; pass < spp; ++pass) {
              PreparedSample ps;
              prepareSamples(scene_.lights(), sp, settings_.seed, pixel, pass, 1, &ps);
              if (ps.needsVisibility() && originals.occluded(ps.segment))
                blocked[pass / 64] |= uint64_t(1) << (pass % 64);
              local += ps.needsVisibility();
            }
          }
          traces += local;
        });
    stats_.own_mesh_traces += traces;
  }

  // Pass `pass` (the batch's k-th) drawn and routed: its flags (and roulette factors) added to
  // the batch, its segments queued on the meshes they need.
  void routePass(int first_pass, int k, QueueBuilder& builder) {
    flags_.emplace_back(pixels_, uint8_t(0));
    std::vector<uint8_t>& flags = flags_.back();
    const int pass = first_pass + k;
    enum { kSegments, kUnqueued, kInside, kOwn };  // the counts
    std::array<std::atomic<uint64_t>, 4> n{};
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      std::array<uint64_t, 4> local{};
      tiling_.forEachPixel(t, [&](int, int, uint32_t pixel) {
        const uint32_t item = uint32_t(size_t(k) * pixels_ + pixel);
        PreparedSample ps;
        prepareSamples(scene_.lights(), points_[pixel], settings_.seed, pixel, pass, 1, &ps);
        if (!ps.needsVisibility()) return;
        ++local[kSegments];
        // Blocked by its own mesh, as the primary pass found (ownMeshShadows).
        if (ownBlocked(pixel, pass)) {
          flags[pixel] = kBlocked;
          ++local[kUnqueued], ++local[kOwn];
          return;
        }
        if (queueSegment(scene_, settings_.policy, ps.segment,
                         scene_.objects()[points_[pixel].object].mesh, item, builder,
                         flags[pixel]) == 0) {
          ++local[kUnqueued];
          local[kInside] += flags[pixel] & kBlocked;
        }
      });
      for (size_t i = 0; i < local.size(); ++i) n[i] += local[i];
    });
    stats_.blocked_by_own_mesh += n[kOwn];
    stats_.shadow_segments += n[kSegments];
    stats_.unqueued_segments += n[kUnqueued];
    stats_.blocked_by_inside += n[kInside];
  }

  // One batch from pass `first_pass`, of at most `max_passes` passes: passes are drawn and routed
  // one by one until the next would take the batch's samples and queues over the queue cap (a
  // batch holds one pass at least). The split depends on the counts of queued pairs alone, never
  // on the threads or on what is resident. Returns the passes it rendered.
  int runBatch(int first_pass, int max_passes) {
    ++stats_.batches;
    flags_.clear();
    factors_.clear();
    QueueBuilder builder(scene_.desc().meshes.size());
    std::vector<uint64_t> counts;
    const int passes = gatherBatch(first_pass, max_passes, builder, counts);
    phase_growth_ = &stats_.route_rss_growth_bytes;
    endPhase();
    phase_growth_ = &stats_.trace_rss_growth_bytes;
    const double variance = settings_.learn_q ? frameVariance() : 0;
    const double seconds = settings_.learn_q ? projectedSeconds() : 0;
    for (uint32_t m : visitOrder(counts, cache_))
      traceQueue(m, builder.take(m), first_pass, variance, seconds);
    endPhase();
    phase_growth_ = &stats_.route_rss_growth_bytes;
    addBatch(first_pass, passes);
    passes_done_ += passes;
    shadow_seconds_ = shadow_clock_.seconds();
    return passes;
  }

  // The batch's passes drawn and routed until the cap (runBatch); `counts` its pairs per mesh.
  int gatherBatch(int first_pass, int max_passes, QueueBuilder& builder,
                  std::vector<uint64_t>& counts) {
    // A flag byte per sample; for proxies-roulette, a slot (item and factor) per queued sample.
    const uint64_t item_bytes = 1;
    const uint64_t pair_bytes =
        kPairBytes +
        (settings_.policy == OutOfCorePolicy::kProxiesRoulette ? 2 * sizeof(uint32_t) : 0);
    int passes = 0;
    uint64_t pairs = 0, batch_bytes = 0;
    while (passes < max_passes) {
      routePass(first_pass, passes, builder);
      ++passes;
      counts = builder.counts(pairs);
      const uint64_t bytes = uint64_t(passes) * pixels_ * item_bytes + pairs * pair_bytes;
      const uint64_t pass_bytes = bytes - batch_bytes;
      batch_bytes = bytes;
      if (bytes + pass_bytes > stats_.queue_cap_bytes) break;
    }
    stats_.queued += pairs;
    if (passes < max_passes) ++stats_.capped_batches;
    if (settings_.policy == OutOfCorePolicy::kProxiesRoulette) {
      factors_.reset(builder.items());
    }
    {
      uint64_t bytes = builder.bytes();
      for (const auto& f : flags_) bytes += f.capacity();
      bytes += factors_.bytes();
      stats_.queue_bytes = std::max(stats_.queue_bytes, bytes);
    }
    return passes;
  }

  // Mesh m's queue of the batch from `first_pass`: under proxies-roulette drawn to be traced or
  // to take the proxies' answer; traced against the loaded original otherwise, each answer in
  // its sample's flags (and factor); the proxies' wrong answers measured for the learner and
  // the variance estimate. `variance` and `seconds`: the learner's projections.
  void traceQueue(uint32_t m, const std::vector<uint32_t>& queue, int first_pass, double variance,
                  double seconds) {
    const bool roulette = settings_.policy == OutOfCorePolicy::kProxiesRoulette;
    const bool has_proxy_answer =
        settings_.policy != OutOfCorePolicy::kExactBatched && scene_.meshes()[m].outside >= 0;
    double q = 1;
    if (roulette && has_proxy_answer) {
      q = settings_.learn_q ? learner_.q(m, queue.size(), cache_.resident(m), variance, seconds)
                            : settings_.load_q;
      stats_.q_sum += q;
      ++stats_.q_draws;
      // One draw per batch and mesh, keyed on neither the thread nor what is resident.
      Rng draw(settings_.seed, hashKeys(uint64_t(first_pass), m, 0x6c6f6164u));
      if (!(draw.uniformDouble() < q)) {
        ++stats_.skipped_queues;
        // The proxies' answer: blocked (every queued segment crosses the mesh's outside proxy).
        for (uint32_t item : queue) flags(item) |= kBlocked;
        return;
      }
    }
    const Stopwatch load_clock;
    const uint64_t loads_before = cache_.stats().loads;
    const TraceScene& originals = cache_.acquire(m);
    const bool loaded = cache_.stats().loads > loads_before;
    const double load_seconds = load_clock.seconds();
    const Stopwatch trace_clock;
    std::atomic<uint64_t> traces{0};
    const bool weighted = q < 1;
    const float inverse_q = float(1.0 / q);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, queue.size(), 256),
                      [&](const tbb::blocked_range<size_t>& r) {
                        uint64_t local = 0;
                        for (size_t i = r.begin(); i < r.end(); ++i) {
                          const uint32_t item = queue[i];
                          uint8_t& f = flags(item);
                          if (f & kBlocked) continue;
                          ++local;
                          // The proxies' answer v' is 0 (blocked) for every queued segment.
                          const bool v = !originals.occluded(sampleOf(item, first_pass).segment);
                          if (has_proxy_answer && v) f |= kWrong;
                          if (!v)
                            f |= kBlocked;
                          else if (weighted)  // v' + (v - v') / q with v' = 0, v = 1
                            factors_.slot(item) *= inverse_q;
                        }
                        traces += local;
                      });
    ++stats_.traced_queues;
    if (has_proxy_answer) {
      // Summed in queue order: the same bits at any thread count.
      double w2 = 0, signed_sum = 0;
      for (uint32_t item : queue) {
        uint8_t& f = flags(item);
        if (!(f & kWrong)) continue;
        f &= uint8_t(~kWrong);
        const Vec3f w = sampleOf(item, first_pass).weight;
        w2 += double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z;
        signed_sum += double(w.x) + w.y + w.z;  // v - v' = 1
      }
      if (weighted) {
        // This queue's skip would have moved the image mean by -S (S its wrong segments'
        // share of the mean); traced with probability q, its term (1[traced]/q - 1) S has
        // variance (1/q - 1) S^2, estimated without bias from the traced queues alone by
        // dividing by q.
        const double s = signed_sum / (3.0 * double(pixels_) * double(settings_.spp));
        stats_.roulette_added_variance += (1 / q - 1) * s * s / q;
      }
      learner_.observe(m, queue.size(), w2, loaded, load_seconds, trace_clock.seconds());
      stats_.proxy_queues.push_back({w2, load_clock.seconds()});
    }
    stats_.original_traces += traces;
  }

  // The batch's samples added to the pixel sums.
  void addBatch(int first_pass, int passes) {
    const bool roulette = settings_.policy == OutOfCorePolicy::kProxiesRoulette;
    // Accumulated pass by pass, as the in-core renderer does: the same sums, bit for bit.
    tbb::parallel_for(size_t(0), pixels_, [&](size_t pixel) {
      SampleSums& sums = sums_[pixel];
      for (int k = 0; k < passes; ++k) {
        const uint32_t item = uint32_t(size_t(k) * pixels_ + pixel);
        const PreparedSample ps = sampleOf(item, first_pass);
        if (!ps.needsVisibility()) continue;  // also every sample of a pixel without a point
        // The product of the roulette's factors, multiplied in the meshes' visit order, which
        // depends on the batches alone (never on the threads).
        const double v = (flags_[size_t(k)][pixel] & kBlocked) ? 0.0
                         : roulette                            ? double(factors_.of(item))
                                                               : 1.0;
        sums.add(ps.weight, v);
        if (settings_.learn_q) {
          const Vec3d x = Vec3d(ps.weight) * v;
          square_sums_[pixel] += x.x * x.x + x.y * x.y + x.z * x.z;
        }
      }
    });
  }

  double frameVariance() const {
    return frameVarianceSpp2(sums_, square_sums_, passes_done_, settings_.spp);
  }

  // The render's seconds projected from the passes so far.
  double projectedSeconds() const {
    if (passes_done_ < 1) return 0;
    return stats_.primary_seconds + shadow_seconds_ * double(settings_.spp) / passes_done_;
  }

  OutOfCoreResult result() {
    OutOfCoreResult r;
    const int w = tiling_.width, h = tiling_.height;
    r.spp = settings_.spp;
    r.radiance = Image{w, h, 3, std::vector<float>(pixels_ * 3)};
    r.visibility = Image{w, h, 1, std::vector<float>(pixels_)};
    for (size_t i = 0; i < pixels_; ++i)
      sums_[i].writeMeans(settings_.spp, &r.radiance.pixels[i * 3], &r.visibility.pixels[i]);
    stats_.cache = cache_.stats();
    stats_.budget_bytes = settings_.budget_bytes;
    stats_.rss_before_bytes = rss_.before();
    stats_.peak_rss_bytes = rss_.peak();
    stats_.peak_rss_growth_bytes = rss_.growth(stats_.peak_rss_bytes);
    // The proxies were resident before the render began: the bound counts them, so the peak
    // compared with it does too.
    stats_.bounded_peak_bytes = stats_.peak_rss_growth_bytes + stats_.proxy_bytes;
    r.stats = stats_;
    return r;
  }

  const OutOfCoreScene& scene_;
  const OutOfCoreSettings& settings_;
  PeakRssPhases rss_;                 // first: the render's memory is measured from its start
  uint64_t* phase_growth_ = nullptr;  // the figure the current phase's peak growth goes to
  const Tiling tiling_;
  const size_t pixels_;
  const size_t own_words_;  // 64-bit words per pixel of own_blocked_
  GeometryCache cache_;
  std::vector<ShadingPoint> points_;
  std::vector<uint64_t> own_blocked_;  // per pixel, a bit per pass: blocked by its own mesh
  // The batch's passes: per pass and pixel, its sample's flags (kBlocked, kWrong).
  std::vector<std::vector<uint8_t>> flags_;
  RouletteFactors factors_;          // proxies-roulette: the product of each queued sample's 1/q
  std::vector<double> square_sums_;  // learned q: per pixel, the sum of its samples' |w v|^2
  LoadQLearner learner_;
  int passes_done_ = 0;
  Stopwatch shadow_clock_;
  double shadow_seconds_ = 0;
  std::vector<SampleSums> sums_;
  OutOfCoreStats stats_;
};

}  // namespace

OutOfCoreResult renderOutOfCore(const OutOfCoreScene& scene, const OutOfCoreSettings& settings) {
  checkOutOfCoreSettings(scene, settings);
  return OutOfCoreRun(scene, settings).run();
}

}  // namespace proxyvis
