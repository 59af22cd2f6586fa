#include "distributed/network_fabric.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace proxyvis {

namespace {

// Published MPI small-message latency and streaming bandwidth (OSU-style ping-pong and bandwidth
// tests): HDR InfiniBand with Open MPI / HPC-X (Azure HBv2), Cray Aries, RoCE over 40-100 GbE
// with OS bypass (the middle of 2-5 us and 4.6-11 GB/s), 10 GbE over TCP.
const NetworkFabric kPresets[] = {
    {"shm", 0, 0, 0, true, false},           {"ib-hdr", 1.6, 23, 0, false, false},
    {"aries", 1.2, 9.2, 0, false, false},    {"roce", 3.5, 11, 0, false, false},
    {"10gbe-tcp", 20, 1.1, 0, false, false}, {"unbatched-20us", 0, 0, 20, false, true},
};

int log2Ceil(int ranks) {
  int steps = 0;
  while ((1 << steps) < ranks) ++steps;
  return steps;
}

}  // namespace

double NetworkFabric::messageSeconds(uint64_t bytes, uint64_t items) const {
  return sendSeconds(1, bytes, items);
}

double NetworkFabric::sendSeconds(uint64_t messages, uint64_t bytes, uint64_t items) const {
  const double transfer = beta_gbps > 0 ? double(bytes) / (beta_gbps * 1e9) : 0.0;
  return 1e-6 * (alpha_us * double(messages) + per_item_us * double(items)) + transfer;
}

double NetworkFabric::collectiveSeconds(int ranks) const {
  return 1e-6 * alpha_us * log2Ceil(ranks);
}

double NetworkFabric::reductionSeconds(int ranks, uint64_t bytes) const {
  return log2Ceil(ranks) * messageSeconds(bytes, 0);
}

std::string NetworkFabric::describe() const {
  if (upper_bound)
    return fmt::format(
        "{} ({:g} us per forwarded segment, one blocking round trip each: an "
        "upper bound for an unbatched design)",
        name, per_item_us);
  return fmt::format("{} (alpha {:.3g} us, beta {:.3g} GB/s{})", name, alpha_us, beta_gbps,
                     measured ? ", measured on this run" : "");
}

const std::vector<std::string>& networkPresetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const NetworkFabric& f : kPresets) n.push_back(f.name);
    return n;
  }();
  return names;
}

NetworkFabric networkFabric(const std::string& name, double alpha_us, double beta_gbps) {
  const auto* preset = std::find_if(std::begin(kPresets), std::end(kPresets),
                                    [&](const NetworkFabric& f) { return f.name == name; });
  if (preset == std::end(kPresets)) {
    std::string list;
    for (const std::string& n : networkPresetNames()) list += (list.empty() ? "" : ", ") + n;
    throw Error("", "--network " + name + " is not a known fabric", {},
                "use one of " + list + ", or --network-alpha-us and --network-beta-gbps");
  }
  NetworkFabric fabric = *preset;
  const bool given_alpha = !(alpha_us < 0), given_beta = !(beta_gbps < 0);
  if (!given_alpha && !given_beta) return fabric;
  if (given_alpha && !(std::isfinite(alpha_us) && alpha_us >= 0))
    throw Error("", fmt::format("--network-alpha-us {} is not a latency", alpha_us), {},
                "give microseconds per message, 0 or more");
  if (given_beta && !(std::isfinite(beta_gbps) && beta_gbps > 0))
    throw Error("", fmt::format("--network-beta-gbps {} is not a bandwidth", beta_gbps), {},
                "give gigabytes per second, more than 0");
  if (fabric.upper_bound)
    throw Error("", "--network unbatched-20us has no alpha or beta to replace",
                "it charges a flat cost per forwarded segment",
                "use --network-alpha-us and --network-beta-gbps with another --network");
  fabric.name = "custom";
  fabric.measured = false;
  if (given_alpha) fabric.alpha_us = alpha_us;
  if (given_beta) fabric.beta_gbps = beta_gbps;
  if (fabric.beta_gbps <= 0)
    throw Error("", "--network-alpha-us on --network shm needs --network-beta-gbps too",
                "shared memory's bandwidth is only known once the run measured it",
                "give both figures");
  return fabric;
}

NetworkFabric withMeasured(NetworkFabric fabric, double alpha_us, double beta_gbps) {
  if (fabric.name == "shm" && fabric.measured) {
    fabric.alpha_us = alpha_us;
    fabric.beta_gbps = beta_gbps;
  }
  return fabric;
}

ModelledTime& ModelledTime::operator+=(const ModelledTime& other) {
  seconds += other.seconds;
  compute_seconds += other.compute_seconds;
  message_seconds += other.message_seconds;
  control_seconds += other.control_seconds;
  rounds += other.rounds;
  return *this;
}

ModelledTime ModelledTime::meanOver(int runs) const {
  const double n = double(std::max(runs, 1));
  return {seconds / n, compute_seconds / n, message_seconds / n, control_seconds / n,
          rounds / uint64_t(std::max(runs, 1))};
}

ModelledTime modelTime(const NetworkFabric& fabric,
                       const std::vector<std::vector<RoundLoad>>& loads, double tail_seconds,
                       double reduction_seconds) {
  ModelledTime t;
  const int ranks = int(loads.size());
  const size_t rounds = loads.empty() ? 0 : loads.front().size();
  for (const auto& rank : loads) PV_CHECK_MSG(rank.size() == rounds, "ranks disagree on rounds");
  for (size_t k = 0; k < rounds; ++k) {
    for (PhaseLoad RoundLoad::*phase : {&RoundLoad::request, &RoundLoad::answer}) {
      double slowest = 0, compute = 0, messages = 0;
      for (const auto& rank : loads) {
        const PhaseLoad& l = rank[k].*phase;
        const double send = fabric.sendSeconds(l.messages, l.bytes, l.items);
        slowest = std::max(slowest, l.compute_seconds + send);
        compute = std::max(compute, l.compute_seconds);
        messages = std::max(messages, send);
      }
      t.seconds += slowest;
      t.compute_seconds += compute;
      t.message_seconds += messages;
    }
    const double control = fabric.collectiveSeconds(ranks);
    t.seconds += control;
    t.control_seconds += control;
  }
  t.seconds += tail_seconds + reduction_seconds;
  t.compute_seconds += tail_seconds;
  t.control_seconds += reduction_seconds;
  t.rounds = rounds;
  return t;
}

}  // namespace proxyvis
