#pragma once
// One row of the out-of-core study (render-compare --geometry-budget): what a configuration's
// renders measured, over its seeds; how rows are scored against the best exact-batched row; the
// oracle ceiling; and the rows as report.json's entries and as the report's table.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "outofcore/out_of_core_render.h"
#include "study/study_page.h"

namespace proxyvis::ooc_study {

struct Row {
  OutOfCorePolicy policy{};
  int spp = 0, batch_passes = 0, seeds = 0;
  uint64_t budget_bytes = 0;
  bool cold_reads = false;
  std::string load_q = "-";  // proxies-roulette: the fixed q, or "learned"
  // Sums over the seeds until finish(), then means (peak RSS: the largest).
  double mse = 0, seconds = 0, load_seconds = 0, read_seconds = 0, build_seconds = 0;
  double loads = 0, hits = 0, evictions = 0, bytes_read = 0, queued = 0, original_traces = 0;
  double skipped_queues = 0, traced_queues = 0, shadow_segments = 0;
  double q_sum = 0, q_draws = 0;  // the mean q of proxies-roulette's draws: q_sum / q_draws
  std::vector<ProxyQueueRecord> proxy_queues;  // proxies-exact: every seed's traced queues
  uint64_t peak_rss_bytes = 0, peak_cache_bytes = 0;
  uint64_t rss_before_bytes = 0;  // resident when its renders started (the largest)
  // The memory bound (outOfCoreMemoryBound) and what it holds: the largest render's growth plus
  // the proxies; within only if every seed's render was.
  uint64_t peak_rss_growth_bytes = 0, bounded_peak_bytes = 0, rss_bound_bytes = 0;
  uint64_t proxy_bytes = 0, image_bytes = 0, overhead_bytes = 0, queue_cap_bytes = 0;
  bool within_rss_bound = true;
  // Scored.
  double efficiency = 0, relative_efficiency = 0;
  bool baseline = false;

  void add(const OutOfCoreStats& s, double image_mse);
  void finish();
};

// "<policy>_<spp>spp_<batch<passes> or frame>[_cold]": the row's image without extension.
std::string imageName(const Row& r);

// Efficiency 1/(MSE x seconds) of every row, relative to the most efficient exact-batched row of
// the same spp and page cache (marked baseline: the best batch for exact, as the comparison
// demands).
void scoreRows(std::vector<Row>& rows);

// The oracle ceiling at one spp: the efficiency, relative to the best exact-batched row, of a
// load-level roulette that knew each queue's error and cost: per (batch, mesh) queue the q that
// minimises the image's MSE x time (0 for a queue the proxies answer right throughout, 1 where
// they are wrong too often for a skip to pay). Modelled from the proxies-exact row's measured
// parts, not run: its seconds less (1 - q) x each queue's measured load and trace seconds, its
// MSE plus (1/q - 1) x each queue's wrong |w|^2 / (spp^2 x 3 x pixels).
struct Ceiling {
  int spp = 0, batch_passes = 0;
  double relative_efficiency = 0;
  double oracle_seconds = 0, oracle_mse = 0, baseline_seconds = 0, baseline_mse = 0;
  double queues = 0, skipped = 0, mean_q = 0;  // per render
};
// The best ceiling of each spp that has a proxies-exact row, largest spp last; `pixels` of the
// image.
std::vector<Ceiling> ceilings(const std::vector<Row>& rows, size_t pixels, double q_min);

nlohmann::json rowJson(const Row& r);
nlohmann::json ceilingJson(const Ceiling& c);
TextTable studyTable(const std::vector<Row>& rows);

}  // namespace proxyvis::ooc_study
