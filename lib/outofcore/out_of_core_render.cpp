// The out-of-core pass loop (contract in out_of_core_render.h).
#include "outofcore/out_of_core_render.h"

#include <fmt/core.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>

#include "outofcore/load_q_learner.h"
#include "render/integrator_steps.h"
#include "util/error.h"
#include "util/peak_rss.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

constexpr uint32_t kNoMesh = std::numeric_limits<uint32_t>::max();

// A segment's flags in a batch: blocked (by its own mesh, an inside proxy, an original or the
// roulette's skip), and "the proxies' answer was wrong" for the mesh being traced.
constexpr uint8_t kBlocked = 1, kWrong = 2;
// What a queued (segment, mesh) pair may take while the batch is gathered: its item index in a
// thread's list of that mesh, and the list's room to grow (a vector at most doubles).
constexpr uint64_t kPairBytes = 2 * sizeof(uint32_t);

// (mesh, item) pairs gathered in parallel into per-thread lists per mesh; a mesh's queue is
// taken, in item order, when the mesh is visited, and the threads' lists of it are freed then.
// The order only matters for the trace's memory access and the order of the queue's sums,
// never for an answer.
class QueueBuilder {
 public:
  explicit QueueBuilder(size_t meshes)
      : lists_([meshes] { return std::vector<std::vector<uint32_t>>(meshes); }), meshes_(meshes) {}
  void add(uint32_t mesh, uint32_t item) { lists_.local()[mesh].push_back(item); }
  // Pairs per mesh, and `total` their sum.
  std::vector<uint64_t> counts(uint64_t& total) const {
    std::vector<uint64_t> n(meshes_, 0);
    total = 0;
    for (const auto& local : lists_)
      for (size_t m = 0; m < meshes_; ++m) n[m] += local[m].size(), total += local[m].size();
    return n;
  }
  // Bytes the lists hold now (their capacity).
  uint64_t bytes() const {
    uint64_t b = 0;
    for (const auto& local : lists_)
      for (const auto& l : local) b += l.capacity() * sizeof(uint32_t);
    return b;
  }
  // Every queued item once, in order.
  std::vector<uint32_t> items() const {
    std::vector<uint32_t> all;
    for (const auto& local : lists_)
      for (const auto& l : local) all.insert(all.end(), l.begin(), l.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  }
  // Mesh m's queue in item order.
  std::vector<uint32_t> take(uint32_t m) {
    size_t n = 0;
    for (const auto& local : lists_) n += local[m].size();
    std::vector<uint32_t> queue;
    queue.reserve(n);
    for (auto& local : lists_) {
      queue.insert(queue.end(), local[m].begin(), local[m].end());
      std::vector<uint32_t>().swap(local[m]);
    }
    std::sort(queue.begin(), queue.end());
    return queue;
  }

 private:
  tbb::enumerable_thread_specific<std::vector<std::vector<uint32_t>>> lists_;
  size_t meshes_;
};

// The meshes with a queue, the resident ones first (no load), then by index.
std::vector<uint32_t> visitOrder(const std::vector<uint64_t>& counts, const GeometryCache& cache) {
  std::vector<uint32_t> order;
  for (uint32_t m = 0; m < counts.size(); ++m)
    if (counts[m] && cache.resident(m)) order.push_back(m);
  for (uint32_t m = 0; m < counts.size(); ++m)
    if (counts[m] && !cache.resident(m)) order.push_back(m);
  return order;
}

class OutOfCoreRun {
 public:
  OutOfCoreRun(const OutOfCoreScene& scene, const OutOfCoreSettings& settings)
      : scene_(scene),
        settings_(settings),
        tiling_(scene.camera().width(), scene.camera().height(), settings.tile_size),
        pixels_(size_t(tiling_.width) * size_t(tiling_.height)),
        own_words_((size_t(settings.spp) + 63) / 64),
        cache_(
            builtBytes(scene), settings.budget_bytes,
            [this](uint32_t m) { return measuredLoad(m); }, loadPeakBytes(scene)),
        learner_(scene.desc().meshes.size(), settings.q_min) {
    stats_.image_bytes = imageBytes(pixels_, settings);
    const OutOfCoreMemoryBound bound =
        outOfCoreMemoryBound(settings.budget_bytes, scene.proxyBytes(), stats_.image_bytes);
    stats_.proxy_bytes = scene.proxyBytes();
    stats_.overhead_bytes = bound.overhead_bytes;
    stats_.rss_bound_bytes = bound.bound_bytes;
    stats_.queue_cap_bytes =
        settings.queue_cap_bytes ? settings.queue_cap_bytes : bound.queue_cap_bytes;
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

  static std::vector<uint64_t> builtBytes(const OutOfCoreScene& scene) {
    std::vector<uint64_t> bytes;
    for (const OutOfCoreMesh& m : scene.meshes()) bytes.push_back(m.built_bytes);
    return bytes;
  }
  static std::vector<uint64_t> loadPeakBytes(const OutOfCoreScene& scene) {
    std::vector<uint64_t> bytes;
    for (const OutOfCoreMesh& m : scene.meshes()) bytes.push_back(m.load_peak_bytes);
    return bytes;
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
  // proxies-roulette: a sample's factor, 1 for one never queued (no slot).
  float factorOf(uint32_t item) const {
    const auto it = std::lower_bound(weighted_items_.begin(), weighted_items_.end(), item);
    return it != weighted_items_.end() && *it == item
               ? factors_[size_t(it - weighted_items_.begin())]
               : 1.0f;
  }
  float& factorSlot(uint32_t item) {
    const auto it = std::lower_bound(weighted_items_.begin(), weighted_items_.end(), item);
    return factors_[size_t(it - weighted_items_.begin())];  // queued: it has a slot
  }
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

  // Queues segment `item` (from a point on a mesh `own_mesh` object) on the other meshes it must
  // be traced against; none when the boxes or proxies decide it (`flags` is then marked blocked
  // if an inside proxy blocks it). The own mesh was traced in the primary pass (ownMeshShadows).
  // Returns the pairs queued.
  uint32_t route(const Segment& s, uint32_t own_mesh, uint32_t item, QueueBuilder& builder,
                 uint8_t& flags) {
    thread_local std::vector<LabelEntry> labels;
    thread_local std::vector<BoxIndex::BoxEntry> boxes;
    thread_local std::vector<TraceScene::Candidate> candidates;
    thread_local std::vector<uint32_t> groups;
    thread_local std::vector<uint8_t> found;
    uint32_t queued = 0;
    if (settings_.policy == OutOfCorePolicy::kExactBatched) {
      labels.clear();
      scene_.objectBoxes().labelsAlong(s, labels);
      for (const LabelEntry& e : labels)
        if (e.label != own_mesh) builder.add(e.label, item), ++queued;
      return queued;
    }
    // Other meshes only where their proxies cannot decide.
    boxes.clear();
    scene_.objectBoxes().boxesAlong(s, boxes);
    candidates.clear();
    groups.clear();
    for (const BoxIndex::BoxEntry& b : boxes) {
      if (b.label == own_mesh) continue;
      size_t g = std::find(groups.begin(), groups.end(), b.label) - groups.begin();
      if (g == groups.size()) groups.push_back(b.label);
      candidates.push_back({b.id, uint32_t(g)});
    }
    if (candidates.empty()) return 0;
    found.assign(groups.size(), 0);
    const TraceScene* inside = scene_.insideProxies();
    if (inside && inside->crossedGroups(s, candidates, found, 1) > 0) {
      flags |= kBlocked;
      return 0;
    }
    std::fill(found.begin(), found.end(), 0);
    const TraceScene* outside = scene_.outsideProxies();
    if (outside) outside->crossedGroups(s, candidates, found, groups.size());
    // A mesh whose outside proxy the segment crosses (the proxies' answer: blocked), or without
    // an outside proxy (none, or an inside one only: it cannot be ruled out).
    for (size_t g = 0; g < groups.size(); ++g)
      if (found[g] || scene_.meshes()[groups[g]].outside < 0)
        builder.add(groups[g], item), ++queued;
    return queued;
  }

  // Pass `pass` (the batch's k-th) drawn and routed: its flags (and roulette factors) added to
  // the batch, its segments queued on the meshes they need.
  void routePass(int first_pass, int k, QueueBuilder& builder) {
    flags_.emplace_back(pixels_, uint8_t(0));
    std::vector<uint8_t>& flags = flags_.back();
    const int pass = first_pass + k;
    std::atomic<uint64_t> segments{0}, unqueued{0}, by_inside{0}, by_own{0};
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      uint64_t local_segments = 0, local_unqueued = 0, local_inside = 0, local_own = 0;
      tiling_.forEachPixel(t, [&](int, int, uint32_t pixel) {
        const uint32_t item = uint32_t(size_t(k) * pixels_ + pixel);
        PreparedSample ps;
        prepareSamples(scene_.lights(), points_[pixel], settings_.seed, pixel, pass, 1, &ps);
        if (!ps.needsVisibility()) return;
        ++local_segments;
        // Blocked by its own mesh, as the primary pass found (ownMeshShadows).
        if (ownBlocked(pixel, pass)) {
          flags[pixel] = kBlocked;
          ++local_unqueued;
          ++local_own;
          return;
        }
        if (route(ps.segment, scene_.objects()[points_[pixel].object].mesh, item, builder,
                  flags[pixel]) == 0) {
          ++local_unqueued;
          local_inside += flags[pixel] & kBlocked;
        }
      });
      segments += local_segments, unqueued += local_unqueued, by_inside += local_inside;
      by_own += local_own;
    });
    stats_.blocked_by_own_mesh += by_own;
    stats_.shadow_segments += segments;
    stats_.unqueued_segments += unqueued;
    stats_.blocked_by_inside += by_inside;
  }

  // One batch from pass `first_pass`, of at most `max_passes` passes: passes are drawn and routed
  // one by one until the next would take the batch's samples and queues over the queue cap (a
  // batch holds one pass at least). The split depends on the counts of queued pairs alone, never
  // on the threads or on what is resident. Returns the passes it rendered.
  int runBatch(int first_pass, int max_passes) {
    ++stats_.batches;
    flags_.clear();
    weighted_items_.clear();
    factors_.clear();
    QueueBuilder builder(scene_.desc().meshes.size());
    // A flag byte per sample; for proxies-roulette, a slot (item and factor) per queued sample.
    const uint64_t item_bytes = 1;
    const uint64_t pair_bytes =
        kPairBytes +
        (settings_.policy == OutOfCorePolicy::kProxiesRoulette ? 2 * sizeof(uint32_t) : 0);
    int passes = 0;
    uint64_t pairs = 0, batch_bytes = 0;
    std::vector<uint64_t> counts;
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
      weighted_items_ = builder.items();
      factors_.assign(weighted_items_.size(), 1.0f);
    }
    {
      uint64_t bytes = builder.bytes();
      for (const auto& f : flags_) bytes += f.capacity();
      bytes += weighted_items_.capacity() * sizeof(uint32_t) + factors_.capacity() * sizeof(float);
      stats_.queue_bytes = std::max(stats_.queue_bytes, bytes);
    }
    phase_growth_ = &stats_.route_rss_growth_bytes;
    endPhase();
    phase_growth_ = &stats_.trace_rss_growth_bytes;
    std::atomic<uint64_t> traces{0};
    const bool roulette = settings_.policy == OutOfCorePolicy::kProxiesRoulette;
    const double variance = settings_.learn_q ? frameVariance() : 0;
    const double seconds = settings_.learn_q ? projectedSeconds() : 0;
    for (uint32_t m : visitOrder(counts, cache_)) {
      const std::vector<uint32_t> queue = builder.take(m);
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
          continue;
        }
      }
      const Stopwatch load_clock;
      const uint64_t loads_before = cache_.stats().loads;
      const TraceScene& originals = cache_.acquire(m);
      const bool loaded = cache_.stats().loads > loads_before;
      const double load_seconds = load_clock.seconds();
      const Stopwatch trace_clock;
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
                              factorSlot(item) *= inverse_q;
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
    }
    stats_.original_traces += traces;
    endPhase();
    phase_growth_ = &stats_.route_rss_growth_bytes;
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
                         : roulette                            ? double(factorOf(item))
                                                               : 1.0;
        sums.add(ps.weight, v);
        if (settings_.learn_q) {
          const Vec3d x = Vec3d(ps.weight) * v;
          square_sums_[pixel] += x.x * x.x + x.y * x.y + x.z * x.z;
        }
      }
    });
    passes_done_ += passes;
    shadow_seconds_ = shadow_clock_.seconds();
    return passes;
  }

  // The frame's variance as LoadQLearner::q wants it (sum over pixels and channels of the pixel
  // mean's variance, times spp^2): spp x the per-sample variance, from the passes so far; 0
  // before two passes.
  double frameVariance() const {
    if (passes_done_ < 2) return 0;
    const double n = passes_done_;
    double sum = 0;
    for (size_t p = 0; p < pixels_; ++p) {
      const Vec3d mean = sums_[p].radiance / n;
      const double var =
          (square_sums_[p] / n - (mean.x * mean.x + mean.y * mean.y + mean.z * mean.z)) * n /
          (n - 1);
      sum += std::max(0.0, var);
    }
    return sum * double(settings_.spp);
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
    for (size_t i = 0; i < pixels_; ++i) {
      for (int c = 0; c < 3; ++c)
        r.radiance.pixels[i * 3 + c] = sums_[i].radianceMean(c, settings_.spp);
      r.visibility.pixels[i] = sums_[i].visibilityMean();
    }
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
  // The batch's passes: per pass and pixel, its sample's flags (kBlocked, kWrong), and for
  // proxies-roulette the product of its factors 1/q (a float: exact for q = 1/2^k, otherwise
  // within float rounding of the product).
  std::vector<std::vector<uint8_t>> flags_;
  std::vector<uint32_t> weighted_items_;  // proxies-roulette: the batch's queued samples, sorted
  std::vector<float> factors_;            // and the product of each one's factors 1/q
  std::vector<double> square_sums_;       // learned q: per pixel, the sum of its samples' |w v|^2
  LoadQLearner learner_;
  int passes_done_ = 0;
  Stopwatch shadow_clock_;
  double shadow_seconds_ = 0;
  std::vector<SampleSums> sums_;
  OutOfCoreStats stats_;
};

}  // namespace

uint64_t imageBytes(size_t pixels, const OutOfCoreSettings& settings) {
  const size_t own_bits = (size_t(std::max(settings.spp, 0)) + 63) / 64 * sizeof(uint64_t);
  return uint64_t(pixels) * (sizeof(ShadingPoint) + sizeof(SampleSums) + own_bits +
                             4 * sizeof(float) + (settings.learn_q ? sizeof(double) : 0));
}

OutOfCoreMemoryBound outOfCoreMemoryBound(uint64_t budget_bytes, uint64_t proxy_bytes,
                                          uint64_t image_bytes) {
  const double held = double(budget_bytes) + double(proxy_bytes) + double(image_bytes);
  OutOfCoreMemoryBound b;
  b.overhead_bytes = uint64_t(kOverheadShare * held);
  b.bound_bytes = uint64_t(held) + b.overhead_bytes;
  b.queue_cap_bytes = uint64_t(kQueueShare * held);
  return b;
}

OutOfCoreResult renderOutOfCore(const OutOfCoreScene& scene, const OutOfCoreSettings& settings) {
  if (settings.spp < 1) throw Error("", "--spp must be at least 1");
  if (settings.tile_size < 1 || settings.batch_passes < 0)
    throw Error("", "tile size must be at least 1 and passes per batch at least 0");
  if (!(settings.load_q > 0 && settings.load_q <= 1))
    throw Error("", fmt::format("--load-q {} is not in (0, 1]", settings.load_q));
  if (settings.policy != OutOfCorePolicy::kExactBatched && !scene.outsideProxies() &&
      !scene.insideProxies())
    throw Error(scene.desc().path.string(),
                fmt::format("--ooc-policy {} needs proxies", outOfCorePolicyName(settings.policy)),
                "no mesh of the scene has an outside or inside proxy with a proved class",
                "generate them with proxy-gen, or use --ooc-policy exact-batched");
  // A budget below one mesh's load could not hold that mesh while it is built and its queue
  // traced: the largest is named, with what it takes.
  size_t largest = 0;
  for (size_t m = 1; m < scene.meshes().size(); ++m)
    if (scene.meshes()[m].load_peak_bytes > scene.meshes()[largest].load_peak_bytes) largest = m;
  const uint64_t need = scene.meshes().empty() ? 0 : scene.meshes()[largest].load_peak_bytes;
  if (need > settings.budget_bytes)
    throw Error(
        "",
        fmt::format("--geometry-budget of {} bytes is smaller than mesh '{}' alone",
                    settings.budget_bytes, scene.desc().meshes[largest].name),
        fmt::format("its built scene takes {} bytes and {} while it is read and built; a mesh "
                    "is loaded whole",
                    scene.meshes()[largest].built_bytes, need),
        fmt::format("give at least {} bytes ({:.1f} MiB)", need, double(need) / double(1 << 20)));
  return OutOfCoreRun(scene, settings).run();
}

}  // namespace proxyvis
