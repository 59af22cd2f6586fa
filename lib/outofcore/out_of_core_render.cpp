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

using Queues = std::vector<std::vector<uint32_t>>;  // per mesh: item indices

// Per-thread (mesh, item) pairs gathered in parallel, then sorted into per-mesh queues in item
// order (the order only matters for the trace's memory access, never for an answer).
struct QueueBuilder {
  tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, uint32_t>>> pairs;
  void add(uint32_t mesh, uint32_t item) { pairs.local().emplace_back(mesh, item); }
  uint64_t into(Queues& queues) {
    uint64_t total = 0;
    for (auto& q : queues) q.clear();
    for (auto& local : pairs) {
      for (const auto& [mesh, item] : local) queues[mesh].push_back(item);
      total += local.size();
      local.clear();
    }
    for (auto& q : queues) std::sort(q.begin(), q.end());
    return total;
  }
};

// The meshes with a queue, the resident ones first (no load), then by index.
std::vector<uint32_t> visitOrder(const Queues& queues, const GeometryCache& cache) {
  std::vector<uint32_t> order;
  for (uint32_t m = 0; m < queues.size(); ++m)
    if (!queues[m].empty() && cache.resident(m)) order.push_back(m);
  for (uint32_t m = 0; m < queues.size(); ++m)
    if (!queues[m].empty() && !cache.resident(m)) order.push_back(m);
  return order;
}

class OutOfCoreRun {
 public:
  OutOfCoreRun(const OutOfCoreScene& scene, const OutOfCoreSettings& settings)
      : scene_(scene),
        settings_(settings),
        tiling_(scene.camera().width(), scene.camera().height(), settings.tile_size),
        pixels_(size_t(tiling_.width) * size_t(tiling_.height)),
        cache_(expectedBytes(scene), settings.budget_bytes,
               [&scene, cold = settings.cold_reads](uint32_t m) {
                 return scene.loadOriginal(m, cold);
               }),
        queues_(scene.desc().meshes.size()),
        learner_(scene.desc().meshes.size(), settings.q_min) {}

  OutOfCoreResult run() {
    const Stopwatch clock;
    const int batch = settings_.batch_passes > 0 ? std::min(settings_.batch_passes, settings_.spp)
                                                 : settings_.spp;
    const int batches = (settings_.spp + batch - 1) / batch;
    Progress progress("render", uint64_t(batches) + 1, settings_.quiet);
    const Stopwatch primary;
    shadePoints();
    stats_.primary_seconds = primary.seconds();
    progress.update();
    sums_.assign(pixels_, SampleSums{});
    if (settings_.learn_q) square_sums_.assign(pixels_, 0.0);
    const Stopwatch shadow;
    shadow_clock_.restart();
    for (int first = 0; first < settings_.spp; first += batch) {
      runBatch(first, std::min(batch, settings_.spp - first));
      progress.update();
    }
    stats_.shadow_seconds = shadow.seconds();
    stats_.seconds = clock.seconds();
    progress.done();
    return result();
  }

 private:
  static std::vector<uint64_t> expectedBytes(const OutOfCoreScene& scene) {
    std::vector<uint64_t> bytes;
    for (const OutOfCoreMesh& m : scene.meshes()) bytes.push_back(m.built_bytes);
    return bytes;
  }

  // Primary rays: queued on every mesh whose object boxes they enter; each mesh traced once.
  // The nearest hit wins, and of hits at the same distance the one of the lower mesh index, so
  // the answer does not depend on which meshes were resident.
  void shadePoints() {
    std::vector<Segment> rays(pixels_);
    std::vector<Hit> hits(pixels_);
    std::vector<uint32_t> hit_mesh(pixels_, std::numeric_limits<uint32_t>::max());
    own_blocked_.assign(pixels_ * size_t(settings_.spp), 0);
    points_.assign(pixels_, ShadingPoint{});  // set by ownMeshShadows, hit by hit
    QueueBuilder builder;
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      thread_local std::vector<LabelEntry> labels;
      tiling_.forEachPixel(t, [&](int x, int y, uint32_t pixel) {
        rays[pixel] = primaryRay(scene_.camera(), x, y, pixel);
        labels.clear();
        scene_.objectBoxes().labelsAlong(rays[pixel], labels);
        for (const LabelEntry& e : labels) builder.add(e.label, pixel);
      });
    });
    stats_.primary_queued = builder.into(queues_);
    for (uint32_t m : visitOrder(queues_, cache_)) {
      const TraceScene& originals = cache_.acquire(m);
      const std::vector<uint32_t>& queue = queues_[m];
      tbb::parallel_for(size_t(0), queue.size(), [&](size_t i) {
        const uint32_t pixel = queue[i];
        const Hit hit = originals.intersect(rays[pixel]);
        if (!hit.hit) return;
        if (!hits[pixel].hit || hit.t < hits[pixel].t ||
            (hit.t == hits[pixel].t && m < hit_mesh[pixel])) {
          hits[pixel] = hit;
          hit_mesh[pixel] = m;
        }
      });
      ownMeshShadows(m, originals, rays, hits, hit_mesh);
    }
  }

  // While mesh m is resident: the shading point of every pixel whose nearest hit so far is on it,
  // and every light sample of every pass of that point, traced against it. A point's own mesh (its
  // object and that mesh's other objects) is then never loaded again for its shadows; a nearer hit
  // on a mesh visited later overwrites the pixel's point and answers. The shading point and samples
  // are the ones the batches draw again (the same function of the hit, the seed, the pixel and the
  // pass), and the trace is against the same built scene, so the answers are the ones a queue would
  // give.
  void ownMeshShadows(uint32_t m, const TraceScene& originals, const std::vector<Segment>& rays,
                      const std::vector<Hit>& hits, const std::vector<uint32_t>& hit_mesh) {
    const std::vector<uint32_t>& queue = queues_[m];
    const float eps = scene_.epsilon();
    const size_t spp = size_t(settings_.spp);
    std::atomic<uint64_t> traces{0};
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, queue.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
          uint64_t local = 0;
          for (size_t i = r.begin(); i < r.end(); ++i) {
            const uint32_t pixel = queue[i];
            if (hit_mesh[pixel] != m) continue;
            const Vec3f& albedo = scene_.desc().meshes[m].albedo;
            const ShadingPoint& sp = points_[pixel] =
                shadingPointOf(rays[pixel], hits[pixel], eps, albedo);
            uint8_t* blocked = &own_blocked_[size_t(pixel) * spp];
            for (size_t pass = 0; pass < spp; ++pass) {
              PreparedSample ps;
              prepareSamples(scene_.lights(), sp, settings_.seed, pixel, int(pass), 1, &ps);
              blocked[pass] = ps.needsVisibility() && originals.occluded(ps.segment);
              local += ps.needsVisibility();
            }
          }
          traces += local;
        });
    stats_.own_mesh_traces += traces;
  }

  // Queues segment `item` (from a point on a mesh `own_mesh` object) on the other meshes it must
  // be traced against; none when the boxes or proxies decide it (`blocked` is then set if an
  // inside proxy blocks it). The own mesh was traced in the primary pass (ownMeshShadows).
  void route(const Segment& s, uint32_t own_mesh, uint32_t item, QueueBuilder& builder,
             uint8_t& blocked) {
    thread_local std::vector<LabelEntry> labels;
    thread_local std::vector<BoxIndex::BoxEntry> boxes;
    thread_local std::vector<TraceScene::Candidate> candidates;
    thread_local std::vector<uint32_t> groups;
    thread_local std::vector<uint8_t> found;
    if (settings_.policy == OutOfCorePolicy::kExactBatched) {
      labels.clear();
      scene_.objectBoxes().labelsAlong(s, labels);
      for (const LabelEntry& e : labels)
        if (e.label != own_mesh) builder.add(e.label, item);
      return;
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
    if (candidates.empty()) return;
    found.assign(groups.size(), 0);
    const TraceScene* inside = scene_.insideProxies();
    if (inside && inside->crossedGroups(s, candidates, found, 1) > 0) {
      blocked = 1;
      return;
    }
    std::fill(found.begin(), found.end(), 0);
    const TraceScene* outside = scene_.outsideProxies();
    if (outside) outside->crossedGroups(s, candidates, found, groups.size());
    // A mesh whose outside proxy the segment crosses (the proxies' answer: blocked), or without
    // an outside proxy (none, or an inside one only: it cannot be ruled out).
    for (size_t g = 0; g < groups.size(); ++g)
      if (found[g] || scene_.meshes()[groups[g]].outside < 0) builder.add(groups[g], item);
  }

  void runBatch(int first_pass, int passes) {
    ++stats_.batches;
    const size_t n = pixels_ * size_t(passes);
    samples_.resize(n);
    blocked_.assign(n, 0);
    factor_.assign(n, 1.0);
    wrong_.assign(n, 0);
    QueueBuilder builder;
    std::atomic<uint64_t> segments{0}, unqueued{0}, by_inside{0}, by_own{0};
    const size_t spp = size_t(settings_.spp);
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      uint64_t local_segments = 0, local_unqueued = 0, local_inside = 0, local_own = 0;
      tiling_.forEachPixel(t, [&](int, int, uint32_t pixel) {
        for (int k = 0; k < passes; ++k) {
          const uint32_t item = uint32_t(size_t(k) * pixels_ + pixel);
          PreparedSample& ps = samples_[item];
          prepareSamples(scene_.lights(), points_[pixel], settings_.seed, pixel, first_pass + k, 1,
                         &ps);
          if (!ps.needsVisibility()) continue;
          ++local_segments;
          // Blocked by its own mesh, as the primary pass found (ownMeshShadows).
          if (own_blocked_[size_t(pixel) * spp + size_t(first_pass + k)]) {
            blocked_[item] = 1;
            ++local_unqueued;
            ++local_own;
            continue;
          }
          const size_t before = builder.pairs.local().size();
          route(ps.segment, scene_.objects()[points_[pixel].object].mesh, item, builder,
                blocked_[item]);
          if (builder.pairs.local().size() == before) {
            ++local_unqueued;
            local_inside += blocked_[item];
          }
        }
      });
      segments += local_segments, unqueued += local_unqueued, by_inside += local_inside;
      by_own += local_own;
    });
    stats_.blocked_by_own_mesh += by_own;
    stats_.shadow_segments += segments;
    stats_.unqueued_segments += unqueued;
    stats_.blocked_by_inside += by_inside;
    stats_.queued += builder.into(queues_);
    std::atomic<uint64_t> traces{0};
    const bool roulette = settings_.policy == OutOfCorePolicy::kProxiesRoulette;
    const double variance = settings_.learn_q ? frameVariance() : 0;
    const double seconds = settings_.learn_q ? projectedSeconds() : 0;
    for (uint32_t m : visitOrder(queues_, cache_)) {
      const std::vector<uint32_t>& queue = queues_[m];
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
          for (uint32_t item : queue) blocked_[item] = 1;
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
      tbb::parallel_for(tbb::blocked_range<size_t>(0, queue.size(), 256),
                        [&](const tbb::blocked_range<size_t>& r) {
                          uint64_t local = 0;
                          for (size_t i = r.begin(); i < r.end(); ++i) {
                            const uint32_t item = queue[i];
                            if (blocked_[item]) continue;
                            ++local;
                            // The proxies' answer v' is 0 (blocked) for every queued segment.
                            const bool v = !originals.occluded(samples_[item].segment);
                            if (has_proxy_answer) wrong_[item] = v;
                            if (!v)
                              blocked_[item] = 1;
                            else if (weighted)
                              factor_[item] *= 1.0 / q;  // v' + (v - v') / q with v' = 0, v = 1
                          }
                          traces += local;
                        });
      ++stats_.traced_queues;
      if (has_proxy_answer) {
        // Summed in queue order: the same bits at any thread count.
        double w2 = 0, signed_sum = 0;
        for (uint32_t item : queue) {
          if (!wrong_[item]) continue;
          wrong_[item] = 0;
          const Vec3f& w = samples_[item].weight;
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
    // Accumulated pass by pass, as the in-core renderer does: the same sums, bit for bit.
    tbb::parallel_for(size_t(0), pixels_, [&](size_t pixel) {
      SampleSums& sums = sums_[pixel];
      for (int k = 0; k < passes; ++k) {
        const size_t item = size_t(k) * pixels_ + pixel;
        const PreparedSample& ps = samples_[item];
        if (!ps.needsVisibility()) continue;  // also every sample of a pixel without a point
        // The product of the roulette's factors, multiplied in the meshes' visit order, which
        // depends on the batches alone (never on the threads).
        const double v = blocked_[item] ? 0.0 : factor_[item];
        sums.add(ps.weight, v);
        if (settings_.learn_q) {
          const Vec3d x = Vec3d(ps.weight) * v;
          square_sums_[pixel] += x.x * x.x + x.y * x.y + x.z * x.z;
        }
      }
    });
    passes_done_ += passes;
    shadow_seconds_ = shadow_clock_.seconds();
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
    stats_.peak_rss_bytes = peakRssBytes();
    r.stats = stats_;
    return r;
  }

  const OutOfCoreScene& scene_;
  const OutOfCoreSettings& settings_;
  const Tiling tiling_;
  const size_t pixels_;
  GeometryCache cache_;
  Queues queues_;
  std::vector<ShadingPoint> points_;
  std::vector<PreparedSample> samples_;
  std::vector<uint8_t> blocked_;
  std::vector<double> factor_;        // proxies-roulette: the product of a segment's factors
  std::vector<uint8_t> own_blocked_;  // per pixel and pass: blocked by its own mesh
  std::vector<uint8_t> wrong_;        // the proxies' answer was wrong for the mesh being traced
  std::vector<double> square_sums_;   // learned q: per pixel, the sum of its samples' |w v|^2
  LoadQLearner learner_;
  int passes_done_ = 0;
  Stopwatch shadow_clock_;
  double shadow_seconds_ = 0;
  std::vector<SampleSums> sums_;
  OutOfCoreStats stats_;
};

}  // namespace

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
  // A budget below one mesh's built scene could not hold that mesh while its queue is traced:
  // the largest is named, with what it takes.
  size_t largest = 0;
  for (size_t m = 1; m < scene.meshes().size(); ++m)
    if (scene.meshes()[m].built_bytes > scene.meshes()[largest].built_bytes) largest = m;
  const uint64_t need = scene.meshes().empty() ? 0 : scene.meshes()[largest].built_bytes;
  if (need > settings.budget_bytes)
    throw Error(
        "",
        fmt::format("--geometry-budget of {} bytes is smaller than mesh '{}' alone",
                    settings.budget_bytes, scene.desc().meshes[largest].name),
        fmt::format("its built scene takes {} bytes, and a mesh is loaded whole", need),
        fmt::format("give at least {} bytes ({:.1f} MiB)", need, double(need) / double(1 << 20)));
  return OutOfCoreRun(scene, settings).run();
}

}  // namespace proxyvis
