#include "study/data_parallel_rows.h"

#include <fmt/format.h>

namespace proxyvis::dp_study {

std::string imageName(const Row& r) {
  return fmt::format("{}_{}_{}spp{}", r.estimator, forwardingName(r.forwarding), r.spp,
                     r.emulated ? "_emulated" : "");
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
          r.emulated ? "emulated " + r.stats.network.name : "shm (this machine)",
          fmt::format("{:.4f}", r.segments ? double(r.forwards) / double(r.segments) : 0.0),
          fmt::format("{:.2f}", 1e-6 * double(r.bytes)),
          std::to_string(r.messages),
          fmt::format("{:.0f}", double(r.peak_rss) / double(1 << 20)),
          fmt::format("{:.3f}", r.seconds),
          fmt::format("{:.3f}", r.modelled.seconds),
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
