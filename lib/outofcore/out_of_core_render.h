#pragma once
// The out-of-core renderer (docs/out_of_core.md): direct illumination with exact visibility where
// the originals stay on disk and a cache of built originals holds what a budget allows. The
// integrator's steps are the single-process renderer's (render/integrator_steps.h): the same
// primary rays, shading points and light samples, so an exact image here equals the in-core
// exact image bit for bit, at any budget, batch size and thread count.
//
// Work is batched by mesh, as Pharr et al. (1997) batch rays by geometry: the primary rays are
// queued on every mesh whose object boxes they enter, then each mesh is loaded once and its
// queue traced. While a mesh is resident there, the shadow segments of every pass of the points
// it holds are traced against it: a point's own mesh (the self-shadowing rule traces the
// original) never needs loading again. The shadow segments of a batch of passes are then queued
// on the other meshes, each mesh loaded once per batch. Policies decide what queues:
//   exact-batched  every other mesh whose object box a segment enters (the fair exact baseline);
//   proxies-exact  only the other meshes whose outside proxy the segment crosses, or that have
//                  none; a segment an inside proxy blocks queues nowhere.
//   proxies-roulette  proxies-exact's queues, but a mesh with an outside proxy is loaded and its
//                  queue traced with probability q per batch (one draw, keyed on the seed, the
//                  batch and the mesh); otherwise its segments take the proxies' answer
//                  (blocked: they cross its outside proxy).
//                  Per segment and mesh the estimate is v' + [traced] (v - v') / q, and a
//                  segment's visibility the product over its meshes: unbiased, since the draws
//                  of different meshes are independent. Meshes without an outside proxy are
//                  always traced. q is fixed, or learned per batch and mesh from earlier
//                  batches only (outofcore/load_q_learner.h).
#include <cstdint>
#include <string>
#include <vector>

#include "outofcore/geometry_cache.h"
#include "outofcore/out_of_core_scene.h"
#include "util/image.h"

namespace proxyvis {

enum class OutOfCorePolicy { kExactBatched, kProxiesExact, kProxiesRoulette };
// "exact-batched", "proxies-exact", "proxies-roulette"
const char* outOfCorePolicyName(OutOfCorePolicy p);
// Throws Error naming --ooc-policy for anything else.
OutOfCorePolicy parseOutOfCorePolicy(const std::string& name);

struct OutOfCoreSettings {
  OutOfCorePolicy policy = OutOfCorePolicy::kExactBatched;
  int spp = 16;
  uint64_t seed = 0;
  int batch_passes = 0;  // passes whose segments are queued together; 0: the whole frame
  uint64_t budget_bytes = 0;
  double load_q = 0.5;      // proxies-roulette: the probability a mesh's queue is traced in a batch
  bool cold_reads = false;  // every load reads its file from the disk, not the page cache
  bool learn_q = false;     // proxies-roulette: q per batch and mesh learned (load_q unused)
  double q_min = 0.05;      // the learned q's floor
  // The most a batch's samples and queues may take (bytes): a batch stops adding passes before
  // it would go over (it holds one pass at least). 0: the memory bound's queue share.
  uint64_t queue_cap_bytes = 0;
  int tile_size = 16;
  bool quiet = false;
};

// The frame's per-pixel buffers, kept for the whole render: each pixel's shading point, its
// sums, its own-mesh answers (a bit per pass), the output image (RGB and visibility) and, with
// learned q, its squared sums.
uint64_t imageBytes(size_t pixels, const OutOfCoreSettings& settings);

// What a render's memory is held to (docs/out_of_core.md, "Memory"): the budget, the proxies
// and the image, plus a stated overhead of kOverheadShare of their sum for everything else (a
// batch's samples and queues, the primary pass's queue, the allocator's slack). The queue cap is
// kQueueShare of the sum, part of the overhead.
inline constexpr double kOverheadShare = 0.10;
inline constexpr double kQueueShare = 0.05;
struct OutOfCoreMemoryBound {
  uint64_t overhead_bytes = 0;   // kOverheadShare x (budget + proxies + image)
  uint64_t bound_bytes = 0;      // budget + proxies + image + overhead
  uint64_t queue_cap_bytes = 0;  // kQueueShare x (budget + proxies + image)
};
OutOfCoreMemoryBound outOfCoreMemoryBound(uint64_t budget_bytes, uint64_t proxy_bytes,
                                          uint64_t image_bytes);
struct OutOfCoreStats;
// The memory figures a render of `pixels` pixels states in `stats` before it starts: image and
// proxy bytes, overhead, bound and queue cap (settings.queue_cap_bytes when given).
void setMemoryBound(OutOfCoreStats& stats, size_t pixels, const OutOfCoreSettings& settings,
                    uint64_t proxy_bytes);

// A traced queue whose segments have a proxy answer: what skipping it would have added to the
// image's summed squared error per unit of (1/q - 1), and what tracing it cost.
struct ProxyQueueRecord {
  double wrong_w2 = 0;  // sum of |w|^2 over its traced segments the proxies answer wrongly
  double seconds = 0;   // measured: its load (if it loaded) and its traces
};

// --load-q: a probability in (0, 1], or "learned". Throws Error naming --load-q otherwise.
void applyLoadQ(const std::string& text, OutOfCoreSettings& settings);
// What a report says of q: the fixed value, or "learned".
std::string loadQText(const OutOfCoreSettings& settings);

struct OutOfCoreStats {
  GeometryCacheStats cache;
  uint64_t batches = 0;
  uint64_t shadow_segments = 0;      // segments needing visibility
  uint64_t queued = 0;               // (segment, mesh) pairs queued
  uint64_t unqueued_segments = 0;    // decided without a load (by the boxes or the proxies)
  uint64_t blocked_by_inside = 0;    // of those, blocked by an inside proxy
  uint64_t blocked_by_own_mesh = 0;  // of those, blocked by their own mesh (primary pass)
  uint64_t own_mesh_traces = 0;      // segments traced against their own mesh in the primary
                                     // pass (with those of points a nearer hit replaced)
  uint64_t original_traces = 0;      // segment traces against loaded originals
  uint64_t skipped_queues = 0;       // proxies-roulette: (batch, mesh) queues not traced
  // proxies-roulette: an unbiased estimate of the variance its draws added to the image's mean
  // (over pixels and channels), from the traced queues; exact where no segment is answered
  // wrongly on two meshes (docs/out_of_core.md, "Variance").
  double roulette_added_variance = 0;
  double q_sum = 0;             // proxies-roulette: the sum of q over its draws
  uint64_t q_draws = 0;         //   and their count (the mean q: q_sum / q_draws)
  uint64_t primary_queued = 0;  // (ray, mesh) pairs of the primary rays
  uint64_t traced_queues = 0;   // (batch, mesh) shadow queues traced
  // The oracle ceiling's inputs (proxy policies): every traced (batch, mesh) queue of a mesh
  // with an outside proxy.
  std::vector<ProxyQueueRecord> proxy_queues;
  uint64_t budget_bytes = 0;
  // Memory, measured (RSS; docs/out_of_core.md, "Memory"). The render starts by handing the
  // heap's freed memory back and resetting the high-water mark: `rss_before_bytes` is what was
  // resident then (the program, the resident scene with its proxies), `peak_rss_bytes` the
  // render's peak, and the growths are over rss_before_bytes.
  uint64_t rss_before_bytes = 0;
  uint64_t peak_rss_bytes = 0;
  uint64_t peak_rss_growth_bytes = 0;
  uint64_t primary_rss_growth_bytes = 0;  // the primary pass, its loads included
  uint64_t route_rss_growth_bytes = 0;    // a batch's samples and queues, before its loads
  uint64_t trace_rss_growth_bytes = 0;    // a batch's loads and traces
  uint64_t load_rss_growth_bytes = 0;     // the most one load (read, decode, build) grew RSS by
  double load_growth_over_built = 0;      // the largest such growth over the mesh's built bytes
  uint64_t queue_bytes = 0;  // the largest shadow batch's flags, factors and queues (capacity)
  uint64_t primary_queue_bytes = 0;                  // the primary rays' queues (capacity)
  uint64_t image_bytes = 0;                          // imageBytes()
  uint64_t queue_cap_bytes = 0;                      // the cap the batches kept to
  uint64_t capped_batches = 0;                       // batches the cap ended before --batch-passes
  uint64_t proxy_bytes = 0;                          // the scene's resident proxies (built)
  uint64_t overhead_bytes = 0, rss_bound_bytes = 0;  // outOfCoreMemoryBound()
  // The render's peak growth plus the proxies (resident before it began): what the bound holds.
  uint64_t bounded_peak_bytes = 0;
  bool withinRssBound() const { return bounded_peak_bytes <= rss_bound_bytes; }
  double seconds = 0, primary_seconds = 0, shadow_seconds = 0;
};

struct OutOfCoreResult {
  Image radiance;    // RGB, the mean over spp
  Image visibility;  // Y, the mean visibility of the pixel's segments
  int spp = 0;
  OutOfCoreStats stats;
};

// Throws Error for settings it cannot run with, a budget below the largest mesh's built bytes,
// or an original that can no longer be read (naming its file; nothing is written).
OutOfCoreResult renderOutOfCore(const OutOfCoreScene& scene, const OutOfCoreSettings& settings);
// The settings renderOutOfCore refuses for `scene` (throws Error): bad numbers, a policy that
// needs proxies the scene lacks, a budget below the largest mesh's load.
void checkOutOfCoreSettings(const OutOfCoreScene& scene, const OutOfCoreSettings& settings);

}  // namespace proxyvis
