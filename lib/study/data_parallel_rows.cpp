#include "study/data_parallel_rows.h"

#include <fmt/format.h>

#include <algorithm>

namespace proxyvis::dp_study {

void Row::addSeed(const DataParallelStats& s, bool first) {
  if (first) {
    stats = s;
    return;
  }
  stats.emulated = stats.emulated || s.emulated;
  stats.seconds += s.seconds;
  stats.modelled += s.modelled;
  stats.shadow_segments += s.shadow_segments;
  stats.forwards += s.forwards;
  stats.forward_bytes += s.forward_bytes;
  stats.forward_messages += s.forward_messages;
  stats.routed_by_proxies += s.routed_by_proxies;
  stats.routed_by_boxes += s.routed_by_boxes;
  stats.rank_peak_rss_bytes = std::max(stats.rank_peak_rss_bytes, s.rank_peak_rss_bytes);
}

void Row::finishSeeds(int seeds) {
  mse /= seeds;
  stats.seconds /= seeds;
  stats.modelled = stats.modelled.meanOver(seeds);
  stats.forward_bytes /= uint64_t(seeds);  // per render, as the table and report.json show them
  stats.forward_messages /= uint64_t(seeds);
}

std::string imageName(const Row& r) {
  return fmt::format("{}_{}_{}spp{}", r.estimator, forwardingName(r.forwarding), r.spp,
                     r.emulated() ? "_emulated" : "");
}

namespace {

// The table's columns and each row's cells, shared by report.md and report.html.
std::vector<std::string> tableHeader(const std::string& network) {
  return {"spp",
          "estimator",
          "forwarding",
          "run on",
          "forwards / shadow segment",
          "forward MB",
          "messages",
          "rank peak RSS MiB",
          "seconds (measured)",
          fmt::format("seconds (modelled, {})", network),
          "MSE",
          "efficiency (measured)",
          fmt::format("efficiency (modelled, {})", network)};
}

std::vector<std::string> tableCells(const Row& r) {
  return {std::to_string(r.spp),
          r.estimator,
          forwardingName(r.forwarding),
          r.emulated() ? "emulated " + r.stats.network.name : "shm (this machine)",
          fmt::format("{:.4f}", r.stats.forwardsPerSegment()),
          fmt::format("{:.2f}", 1e-6 * double(r.stats.forward_bytes)),
          std::to_string(r.stats.forward_messages),
          fmt::format("{:.0f}", double(r.stats.rank_peak_rss_bytes) / double(1 << 20)),
          fmt::format("{:.3f}", r.stats.seconds),
          fmt::format("{:.3f}", r.stats.modelled.seconds),
          fmt::format("{:.3e}", r.mse),
          fmt::format("{:.2f}x", r.relative),
          fmt::format("{:.2f}x", r.modelled_relative)};
}

}  // namespace

TextTable studyTable(const std::vector<Row>& rows, const std::string& network) {
  TextTable t{tableHeader(network), "rlllrrrrrrrrr", {}};
  for (const Row& r : rows) t.rows.push_back(tableCells(r));
  return t;
}

}  // namespace proxyvis::dp_study
