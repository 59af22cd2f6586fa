// The data-parallel render loop (contract in data_parallel_render.h).
#include "distributed/data_parallel_render.h"

#include <sys/resource.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>

#include "distributed/exchange_ledger.h"
#include "distributed/forwarding_round.h"
#include "distributed/roulette_forwarding.h"
#include "distributed/round_model.h"
#include "distributed/route_choice.h"
#include "render/integrator_steps.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

// The streams of roulette's forwarding choice and of the route's choice for (pixel, pass): apart
// from the light sample's.
constexpr uint64_t kRouletteStream = 7;
constexpr uint64_t kRouteStream = 8;

struct PixelSums : SampleSums {
  uint32_t forwards = 0;
};

// Summed over ranks at the end.
// clang-format off
enum Count : size_t {
  kSegments, kLocal, kInside, kUndecidedCount, kForwarded, kBytes,
  kMessages, kForwards, kShaded, kRoutedProxies, kRoutedBoxes, kNumCounts
};
// clang-format on

// One rank's render, phase by phase (the steps of data_parallel_render.h).
class RankRender {
 public:
  RankRender(const DistributedScene& scene, const DataParallelSettings& settings,
             const MpiComm& comm)
      : scene_(scene),
        settings_(settings),
        comm_(comm),
        rank_(comm.rank()),
        ranks_(comm.size()),
        width_(scene.camera().width()),
        height_(scene.camera().height()),
        num_pixels_(size_t(width_) * size_t(height_)),
        tiling_(width_, height_, settings.tile_size),
        num_lights_(scene.lights().numLights()),
        slots_(std::max(1, ranks_ - 1)),
        learner_(size_t(tiling_.count()) * num_lights_, settings.q_min),
        routes_(size_t(tiling_.count()) * num_lights_, settings.proxy_route),
        cpu_start_(processCpuSeconds()) {
    stats_.ranks = ranks_;
  }

  DataParallelResult run() {
    shadePrimaryRays();
    sums_.assign(owned_.size(), {});
    const uint64_t total_rounds =
        uint64_t((settings_.spp + settings_.passes_per_round - 1) / settings_.passes_per_round);
    Progress progress("render (data-parallel)", total_rounds, settings_.quiet || rank_ != 0);
    for (int start = 0; start < settings_.spp; start += settings_.passes_per_round) {
      const int count = std::min(settings_.passes_per_round, settings_.spp - start);
      const std::vector<double> q =
          learner_.probabilities(settings_.forward_cost_us, settings_.local_cost_us);
      prepareRound(start, count, q);
      forwardPending();
      addRound(count, q);
      const double forward_us = ledger_.forwardCostUs(settings_.network);
      learner_.setMeasuredCosts(my_segments_ ? 1e6 * computeCpu() / double(my_segments_) : 1.0,
                                forward_us);
      const int threads = tbb::this_task_arena::max_concurrency();
      routes_.update(ledger_.routeForwardCostUs(settings_.network, threads), threads);
      progress.update();
    }
    progress.done();
    DataParallelResult result = reduceImages();
    result.stats = reduceStats();
    return result;
  }

 private:
  // Compute time is the process CPU time outside MPI calls (Open MPI polls while it waits), so
  // that ranks sharing cores (more ranks than cores on a test machine) are not charged for the
  // time another rank ran. The model's compute is wall time outside MPI calls: what a round
  // waits for on the machine that ran it.
  template <typename Call>
  void timed(Call&& call) {
    const double c = processCpuSeconds(), w = clock_.seconds();
    call();
    mpi_cpu_ += processCpuSeconds() - c;
    mpi_wall_ += clock_.seconds() - w;
  }
  double computeCpu() const { return processCpuSeconds() - cpu_start_ - mpi_cpu_; }
  double computeWall() const { return clock_.seconds() - mpi_wall_; }

  // A reduction of `bytes` bytes per rank: with an emulated fabric it ends no earlier than the
  // fabric's tree of messages would (from this rank's entry).
  template <typename Call>
  void reduction(uint64_t bytes, Call&& call) {
    const double entered = steadySeconds();
    timed([&] {
      call();
      if (settings_.emulate && ranks_ > 1)
        emulated_wait_ +=
            waitUntilSteady(entered + settings_.network.reductionSeconds(ranks_, bytes));
    });
    reduction_seconds_ += ranks_ > 1 ? settings_.network.reductionSeconds(ranks_, bytes) : 0.0;
  }

  // 1. Primary rays, composited by the closest hit over ranks: the pixels this rank shades.
  void shadePrimaryRays() {
    std::vector<Segment> rays(num_pixels_);
    std::vector<Hit> hits(num_pixels_);
    std::vector<MpiComm::ValueKey> best(num_pixels_);
    pixel_tile_.assign(num_pixels_, 0);
    tbb::parallel_for(0, tiling_.count(), [&](int t) {
      tiling_.forEachPixel(t, [&](int x, int y, uint32_t pixel) {
        pixel_tile_[pixel] = uint32_t(t);
        rays[pixel] = primaryRay(scene_.camera(), x, y, pixel);
        hits[pixel] = scene_.intersectLocal(rays[pixel]);
        MpiComm::ValueKey& b = best[pixel];
        if (!hits[pixel].hit) {
          b = {std::numeric_limits<float>::infinity(), INT_MAX};
          return;
        }
        const int owner = scene_.owners()[hits[pixel].user_id];
        b = {hits[pixel].t, owner >= 0 ? owner : t % ranks_};
      });
    });
    const std::vector<MpiComm::ValueKey> mine = best;
    reduction(sizeof(MpiComm::ValueKey) * num_pixels_, [&] { comm_.minLoc(best); });
    for (uint32_t p = 0; p < num_pixels_; ++p) {
      if (best[p].key != rank_ || best[p].value != mine[p].value || mine[p].key != rank_) continue;
      const Hit& h = hits[p];
      owned_.push_back(p);
      points_.push_back(
          shadingPointOf(rays[p], h, scene_.epsilon(),
                         scene_.desc().meshes[scene_.objects()[h.user_id].mesh].albedo));
    }
  }

  // 2. The light samples of passes [start, start + count) for every owned pixel, traced locally
  // and routed: decided here, or pending with the ranks to ask.
  void prepareRound(int start, int count, const std::vector<double>& q) {
    RoundEntries& r = round_;
    const size_t n = owned_.size() * size_t(count);
    r.reset(n, size_t(slots_));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, owned_.size(), 64),
                      [&](const tbb::blocked_range<size_t>& range) {
                        Scratch scratch;
                        for (size_t i = range.begin(); i != range.end(); ++i)
                          for (int j = 0; j < count; ++j)
                            prepareEntry(i, i * size_t(count) + size_t(j), start + j, q, scratch);
                      });
  }

  struct Scratch {
    std::vector<LabelEntry> labels;
    Route route;
  };

  // Entry e: owned pixel i's light sample of `pass`.
  void prepareEntry(size_t i, size_t e, int pass, const std::vector<double>& q, Scratch& scratch) {
    RoundEntries& r = round_;
    const uint32_t pixel = owned_[i];
    PreparedSample& ps = r.samples[e];
    prepareSamples(scene_.lights(), points_[i], settings_.seed, pixel, pass, 1, &ps);
    if (!ps.needsVisibility()) return;
    r.region[e] = pixel_tile_[pixel] * uint32_t(num_lights_) + ps.light;
    r.state[e] = kDecided;
    if (scene_.locallyOccluded(ps.segment)) return;  // V = 0
    Route& route = scratch.route;
    Forwarding policy = settings_.forwarding;
    bool timed = false;  // only a measured route choice times routes
    if (policy == Forwarding::kProxies) {
      r.via_proxies[e] = 1;
      if (settings_.proxy_route == ProxyRoute::kMeasured) {
        const uint64_t key = hashKeys(pixel, uint64_t(pass), kRouteStream);
        r.via_proxies[e] = routes_.useProxies(r.region[e], key) ? 1 : 0;
        if (!r.via_proxies[e]) policy = Forwarding::kInstanceBoxes;
        timed = RouteChoice::timed(key);
      }
    }
    const double t0 = timed ? steadySeconds() : 0.0;
    scene_.route(policy, ps.segment, scratch.labels, route);
    if (timed) r.route_seconds[e] = float(steadySeconds() - t0);
    if (route.blocked_by_inside) {  // V = 0, proved by an inside proxy
      r.outcome[e] = kBlockedByInside;
      return;
    }
    if (route.ranks.empty()) {
      r.outcome[e] = kNoRemoteRank;
      r.estimate[e] = 1.0;
      return;
    }
    r.outcome[e] = kUndecided;
    if (settings_.roulette) {
      const double qe = q[r.region[e]];
      Rng rng(settings_.seed, hashKeys(pixel, uint64_t(pass), kRouletteStream));
      if (!(rng.uniformDouble() < qe)) return;  // the proxies' answer: blocked
      r.weight[e] = 1.0 / qe;
    }
    r.forwarded[e] = 1;
    r.state[e] = kPending;
    r.num_candidates[e] = uint8_t(route.ranks.size());
    std::copy(route.ranks.begin(), route.ranks.end(),
              r.candidates.begin() + long(e * size_t(slots_)));
  }

  // 3. Forwarding rounds: each pending segment goes to its next candidate until one blocks it.
  void forwardPending() {
    RoundEntries& r = round_;
    std::vector<uint32_t> pending;
    for (size_t e = 0; e < r.state.size(); ++e)
      if (r.state[e] == kPending) pending.push_back(uint32_t(e));
    auto outbox = std::vector<std::vector<uint8_t>>(size_t(ranks_));
    std::vector<std::vector<uint8_t>> replies;
    auto sent = std::vector<std::vector<uint32_t>>(size_t(ranks_));
    ledger_.startBatch();
    for (;;) {
      for (auto& o : outbox) o.clear();
      for (auto& s : sent) s.clear();
      for (uint32_t e : pending) {
        const uint16_t to = r.candidates[size_t(e) * size_t(slots_) + r.next[e]];
        const auto* bytes = reinterpret_cast<const uint8_t*>(&r.samples[e].segment);
        outbox[to].insert(outbox[to].end(), bytes, bytes + sizeof(Segment));
        sent[to].push_back(e);
      }
      MpiComm::RoundStats round;
      timed([&] {
        round = comm_.exchange(outbox, sizeof(Segment), pending.size(), answerRequests,
                               const_cast<DistributedScene*>(&scene_), replies,
                               settings_.emulate ? &settings_.network : nullptr);
      });
      mpi_cpu_ -= round.answer_cpu_seconds;  // answering is compute
      mpi_wall_ -= round.answer_seconds;
      ledger_.record(round, computeWall());
      ++stats_.rounds;
      if (round.open_total == 0) break;
      pending.clear();
      for (int to = 0; to < ranks_; ++to) {
        for (size_t k = 0; k < sent[size_t(to)].size(); ++k) {
          const uint32_t e = sent[size_t(to)][k];
          ++r.forwards[e];
          if (replies[size_t(to)][k]) {
            r.estimate[e] = 0.0;
            r.state[e] = kDecided;
          } else if (++r.next[e] == r.num_candidates[e]) {
            r.estimate[e] = r.weight[e];
            r.state[e] = kDecided;
          } else {
            pending.push_back(e);
          }
        }
      }
      std::sort(pending.begin(), pending.end());
    }
  }

  // 4. Pixel sums in pass order, as the single-process renderer adds them; counts and learning.
  void addRound(int count, const std::vector<double>& q) {
    const RoundEntries& r = round_;
    tbb::parallel_for(size_t(0), owned_.size(), [&](size_t i) {
      PixelSums& s = sums_[i];
      for (int j = 0; j < count; ++j) {
        const size_t e = i * size_t(count) + size_t(j);
        if (r.state[e] == kNoVisibility) continue;
        s.add(r.samples[e].weight, r.estimate[e]);
        s.forwards += r.forwards[e];
      }
    });
    for (size_t e = 0; e < r.state.size(); ++e) {
      if (r.state[e] == kNoVisibility) continue;
      ++my_segments_;
      const bool undecided = r.outcome[e] == kUndecided;
      counts_[kSegments] += 1;
      counts_[kLocal] += r.outcome[e] == kBlockedLocally;
      counts_[kInside] += r.outcome[e] == kBlockedByInside;
      counts_[kUndecidedCount] += undecided;
      counts_[kForwarded] += r.forwarded[e];
      if (undecided && settings_.roulette) {
        q_sum_ += q[r.region[e]];
        ++q_count_;
      }
      learner_.add(r.region[e], r.estimate[e], undecided, r.forwarded[e] != 0, r.forwards[e],
                   r.forwarded[e] && r.estimate[e] > 0);
      if (settings_.forwarding == Forwarding::kProxies && r.outcome[e] != kBlockedLocally)
        routes_.add(r.region[e], r.via_proxies[e] != 0, r.route_seconds[e], r.forwards[e]);
    }
  }

  // The image, reduced to rank 0 (every pixel is non-zero on one rank at most).
  DataParallelResult reduceImages() {
    DataParallelResult result;
    result.spp = settings_.spp;
    Image radiance{width_, height_, 3, std::vector<float>(num_pixels_ * 3, 0.0f)};
    Image visibility{width_, height_, 1, std::vector<float>(num_pixels_, 0.0f)};
    Image forwards{width_, height_, 1, std::vector<float>(num_pixels_, 0.0f)};
    Image owner{width_, height_, 1, std::vector<float>(num_pixels_, 0.0f)};
    for (size_t i = 0; i < owned_.size(); ++i) {
      const size_t p = owned_[i];
      const PixelSums& s = sums_[i];
      s.writeMeans(settings_.spp, &radiance.pixels[p * 3], &visibility.pixels[p]);
      forwards.pixels[p] = float(s.forwards);
      owner.pixels[p] = float(rank_ + 1);
    }
    compute_seconds_ = computeCpu() / double(tbb::this_task_arena::max_concurrency());
    tail_wall_ = computeWall() - ledger_.lastRoundWall();
    reduction(sizeof(float) * 6 * num_pixels_, [&] {
      comm_.sum(radiance.pixels, true);
      comm_.sum(visibility.pixels, true);
      comm_.sum(forwards.pixels, true);
      comm_.sum(owner.pixels, true);
    });
    render_seconds_ = clock_.seconds();
    if (rank_ == 0) {
      result.radiance = std::move(radiance);
      result.visibility = std::move(visibility);
      result.forwards = std::move(forwards);
      result.owner = std::move(owner);
    }
    return result;
  }

  // Statistics over ranks.
  DataParallelStats reduceStats() {
    DataParallelStats stats = stats_;
    counts_[kForwards] = ledger_.itemsSent();
    counts_[kBytes] = ledger_.bytesSent();
    counts_[kMessages] = ledger_.messagesSent();
    counts_[kShaded] = owned_.size();
    counts_[kRoutedProxies] = routes_.routedByProxies();
    counts_[kRoutedBoxes] = routes_.routedByBoxes();
    std::vector<uint64_t> totals(counts_.begin(), counts_.end());
    comm_.sum(totals);
    stats.shadow_segments = totals[kSegments];
    stats.blocked_locally = totals[kLocal];
    stats.blocked_by_inside = totals[kInside];
    stats.undecided = totals[kUndecidedCount];
    stats.forwarded_segments = totals[kForwarded];
    stats.forward_bytes = totals[kBytes];
    stats.forward_messages = totals[kMessages];
    stats.forwards = totals[kForwards];
    stats.pixels_shaded = totals[kShaded];
    stats.routed_by_proxies = totals[kRoutedProxies];
    stats.routed_by_boxes = totals[kRoutedBoxes];
    stats.proxy_route = settings_.proxy_route;
    std::vector<uint64_t> per_rank(size_t(ranks_) * 2, 0);
    per_rank[size_t(rank_)] = peakRssBytes();
    per_rank[size_t(ranks_ + rank_)] = owned_.size();
    comm_.sum(per_rank);
    stats.rank_rss_bytes.assign(per_rank.begin(), per_rank.begin() + ranks_);
    stats.rank_shaded_pixels.assign(per_rank.begin() + ranks_, per_rank.end());
    stats.rank_peak_rss_bytes =
        *std::max_element(stats.rank_rss_bytes.begin(), stats.rank_rss_bytes.end());
    std::vector<uint64_t> busiest = {ledger_.itemsSent(), ledger_.bytesSent(),
                                     ledger_.messagesSent()};
    comm_.max(busiest);
    stats.max_rank_forwards = busiest[0];
    stats.max_rank_forward_bytes = busiest[1];
    stats.max_rank_forward_messages = busiest[2];
    // The render ends with the image on rank 0; the statistics' reductions are not part of it.
    std::vector<double> times = {compute_seconds_, ledger_.exchangeSeconds(), render_seconds_};
    comm_.max(times);
    stats.max_compute_seconds = times[0];
    stats.max_exchange_seconds = times[1];
    stats.seconds = times[2];
    std::vector<double> q_sums = {q_sum_, double(q_count_)};
    comm_.sum(q_sums);
    stats.mean_q = q_sums[1] > 0 ? q_sums[0] / q_sums[1] : 1.0;
    modelRun(stats);
    return stats;
  }

  // The alpha-beta model of the run from every rank's per-round loads; the emulated waits.
  void modelRun(DataParallelStats& stats) {
    stats.network = settings_.network;
    stats.modelled =
        modelAcrossRanks(settings_.network, ledger_.loads(), tail_wall_, reduction_seconds_, comm_);
    std::vector<double> wait = {emulated_wait_ + ledger_.emulatedWaitSeconds()};
    comm_.max(wait);
    stats.max_emulated_wait_seconds = wait[0];
    stats.emulated = settings_.emulate && wait[0] > 0;
  }

  const DistributedScene& scene_;
  const DataParallelSettings& settings_;
  const MpiComm& comm_;
  const int rank_, ranks_;
  const int width_, height_;
  const size_t num_pixels_;
  const Tiling tiling_;
  const size_t num_lights_;
  const int slots_;  // candidate ranks per entry
  RouletteForwarding learner_;
  RouteChoice routes_;
  const Stopwatch clock_;
  const double cpu_start_;
  double mpi_cpu_ = 0, compute_seconds_ = 0;
  double mpi_wall_ = 0, emulated_wait_ = 0, reduction_seconds_ = 0;  // emulated: reductions'
  ExchangeLedger ledger_;
  double tail_wall_ = 0, render_seconds_ = 0;  // work after the last round; the render's time

  std::vector<uint32_t> pixel_tile_;  // per pixel: its screen tile
  std::vector<uint32_t> owned_;       // the pixels this rank shades, ascending
  std::vector<ShadingPoint> points_;  // their shading points
  std::vector<PixelSums> sums_;       // per owned pixel
  RoundEntries round_;
  DataParallelStats stats_;
  std::array<uint64_t, kNumCounts> counts_{};
  double q_sum_ = 0;
  uint64_t q_count_ = 0;
  uint64_t my_segments_ = 0;
};

}  // namespace

DataParallelResult renderDataParallel(const DistributedScene& scene,
                                      const DataParallelSettings& settings, const MpiComm& comm) {
  if (settings.spp < 1) throw Error("", "--spp must be at least 1 for a data-parallel render");
  if (settings.tile_size < 1 || settings.passes_per_round < 1)
    throw Error("", "tile size and passes per round must be at least 1");
  if (settings.forwarding == Forwarding::kProxies && !scene.hasProxyForwarding())
    throw Error("", "--forwarding proxies needs the scene loaded with its proxies");
  if (settings.network.name == "shm" && settings.network.measured &&
      !(settings.network.beta_gbps > 0) && comm.size() > 1)
    throw Error("", "the shared-memory fabric was not measured before the render");
  static_assert(sizeof(Segment) == 32, "the request format is 8 floats");
  return RankRender(scene, settings, comm).run();
}

}  // namespace proxyvis
