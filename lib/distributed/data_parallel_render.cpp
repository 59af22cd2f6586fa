// The data-parallel render loop (contract in data_parallel_render.h).
#include "distributed/data_parallel_render.h"

#include <sys/resource.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>

#include "distributed/roulette_forwarding.h"
#include "render/internal/integrator.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

using detail::PreparedSample;
using detail::ShadingPoint;
using detail::Tiling;

namespace {

// The stream of roulette's forwarding choice for (pixel, pass): apart from the light sample's.
constexpr uint64_t kRouletteStream = 7;

enum : uint8_t { kNoVisibility = 0, kDecided = 1, kPending = 2 };
// How a segment was decided before any forward.
enum Outcome : uint8_t { kBlockedLocally, kBlockedByInside, kNoRemoteRank, kUndecided };

struct PixelSums {
  Vec3d radiance;
  double vis_sum = 0;
  uint32_t vis_n = 0;
  uint32_t forwards = 0;
};

// The entries of one round: light samples of `count` passes for every pixel this rank shades.
struct RoundEntries {
  std::vector<PreparedSample> samples;
  std::vector<uint8_t> state;
  std::vector<double> estimate;  // V~ once decided
  std::vector<double> weight;    // what a visible answer is worth: 1, or 1/q under roulette
  std::vector<uint8_t> outcome;  // Outcome, once the local trace and the route are known
  std::vector<uint8_t> forwarded;
  std::vector<uint16_t> forwards;    // ranks asked so far
  std::vector<uint16_t> candidates;  // (ranks - 1) slots per entry
  std::vector<uint8_t> num_candidates, next;
  std::vector<uint32_t> region;
};

// A forwarded segment's answer: 1 if this rank's own originals block it. `context` is the scene.
void answerRequests(void* context, const uint8_t* requests, size_t count, uint8_t* answers) {
  const auto* scene = static_cast<const DistributedScene*>(context);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        Segment s;
                        std::memcpy(&s, requests + i * sizeof(Segment), sizeof(Segment));
                        answers[i] = scene->ownOccluded(s) ? 1 : 0;
                      }
                    });
}

}  // namespace

uint64_t peakRssBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024u;
}

DataParallelResult renderDataParallel(const DistributedScene& scene,
                                      const DataParallelSettings& settings, const MpiComm& comm) {
  if (settings.spp < 1) throw Error("", "--spp must be at least 1 for a data-parallel render");
  if (settings.tile_size < 1 || settings.passes_per_round < 1)
    throw Error("", "tile size and passes per round must be at least 1");
  if (settings.forwarding == Forwarding::kProxies && !scene.hasProxyForwarding())
    throw Error("", "--forwarding proxies needs the scene loaded with its proxies");
  static_assert(sizeof(Segment) == 32, "the request format is 8 floats");
  // Compute time is the process CPU time outside MPI calls (Open MPI polls while it waits), so
  // that ranks sharing cores (more ranks than cores on a test machine) are not charged for the
  // time another rank ran.
  const Stopwatch clock;
  const double cpu_start = processCpuSeconds();
  double mpi_cpu = 0;
  auto timed = [&](auto&& call) {
    const double c = processCpuSeconds();
    call();
    mpi_cpu += processCpuSeconds() - c;
  };
  auto computeCpu = [&] { return processCpuSeconds() - cpu_start - mpi_cpu; };

  const int rank = comm.rank(), ranks = comm.size();
  const int width = scene.camera().width(), height = scene.camera().height();
  const size_t num_pixels = size_t(width) * size_t(height);
  const Tiling tiling(width, height, settings.tile_size);

  // 1. Primary rays, composited by the closest hit over ranks.
  std::vector<Segment> rays(num_pixels);
  std::vector<Hit> hits(num_pixels);
  std::vector<MpiComm::ValueKey> best(num_pixels);
  std::vector<uint32_t> pixel_tile(num_pixels);
  tbb::parallel_for(0, tiling.count(), [&](int t) {
    tiling.forEachPixel(t, [&](int x, int y, uint32_t pixel) {
      pixel_tile[pixel] = uint32_t(t);
      rays[pixel] = detail::primaryRay(scene.camera(), x, y, pixel);
      hits[pixel] = scene.intersectLocal(rays[pixel]);
      MpiComm::ValueKey& b = best[pixel];
      if (!hits[pixel].hit) {
        b = {std::numeric_limits<float>::infinity(), INT_MAX};
        return;
      }
      const int owner = scene.owners()[hits[pixel].user_id];
      b = {hits[pixel].t, owner >= 0 ? owner : t % ranks};
    });
  });
  const std::vector<MpiComm::ValueKey> mine = best;
  timed([&] { comm.minLoc(best); });
  std::vector<uint32_t> owned;
  std::vector<ShadingPoint> points;
  for (uint32_t p = 0; p < num_pixels; ++p) {
    if (best[p].key != rank || best[p].value != mine[p].value || mine[p].key != rank) continue;
    const Hit& h = hits[p];
    owned.push_back(p);
    points.push_back(detail::shadingPointOf(
        rays[p], h, scene.epsilon(), scene.desc().meshes[scene.objects()[h.user_id].mesh].albedo));
  }
  rays = {};
  hits = {};

  // 2. Light samples in rounds of passes.
  const size_t num_lights = scene.lights().numLights();
  const int slots = std::max(1, ranks - 1);
  RouletteForwarding learner(size_t(tiling.count()) * num_lights, settings.q_min);
  std::vector<PixelSums> sums(owned.size());
  DataParallelStats stats;
  stats.ranks = ranks;
  // Summed over ranks at the end: segments, blocked locally, blocked by inside proxies, undecided,
  // forwarded, bytes, messages, forwards, pixels shaded.
  std::vector<uint64_t> counts(9, 0);
  double q_sum = 0;
  uint64_t q_count = 0;
  uint64_t my_forwards = 0, my_segments = 0;
  double exchange_seconds = 0;
  const uint64_t total_rounds =
      uint64_t((settings.spp + settings.passes_per_round - 1) / settings.passes_per_round);
  Progress progress("render (data-parallel)", total_rounds, settings.quiet || rank != 0);
  RoundEntries r;
  for (int start = 0; start < settings.spp; start += settings.passes_per_round) {
    const int count = std::min(settings.passes_per_round, settings.spp - start);
    const size_t n = owned.size() * size_t(count);
    r.samples.assign(n, {});
    r.state.assign(n, kNoVisibility);
    r.estimate.assign(n, 0.0);
    r.weight.assign(n, 1.0);
    r.outcome.assign(n, kBlockedLocally);
    r.forwarded.assign(n, 0);
    r.forwards.assign(n, 0);
    r.candidates.assign(n * size_t(slots), 0);
    r.num_candidates.assign(n, 0);
    r.next.assign(n, 0);
    r.region.assign(n, 0);
    std::vector<double> q = learner.probabilities(settings.forward_cost_us, settings.local_cost_us);

    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, owned.size(), 64),
        [&](const tbb::blocked_range<size_t>& range) {
          std::vector<LabelEntry> scratch;
          std::vector<TraceScene::UserHit> user_hits;
          Route route;
          for (size_t i = range.begin(); i != range.end(); ++i) {
            const uint32_t pixel = owned[i];
            for (int j = 0; j < count; ++j) {
              const size_t e = i * size_t(count) + size_t(j);
              const int pass = start + j;
              PreparedSample& ps = r.samples[e];
              detail::prepareSamples(scene.lights(), points[i], settings.seed, pixel, pass, 1, &ps);
              if (!(ps.weight.x > 0 || ps.weight.y > 0 || ps.weight.z > 0)) continue;
              r.region[e] = pixel_tile[pixel] * uint32_t(num_lights) + ps.light;
              r.state[e] = kDecided;
              if (scene.locallyOccluded(ps.segment)) continue;  // V = 0
              scene.route(settings.forwarding, ps.segment, scratch, user_hits, route);
              if (route.blocked_by_inside) {  // V = 0, proved by an inside proxy
                r.outcome[e] = kBlockedByInside;
                continue;
              }
              if (route.ranks.empty()) {
                r.outcome[e] = kNoRemoteRank;
                r.estimate[e] = 1.0;
                continue;
              }
              r.outcome[e] = kUndecided;
              if (settings.roulette) {
                const double qe = q[r.region[e]];
                Rng rng(settings.seed, hashKeys(pixel, uint64_t(pass), kRouletteStream));
                if (!(rng.uniformDouble() < qe)) continue;  // the proxies' answer: blocked
                r.weight[e] = 1.0 / qe;
              }
              r.forwarded[e] = 1;
              r.state[e] = kPending;
              r.num_candidates[e] = uint8_t(route.ranks.size());
              std::copy(route.ranks.begin(), route.ranks.end(),
                        r.candidates.begin() + long(e * size_t(slots)));
            }
          }
        });

    // Forwarding rounds: each pending segment goes to its next candidate until one blocks it.
    std::vector<uint32_t> pending;
    for (size_t e = 0; e < n; ++e)
      if (r.state[e] == kPending) pending.push_back(uint32_t(e));
    auto outbox = std::vector<std::vector<uint8_t>>(size_t(ranks));
    std::vector<std::vector<uint8_t>> replies;
    auto sent = std::vector<std::vector<uint32_t>>(size_t(ranks));
    for (;;) {
      uint64_t open = pending.size();
      timed([&] { comm.sum(std::span<uint64_t>(&open, 1)); });
      if (open == 0) break;
      for (auto& o : outbox) o.clear();
      for (auto& s : sent) s.clear();
      for (uint32_t e : pending) {
        const uint16_t to = r.candidates[size_t(e) * size_t(slots) + r.next[e]];
        const auto* bytes = reinterpret_cast<const uint8_t*>(&r.samples[e].segment);
        outbox[to].insert(outbox[to].end(), bytes, bytes + sizeof(Segment));
        sent[to].push_back(e);
      }
      MpiComm::RoundStats round;
      timed([&] {
        round = comm.exchange(outbox, sizeof(Segment), answerRequests,
                              const_cast<DistributedScene*>(&scene), replies);
      });
      mpi_cpu -= round.answer_cpu_seconds;  // answering is compute
      exchange_seconds += round.seconds;
      my_forwards += round.items_sent;
      counts[5] += round.bytes_sent;
      counts[6] += round.messages_sent;
      ++stats.rounds;
      pending.clear();
      for (int to = 0; to < ranks; ++to) {
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

    // Pixel sums in pass order, as the single-process renderer adds them.
    tbb::parallel_for(size_t(0), owned.size(), [&](size_t i) {
      PixelSums& s = sums[i];
      for (int j = 0; j < count; ++j) {
        const size_t e = i * size_t(count) + size_t(j);
        if (r.state[e] == kNoVisibility) continue;
        const double v = r.estimate[e];
        s.radiance += Vec3d(r.samples[e].weight) * v;
        s.vis_sum += v;
        s.vis_n += 1;
        s.forwards += r.forwards[e];
      }
    });
    for (size_t e = 0; e < n; ++e) {
      if (r.state[e] == kNoVisibility) continue;
      ++my_segments;
      const bool undecided = r.outcome[e] == kUndecided;
      counts[0] += 1;
      counts[1] += r.outcome[e] == kBlockedLocally;
      counts[2] += r.outcome[e] == kBlockedByInside;
      counts[3] += undecided;
      counts[4] += r.forwarded[e];
      if (undecided && settings.roulette) {
        q_sum += q[r.region[e]];
        ++q_count;
      }
      learner.add(r.region[e], r.estimate[e], undecided, r.forwarded[e] != 0, r.forwards[e],
                  r.forwarded[e] && r.estimate[e] > 0);
    }
    learner.setMeasuredCosts(my_segments ? 1e6 * computeCpu() / double(my_segments) : 1.0,
                             my_forwards ? 1e6 * exchange_seconds / double(my_forwards) : 1.0);
    progress.update();
  }
  progress.done();

  // 3. The image, reduced to rank 0 (every pixel is non-zero on one rank at most).
  DataParallelResult result;
  result.spp = settings.spp;
  Image radiance{width, height, 3, std::vector<float>(num_pixels * 3, 0.0f)};
  Image visibility{width, height, 1, std::vector<float>(num_pixels, 0.0f)};
  Image forwards{width, height, 1, std::vector<float>(num_pixels, 0.0f)};
  Image owner{width, height, 1, std::vector<float>(num_pixels, 0.0f)};
  for (size_t i = 0; i < owned.size(); ++i) {
    const size_t p = owned[i];
    const PixelSums& s = sums[i];
    for (int c = 0; c < 3; ++c)
      radiance.pixels[p * 3 + size_t(c)] = float(s.radiance[c] / settings.spp);
    visibility.pixels[p] = s.vis_n ? float(s.vis_sum / s.vis_n) : 0.0f;
    forwards.pixels[p] = float(s.forwards);
    owner.pixels[p] = float(rank + 1);
  }
  const double compute_seconds = computeCpu() / double(tbb::this_task_arena::max_concurrency());
  timed([&] {
    comm.sum(radiance.pixels, true);
    comm.sum(visibility.pixels, true);
    comm.sum(forwards.pixels, true);
    comm.sum(owner.pixels, true);
  });
  if (rank == 0) {
    result.radiance = std::move(radiance);
    result.visibility = std::move(visibility);
    result.forwards = std::move(forwards);
    result.owner = std::move(owner);
  }

  // 4. Statistics over ranks.
  counts[7] = my_forwards;
  counts[8] = owned.size();
  std::vector<uint64_t> totals = counts;
  comm.sum(totals);
  stats.shadow_segments = totals[0];
  stats.blocked_locally = totals[1];
  stats.blocked_by_inside = totals[2];
  stats.undecided = totals[3];
  stats.forwarded_segments = totals[4];
  stats.forward_bytes = totals[5];
  stats.forward_messages = totals[6];
  stats.forwards = totals[7];
  stats.pixels_shaded = totals[8];
  std::vector<uint64_t> per_rank(size_t(ranks) * 2, 0);
  per_rank[size_t(rank)] = peakRssBytes();
  per_rank[size_t(ranks + rank)] = owned.size();
  comm.sum(per_rank);
  stats.rank_rss_bytes.assign(per_rank.begin(), per_rank.begin() + ranks);
  stats.rank_shaded_pixels.assign(per_rank.begin() + ranks, per_rank.end());
  stats.rank_peak_rss_bytes =
      *std::max_element(stats.rank_rss_bytes.begin(), stats.rank_rss_bytes.end());
  std::vector<uint64_t> busiest = {my_forwards, counts[5], counts[6]};
  comm.max(busiest);
  stats.max_rank_forwards = busiest[0];
  stats.max_rank_forward_bytes = busiest[1];
  stats.max_rank_forward_messages = busiest[2];
  std::vector<double> times = {compute_seconds, exchange_seconds, clock.seconds()};
  comm.max(times);
  stats.max_compute_seconds = times[0];
  stats.max_exchange_seconds = times[1];
  stats.seconds = times[2];
  std::vector<double> q_sums = {q_sum, double(q_count)};
  comm.sum(q_sums);
  stats.mean_q = q_sums[1] > 0 ? q_sums[0] / q_sums[1] : 1.0;
  result.stats = stats;
  return result;
}

}  // namespace proxyvis
