#pragma once
// What render and render-compare share for a data-parallel run: the flags, one run from a scene
// description to the image on rank 0, and its JSON row (the report keys users' scripts read:
// forwarding, ranks, forwards_per_shadow_segment, forward_bytes, forward_messages,
// rank_peak_rss_bytes, ...).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "distributed/data_parallel_render.h"
#include "distributed/distributed_scene.h"
#include "render/render_options.h"

namespace proxyvis {

struct DataParallelFlags {
  bool enabled = false;                // --data-parallel
  std::string forwarding = "proxies";  // one policy (render) or a comma list (render-compare)
  int passes_per_round = 4;     // roulette learns between rounds: its first round forwards all
  double forward_cost_us = -1;  // roulette's forward cost; < 0: from the fabric and this run
  double local_cost_us = -1;
  std::string network = "shm";                           // --network: a preset of network_fabric.h
  double network_alpha_us = -1, network_beta_gbps = -1;  // < 0: the preset's
  bool emulate_network = false;
  std::string proxy_route;  // --proxy-route; empty: always

  // The route choice --forwarding proxies uses (throws Error for an unknown name).
  ProxyRoute proxyRoute() const;
  // Throws Error (exit 2) for an unknown --proxy-route, or one given where no policy is
  // `proxies` (it would not act).
  void checkProxyRoute(bool proxies_forwarding) const;
};

// Adds --data-parallel, --forwarding, --passes-per-round, --forward-cost-us, --local-cost-us,
// --network, --network-alpha-us, --network-beta-gbps, --emulate-network.
// `list`: --forwarding takes a comma-separated list (render-compare).
void addDataParallelFlags(CLI::App& app, DataParallelFlags& flags, bool list);

// Throws Error (exit 2) when a data-parallel flag is given without --data-parallel: it would
// not act.
void refuseDataParallelFlagsAlone(const CLI::App& app, const DataParallelFlags& flags);

// The fabric the flags name, with shared memory's alpha and beta measured on this job when it
// is `shm` (collective; throws the collective Error of MpiComm::agree for a bad flag or an
// emulation across hosts). `emulate` is set when --emulate-network asks for a fabric other
// than this machine's own.
struct JobNetwork {
  NetworkFabric fabric;
  NetworkFabric shm;  // this machine's, measured
  bool emulate = false;
};
JobNetwork resolveNetwork(const DataParallelFlags& flags, const MpiComm& comm);

// The scene options of a data-parallel run: the single-process renderer's scene options for the
// same flags (--proxy-kind, --build, --memory-budget act alike in both), and proxy forwarding when
// `proxies`. Collective: a flag the two renderers share that cannot act here is refused (Error on
// rank 0, ReportedOnAnotherRank elsewhere) rather than ignored: --probes, --roulette-costs other
// than measured; DistributedScene::load refuses a --proxy-kind it cannot forward by.
DistributedSceneOptions distributedSceneOptions(const RenderFlags& flags, bool proxies,
                                                const MpiComm& comm);

// One rank's share, for the report (gathered on rank 0).
struct RankFacts {
  int rank = 0;
  std::string host;
  uint64_t own_objects = 0, own_triangles = 0, replicated_triangles = 0, proxy_triangles = 0;
  uint64_t peak_rss_bytes = 0, shaded_pixels = 0;
  std::vector<std::string> originals_opened;
};
// Collective; the full list on rank 0, empty elsewhere.
std::vector<RankFacts> gatherRankFacts(const DistributedScene& scene,
                                       const DataParallelStats& stats, const MpiComm& comm);

// The row of one run: estimator, forwarding, ranks, the forward counts, memory, time, the
// fabric (network, network_alpha_us, network_beta_gbps, emulated) and the alpha-beta model's
// time with its per-round sums; forward_cost_us when roulette's was fixed (>= 0).
nlohmann::json dataParallelRow(const std::string& estimator, Forwarding forwarding,
                               const DataParallelStats& stats, double forward_cost_us);
nlohmann::json rankFactsJson(const std::vector<RankFacts>& facts);
// The model's keys of a row: modelled_seconds and its per-round sums.
void setModelledKeys(nlohmann::json& row, const ModelledTime& modelled);

// The ranks' peak RSS and their shares, one line each, for the human report.
std::string rankFactsText(const std::vector<RankFacts>& facts);

}  // namespace proxyvis
