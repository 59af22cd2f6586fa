#pragma once
// The data-parallel direct-illumination renderer (docs/data_parallel.md). Every rank runs it on
// its DistributedScene:
//   1. primary rays: every rank traces every pixel's primary ray against its own originals; the
//      closest hit over ranks (an MPI min-reduction, sort-last compositing) decides which rank
//      shades the pixel: the owner of the object hit, or for replicated geometry the owner of
//      the pixel's screen tile;
//   2. light samples exactly as the single-process renderer draws them (keyed on seed, pixel,
//      pass), in rounds of a few passes;
//   3. each shadow segment is traced against the rank's own and replicated originals; if they
//      leave it unblocked, the forwarding policy names the remote ranks that may block it (under
//      `proxies` with --proxy-route measured, per region the cheaper of the proxies' and the
//      boxes' route: route_choice.h), and it is sent to them one at a time, nearest first, in
//      batches (one message per rank pair and round) until one blocks it or none is left. `exact`
//      forwards every such segment; `roulette` forwards a segment that the proxies left undecided
//      with probability q (learned per screen tile x light from earlier rounds) and weighs the
//      answer by 1/q, otherwise takes the proxies' answer (blocked): unbiased for any q > 0;
//   4. pixel sums in the single-process order; the image is reduced to rank 0.
// Exact renders equal the single-process exact render bit for bit, at any rank and thread count.
#include <cstdint>
#include <string>
#include <vector>

#include "distributed/distributed_scene.h"
#include "distributed/mpi_comm.h"
#include "distributed/network_fabric.h"
#include "distributed/route_choice.h"
#include "util/image.h"
#include "util/peak_rss.h"

namespace proxyvis {

struct DataParallelSettings {
  Forwarding forwarding = Forwarding::kProxies;
  bool roulette = false;  // false: exact
  // Under kProxies: per region, the cheaper of the proxies' and the instance boxes' route
  // (measured; route_choice.h), or the proxies' route for every segment.
  ProxyRoute proxy_route = ProxyRoute::kAlways;
  int spp = 16;
  uint64_t seed = 0;
  int tile_size = 16;        // screen tiles: replicated hits are shaded by the tile's rank
  int passes_per_round = 8;  // light samples per pixel traced between two exchanges
  double q_min = 0.05;       // roulette's smallest forwarding probability
  // Roulette's costs in microseconds: a forward, and a segment's local work. < 0: from this run
  // (a forward: what `network` charges for the last round's messages per forwarded segment, at
  // their actual batch size, plus the measured remote trace; the choices then depend on timing,
  // the estimate stays unbiased).
  double forward_cost_us = -1;
  double local_cost_us = -1;
  // The fabric the model prices and, with `emulate`, the exchange waits for. Its alpha and beta
  // must be known (shm: measured by the caller, MpiComm::measureFabric()).
  NetworkFabric network;
  bool emulate = false;
  bool quiet = false;
};

struct DataParallelStats {
  int ranks = 1;
  uint64_t pixels_shaded = 0;       // all ranks
  uint64_t shadow_segments = 0;     // segments that needed visibility (all ranks)
  uint64_t blocked_locally = 0;     // by a rank's own or replicated originals
  uint64_t blocked_by_inside = 0;   // by an inside proxy, without a forward
  uint64_t undecided = 0;           // unblocked here with at least one remote rank to ask
  uint64_t forwarded_segments = 0;  // undecided segments that were sent (roulette: some)
  uint64_t routed_by_proxies = 0;   // kProxies: segments routed through the proxies
  uint64_t routed_by_boxes = 0;     // kProxies: segments the route choice sent by instance boxes
  ProxyRoute proxy_route = ProxyRoute::kAlways;  // the settings' choice
  uint64_t forwards = 0;           // segment messages items sent (one per segment and rank asked)
  uint64_t forward_bytes = 0;      // requests and answers, all ranks
  uint64_t forward_messages = 0;   // non-empty messages, all ranks
  uint64_t rounds = 0;             // exchange rounds
  uint64_t max_rank_forwards = 0;  // forwards sent by the busiest rank
  uint64_t max_rank_forward_bytes = 0, max_rank_forward_messages = 0;  // sent by the busiest
  double seconds = 0;                    // wall time of the render (load excluded), rank 0
  double max_compute_seconds = 0;        // the slowest rank's time outside MPI calls
  double max_exchange_seconds = 0;       // the largest rank's time inside exchanges and reductions
  uint64_t rank_peak_rss_bytes = 0;      // the largest over ranks (load included)
  std::vector<uint64_t> rank_rss_bytes;  // per rank
  std::vector<uint64_t> rank_shaded_pixels;
  double mean_q = 1;      // roulette: mean forwarding probability over undecided ones
  NetworkFabric network;  // the fabric modelled (and emulated)
  bool emulated = false;  // the exchange waited for the emulated fabric
  double max_emulated_wait_seconds = 0;  // the most a rank held messages back
  // The alpha-beta model of this run on `network`, from every rank's per-round loads (compute
  // measured as wall time outside MPI calls): a model from measured counts, not a measurement.
  ModelledTime modelled;

  double forwardsPerSegment() const {
    return shadow_segments ? double(forwards) / double(shadow_segments) : 0;
  }
};

struct DataParallelResult {
  // On rank 0: the whole image; elsewhere empty. Channels: radiance (3), visibility (mean
  // estimate per traced sample), forwards per pixel, owner rank + 1 (0 = no shading point).
  Image radiance, visibility, forwards, owner;
  int spp = 0;
  DataParallelStats stats;
};

// Collective. Throws Error for bad settings (on every rank alike).
DataParallelResult renderDataParallel(const DistributedScene& scene,
                                      const DataParallelSettings& settings, const MpiComm& comm);

}  // namespace proxyvis
