#include "distributed/data_parallel_job.h"

#include <fmt/format.h>

#include "util/app_main.h"

namespace proxyvis {

void addDataParallelFlags(CLI::App& app, DataParallelFlags& flags, bool list) {
  const std::string group = "Data-parallel (run under mpirun; docs/data_parallel.md)";
  app.add_flag("--data-parallel", flags.enabled,
               "Split the scene's objects over the MPI ranks (each loads only its own originals "
               "and every proxy) and forward shadow rays between them")
      ->group(group);
  app.add_option("--forwarding", flags.forwarding,
                 list ? "Forwarding policies to compare, comma-separated: domain-bounds, "
                        "instance-boxes, proxies"
                      : "Which ranks a shadow ray is sent to: domain-bounds, instance-boxes or "
                        "proxies (outside and inside proxies where the scene has them)")
      ->capture_default_str()
      ->group(group);
  app.add_option("--passes-per-round", flags.passes_per_round,
                 "Light samples per pixel traced between two exchanges of rays")
      ->check(integerIn(1, 1024))
      ->capture_default_str()
      ->group(group);
  app.add_option("--forward-cost-us", flags.forward_cost_us,
                 "Roulette: the cost of one forwarded ray in microseconds (default: what --network "
                 "charges for the last round's messages per ray, at their batch size, plus the "
                 "measured remote trace)")
      ->check(numberIn(0, 1e6))
      ->group(group);
  app.add_option("--local-cost-us", flags.local_cost_us,
                 "Roulette: a segment's local work in microseconds (default: measured); with "
                 "--forward-cost-us the render is bit-reproducible for a given rank count")
      ->check(numberIn(0, 1e6))
      ->group(group);
  std::string presets;
  for (const std::string& n : networkPresetNames()) presets += (presets.empty() ? "" : ", ") + n;
  app.add_option("--network", flags.network,
                 "The fabric the report's alpha-beta model prices (and --emulate-network "
                 "emulates): " +
                     presets +
                     " (shm: this machine's shared memory, measured by a ping-pong at the start; "
                     "unbatched-20us: a flat 20 us per forward, an upper bound for an unbatched "
                     "design)")
      ->capture_default_str()
      ->group(group);
  app.add_option("--network-alpha-us", flags.network_alpha_us,
                 "A custom fabric's latency per message, in microseconds (replaces the preset's)")
      ->check(numberIn(0, 1e6))
      ->group(group);
  app.add_option("--network-beta-gbps", flags.network_beta_gbps,
                 "A custom fabric's bandwidth, in GB/s (replaces the preset's)")
      ->check(numberIn(1e-6, 1e6))
      ->group(group);
  app.add_option("--proxy-route", flags.proxy_route,
                 "With --forwarding proxies: 'measured' routes each region's segments (screen "
                 "tile x light) the cheaper way, through the proxies or through the instance "
                 "boxes alone, from costs measured in earlier rounds (images unchanged; roulette's "
                 "then depend on timing); 'always' (default) routes every segment through the "
                 "proxies")
      ->group(group);
  app.add_flag("--emulate-network", flags.emulate_network,
               "Make the exchange take what --network charges (each message leaves no earlier "
               "than alpha + bytes/beta after the previous one; the count exchange likewise), so "
               "that the measured time is the time under that fabric (ranks on one host)")
      ->group(group);
}

void refuseDataParallelFlagsAlone(const CLI::App& app, const DataParallelFlags& flags) {
  if (flags.enabled) return;
  for (const char* name :
       {"--forwarding", "--passes-per-round", "--forward-cost-us", "--local-cost-us", "--network",
        "--network-alpha-us", "--network-beta-gbps", "--emulate-network", "--proxy-route"})
    if (app.count(name) > 0)
      throw Error("", std::string(name) + " needs --data-parallel",
                  "it only acts on the data-parallel renderer",
                  "add --data-parallel (under mpirun)");
}

ProxyRoute DataParallelFlags::proxyRoute() const {
  // `always` unless asked: the measured choice did not beat it reliably in measured wall time
  // (docs/data_parallel.md, "Where the proxies pay").
  return proxy_route.empty() ? ProxyRoute::kAlways : parseProxyRoute(proxy_route);
}

void DataParallelFlags::checkProxyRoute(bool proxies_forwarding) const {
  proxyRoute();
  if (!proxy_route.empty() && !proxies_forwarding)
    throw Error("", "--proxy-route does not act without --forwarding proxies",
                "the box policies route every segment by their boxes",
                "add --forwarding proxies, or leave --proxy-route out");
}

JobNetwork resolveNetwork(const DataParallelFlags& flags, const MpiComm& comm) {
  JobNetwork job;
  comm.collectively([&] {
    job.fabric = networkFabric(flags.network, flags.network_alpha_us, flags.network_beta_gbps);
  });
  const bool one_host = comm.oneHost();
  comm.collectively([&] {
    if (flags.emulate_network && !one_host)
      throw Error("", "--emulate-network needs every rank on one host",
                  "the emulated fabric compares the ranks' clocks", "run the ranks on one node");
  });
  const auto [alpha_us, beta_gbps] = comm.measureFabric();
  job.shm = withMeasured(networkFabric("shm", -1, -1), alpha_us, beta_gbps);
  job.fabric = withMeasured(job.fabric, alpha_us, beta_gbps);
  job.emulate = flags.emulate_network && !job.fabric.measured && comm.size() > 1;
  return job;
}

DistributedSceneOptions distributedSceneOptions(const RenderFlags& flags, bool proxies,
                                                const MpiComm& comm) {
  comm.collectively([&] {
    if (flags.probes_given)
      throw Error("", "--probes is not available with --data-parallel",
                  "its estimators, exact and roulette forwarding, trace no probe rays",
                  "leave --probes out");
    if (flags.roulette_costs != "measured")
      throw Error("", "--roulette-costs is not available with --data-parallel",
                  "roulette forwarding weighs a forward against a segment's local work",
                  "use --forward-cost-us and --local-cost-us");
  });
  DistributedSceneOptions options;
  // What the single-process renderer would load for the same flags (quiet: the ranks' warnings
  // would repeat one another).
  options.scene = flags.sceneOptions(true);
  options.proxies = proxies;
  return options;
}

std::vector<RankFacts> gatherRankFacts(const DistributedScene& scene,
                                       const DataParallelStats& stats, const MpiComm& comm) {
  const DistributedScene::Facts& f = scene.facts();
  nlohmann::json mine = {
      {"rank", comm.rank()},
      {"host", comm.hostName()},
      {"own_objects", f.own_objects},
      {"own_triangles", f.own_triangles},
      {"replicated_triangles", f.replicated_triangles},
      {"proxy_triangles", f.proxy_triangles},
      {"peak_rss_bytes", peakRssBytes()},
      {"shaded_pixels",
       stats.rank_shaded_pixels.empty() ? 0 : stats.rank_shaded_pixels[size_t(comm.rank())]}};
  nlohmann::json files = nlohmann::json::array();
  for (const auto& p : f.originals_opened) files.push_back(p.string());
  mine["originals_opened"] = files;
  std::vector<RankFacts> out;
  for (const std::string& text : comm.gatherToRoot(mine.dump())) {
    const nlohmann::json j = nlohmann::json::parse(text);
    RankFacts r;
    r.rank = j["rank"];
    r.host = j["host"];
    r.own_objects = j["own_objects"];
    r.own_triangles = j["own_triangles"];
    r.replicated_triangles = j["replicated_triangles"];
    r.proxy_triangles = j["proxy_triangles"];
    r.peak_rss_bytes = j["peak_rss_bytes"];
    r.shaded_pixels = j["shaded_pixels"];
    r.originals_opened = j["originals_opened"].get<std::vector<std::string>>();
    out.push_back(std::move(r));
  }
  return out;
}

nlohmann::json dataParallelRow(const std::string& estimator, Forwarding forwarding,
                               const DataParallelStats& s, double forward_cost_us) {
  nlohmann::json row = {{"estimator", estimator},
                        {"forwarding", forwardingName(forwarding)},
                        {"ranks", s.ranks},
                        {"shadow_segments", s.shadow_segments},
                        {"forwards", s.forwards},
                        {"forwards_per_shadow_segment", s.forwardsPerSegment()},
                        {"forward_bytes", s.forward_bytes},
                        {"forward_messages", s.forward_messages},
                        {"forward_rounds", s.rounds},
                        {"blocked_locally", s.blocked_locally},
                        {"blocked_by_inside_proxy", s.blocked_by_inside},
                        {"undecided", s.undecided},
                        {"forwarded_segments", s.forwarded_segments},
                        {"proxy_route", forwarding == Forwarding::kProxies
                                            ? nlohmann::json(proxyRouteName(s.proxy_route))
                                            : nlohmann::json(nullptr)},
                        {"routed_by_proxies", s.routed_by_proxies},
                        {"routed_by_instance_boxes", s.routed_by_boxes},
                        {"mean_q", s.mean_q},
                        {"rank_peak_rss_bytes", s.rank_peak_rss_bytes},
                        {"seconds", s.seconds},
                        {"compute_seconds", s.max_compute_seconds},
                        {"exchange_seconds", s.max_exchange_seconds},
                        {"max_rank_forwards", s.max_rank_forwards},
                        {"forward_bytes_per_rank", double(s.forward_bytes) / s.ranks},
                        {"forward_messages_per_rank", double(s.forward_messages) / s.ranks},
                        {"max_rank_forward_bytes", s.max_rank_forward_bytes},
                        {"max_rank_forward_messages", s.max_rank_forward_messages},
                        {"network", s.network.name},
                        {"network_alpha_us", s.network.alpha_us},
                        {"network_beta_gbps", s.network.beta_gbps},
                        {"network_per_forward_us", s.network.per_item_us},
                        {"network_upper_bound", s.network.upper_bound},
                        {"network_description", s.network.describe()},
                        {"emulated", s.emulated},
                        {"emulated_wait_seconds", s.max_emulated_wait_seconds}};
  setModelledKeys(row, s.modelled);
  row["forward_cost_us"] = forward_cost_us >= 0 ? nlohmann::json(forward_cost_us) : nullptr;
  return row;
}

void setModelledKeys(nlohmann::json& row, const ModelledTime& modelled) {
  row["modelled_seconds"] = modelled.seconds;
  row["modelled_compute_seconds"] = modelled.compute_seconds;
  row["modelled_message_seconds"] = modelled.message_seconds;
  row["modelled_control_seconds"] = modelled.control_seconds;
  row["modelled_rounds"] = modelled.rounds;
}

nlohmann::json rankFactsJson(const std::vector<RankFacts>& facts) {
  nlohmann::json out = nlohmann::json::array();
  for (const RankFacts& r : facts)
    out.push_back({{"rank", r.rank},
                   {"host", r.host},
                   {"own_objects", r.own_objects},
                   {"own_triangles", r.own_triangles},
                   {"replicated_triangles", r.replicated_triangles},
                   {"proxy_triangles", r.proxy_triangles},
                   {"peak_rss_bytes", r.peak_rss_bytes},
                   {"shaded_pixels", r.shaded_pixels},
                   {"originals_opened", r.originals_opened}});
  return out;
}

std::string rankFactsText(const std::vector<RankFacts>& facts) {
  std::string out;
  for (const RankFacts& r : facts)
    out += fmt::format(
        "  rank {} ({}): {} objects, {:.2f} M own + {:.2f} M replicated triangles, {} original "
        "files, {} pixels shaded, peak RSS {:.0f} MiB\n",
        r.rank, r.host, r.own_objects, 1e-6 * double(r.own_triangles),
        1e-6 * double(r.replicated_triangles), r.originals_opened.size(), r.shaded_pixels,
        double(r.peak_rss_bytes) / double(1 << 20));
  return out;
}

}  // namespace proxyvis
