#include "study/out_of_core_rows.h"

#include <fmt/format.h>

#include <algorithm>

namespace proxyvis::ooc_study {

void Row::add(const OutOfCoreStats& s, double image_mse) {
  ++seeds;
  mse += image_mse;
  seconds += s.seconds;
  load_seconds += s.cache.loadSeconds();
  read_seconds += s.cache.read_seconds;
  build_seconds += s.cache.build_seconds;
  loads += double(s.cache.loads);
  hits += double(s.cache.hits);
  evictions += double(s.cache.evictions);
  bytes_read += double(s.cache.bytes_read);
  queued += double(s.queued);
  original_traces += double(s.original_traces);
  skipped_queues += double(s.skipped_queues);
  traced_queues += double(s.traced_queues);
  shadow_segments += double(s.shadow_segments);
  q_sum += s.q_sum;
  q_draws += double(s.q_draws);
  if (policy == OutOfCorePolicy::kProxiesExact)
    proxy_queues.insert(proxy_queues.end(), s.proxy_queues.begin(), s.proxy_queues.end());
  peak_rss_bytes = std::max(peak_rss_bytes, s.peak_rss_bytes);
  peak_cache_bytes = std::max(peak_cache_bytes, s.cache.peak_resident_bytes);
  rss_before_bytes = std::max(rss_before_bytes, s.rss_before_bytes);
  peak_rss_growth_bytes = std::max(peak_rss_growth_bytes, s.peak_rss_growth_bytes);
  bounded_peak_bytes = std::max(bounded_peak_bytes, s.bounded_peak_bytes);
  rss_bound_bytes = s.rss_bound_bytes;
  proxy_bytes = s.proxy_bytes;
  image_bytes = s.image_bytes;
  overhead_bytes = s.overhead_bytes;
  queue_cap_bytes = s.queue_cap_bytes;
  within_rss_bound = within_rss_bound && s.withinRssBound();
}

void Row::finish() {
  if (seeds == 0) return;
  const double n = seeds;
  for (double* v :
       {&mse, &seconds, &load_seconds, &read_seconds, &build_seconds, &loads, &hits, &evictions,
        &bytes_read, &queued, &original_traces, &skipped_queues, &traced_queues, &shadow_segments})
    *v /= n;
}

std::string imageName(const Row& r) {
  return fmt::format("{}_{}spp_{}{}", outOfCorePolicyName(r.policy), r.spp,
                     r.batch_passes > 0 ? fmt::format("batch{}", r.batch_passes) : "frame",
                     r.cold_reads ? "_cold" : "");
}

namespace {

const Row* baselineOf(const std::vector<Row>& rows, int spp, bool cold) {
  const Row* best = nullptr;
  for (const Row& b : rows)
    if (b.spp == spp && b.cold_reads == cold && b.policy == OutOfCorePolicy::kExactBatched &&
        (!best || b.efficiency > best->efficiency))
      best = &b;
  return best;
}

}  // namespace

void scoreRows(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.efficiency = r.mse > 0 && r.seconds > 0 ? 1 / (r.mse * r.seconds) : 0;
  }
  for (Row& r : rows) {
    const Row* base = baselineOf(rows, r.spp, r.cold_reads);
    r.baseline = base == &r;
    r.relative_efficiency = base && base->efficiency > 0 ? r.efficiency / base->efficiency : 0;
  }
}

namespace {

// The oracle's q per queue for a proxies-exact row (see Ceiling): the fixed point of
// q_k = sqrt(E_k T / (C_k V)), clamped to [q_min, 1], and 0 where E_k = 0.
Ceiling oracle(const Row& r, size_t pixels, double q_min) {
  Ceiling c;
  c.spp = r.spp;
  c.batch_passes = r.batch_passes;
  const double seeds = std::max(1, r.seeds);
  const double scale = 1 / (double(r.spp) * double(r.spp) * 3 * double(pixels)) / seeds;
  std::vector<double> q(r.proxy_queues.size(), 1.0);
  double t = r.seconds, v = r.mse;
  for (int iteration = 0; iteration < 50; ++iteration) {
    for (size_t k = 0; k < q.size(); ++k) {
      const double e = r.proxy_queues[k].wrong_w2 * scale;
      const double cost = r.proxy_queues[k].seconds / seeds;
      q[k] = e <= 0 ? 0.0 : cost <= 0 ? 1.0 : std::clamp(std::sqrt(e * t / (cost * v)), q_min, 1.0);
    }
    t = r.seconds, v = r.mse;
    for (size_t k = 0; k < q.size(); ++k) {
      t -= (1 - q[k]) * r.proxy_queues[k].seconds / seeds;
      if (q[k] > 0) v += (1 / q[k] - 1) * r.proxy_queues[k].wrong_w2 * scale;
    }
  }
  c.oracle_seconds = std::max(t, 1e-9);
  c.oracle_mse = v;
  c.queues = double(q.size()) / seeds;
  for (double x : q) {
    c.skipped += (x == 0) / seeds;
    c.mean_q += x / seeds;
  }
  if (c.queues > 0) c.mean_q /= c.queues;
  return c;
}

}  // namespace

std::vector<Ceiling> ceilings(const std::vector<Row>& rows, size_t pixels, double q_min) {
  std::vector<Ceiling> out;
  std::vector<int> spps;
  for (const Row& r : rows)
    if (std::find(spps.begin(), spps.end(), r.spp) == spps.end()) spps.push_back(r.spp);
  std::sort(spps.begin(), spps.end());
  for (int spp : spps) {
    // Warm reads: the ceiling of the setting the targets name.
    const Row* base = baselineOf(rows, spp, false);
    if (!base || base->efficiency <= 0) continue;
    std::optional<Ceiling> best;
    for (const Row& r : rows) {
      if (r.spp != spp || r.cold_reads || r.policy != OutOfCorePolicy::kProxiesExact || r.mse <= 0)
        continue;
      Ceiling c = oracle(r, pixels, q_min);
      c.baseline_seconds = base->seconds;
      c.baseline_mse = base->mse;
      c.relative_efficiency = 1 / (c.oracle_mse * c.oracle_seconds) / base->efficiency;
      if (!best || c.relative_efficiency > best->relative_efficiency) best = c;
    }
    if (best) out.push_back(*best);
  }
  return out;
}

nlohmann::json rowJson(const Row& r) {
  return {{"table", "equal-spp"},
          {"policy", outOfCorePolicyName(r.policy)},
          {"estimator", r.policy == OutOfCorePolicy::kProxiesRoulette ? "roulette" : "exact"},
          {"spp", r.spp},
          {"batch_passes", r.batch_passes},
          {"seeds", r.seeds},
          {"geometry_budget_bytes", r.budget_bytes},
          {"page_cache", r.cold_reads ? "cold" : "warm"},
          {"load_q", r.load_q},
          {"mean_load_q", r.q_draws > 0 ? r.q_sum / r.q_draws : 1.0},
          {"loads_per_frame", r.loads},
          {"hits_per_frame", r.hits},
          {"evictions_per_frame", r.evictions},
          {"bytes_read", r.bytes_read},
          {"load_seconds", r.load_seconds},
          {"read_seconds", r.read_seconds},
          {"build_seconds", r.build_seconds},
          {"shadow_segments", r.shadow_segments},
          {"shadow_segments_per_second", r.seconds > 0 ? r.shadow_segments / r.seconds : 0.0},
          {"queued", r.queued},
          {"original_traces", r.original_traces},
          {"traced_queues", r.traced_queues},
          {"skipped_queues", r.skipped_queues},
          {"peak_rss_bytes", r.peak_rss_bytes},
          {"peak_cache_bytes", r.peak_cache_bytes},
          {"rss_before_bytes", r.rss_before_bytes},
          {"peak_rss_growth_bytes", r.peak_rss_growth_bytes},
          {"proxy_bytes", r.proxy_bytes},
          {"image_bytes", r.image_bytes},
          {"overhead_bytes", r.overhead_bytes},
          {"queue_cap_bytes", r.queue_cap_bytes},
          {"rss_bound_bytes", r.rss_bound_bytes},
          {"bounded_peak_bytes", r.bounded_peak_bytes},
          {"within_rss_bound", r.within_rss_bound},
          {"seconds", r.seconds},
          {"mse", r.mse},
          {"efficiency", r.efficiency},
          {"relative_efficiency", r.relative_efficiency},
          {"baseline", r.baseline},
          {"image", "images/" + imageName(r) + ".exr"}};
}

nlohmann::json ceilingJson(const Ceiling& c) {
  return {{"spp", c.spp},
          {"batch_passes", c.batch_passes},
          {"relative_efficiency", c.relative_efficiency},
          {"oracle_seconds", c.oracle_seconds},
          {"oracle_mse", c.oracle_mse},
          {"baseline_seconds", c.baseline_seconds},
          {"baseline_mse", c.baseline_mse},
          {"queues_per_frame", c.queues},
          {"queues_skipped_per_frame", c.skipped},
          {"mean_q", c.mean_q},
          {"model",
           "modelled from the proxies-exact row's measured parts, not run: per (batch, mesh) "
           "queue the q minimising MSE x time, its seconds less (1 - q) x the queue's measured "
           "load and trace seconds, its MSE plus (1/q - 1) x the queue's wrongly answered "
           "|w|^2 / (spp^2 x 3 x pixels)"}};
}

TextTable studyTable(const std::vector<Row>& rows) {
  TextTable t{
      {"spp", "policy", "passes per batch", "page cache", "load q", "loads / frame", "MB read",
       "load s", "peak RSS MiB", "held / bound MiB", "seconds", "MSE", "efficiency"},
      "rlllrrrrrrrrr",
      {}};
  for (const Row& r : rows)
    t.rows.push_back(
        {std::to_string(r.spp), outOfCorePolicyName(r.policy),
         r.batch_passes > 0 ? std::to_string(r.batch_passes) : "frame",
         r.cold_reads ? "cold" : "warm",
         r.q_draws > 0 ? fmt::format("{} (mean {:.2f})", r.load_q, r.q_sum / r.q_draws) : r.load_q,
         fmt::format("{:.1f}", r.loads), fmt::format("{:.1f}", 1e-6 * r.bytes_read),
         fmt::format("{:.2f}", r.load_seconds),
         fmt::format("{:.0f}", double(r.peak_rss_bytes) / double(1 << 20)),
         fmt::format("{:.1f} / {:.1f}{}", double(r.bounded_peak_bytes) / double(1 << 20),
                     double(r.rss_bound_bytes) / double(1 << 20),
                     r.within_rss_bound ? "" : " (over)"),
         fmt::format("{:.3f}", r.seconds), fmt::format("{:.3e}", r.mse),
         fmt::format("{:.2f}x{}", r.relative_efficiency, r.baseline ? " (baseline)" : "")});
  return t;
}

}  // namespace proxyvis::ooc_study
