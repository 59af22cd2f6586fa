#include "render_data_parallel.h"

#include <fmt/format.h>
#include <tbb/global_control.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

#include "distributed/data_parallel_render.h"
#include "distributed/distributed_scene.h"
#include "distributed/mpi_comm.h"
#include "image/image_io.h"
#include "image/oiio_module.h"
#include "render/image_metadata.h"
#include "render_image.h"
#include "scene/scene_desc.h"
#include "util/build_info.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/rng.h"

namespace proxyvis {

namespace {

// Fault injection for the tests: the rank named by PROXYVIS_TEST_KILL_RANK dies by SIGKILL once
// the scene is loaded, as a node that fails mid-job would.
void maybeDieForTest(int rank) {
  const char* k = std::getenv("PROXYVIS_TEST_KILL_RANK");
  if (k && std::atoi(k) == rank) std::raise(SIGKILL);
}

// Fault injection for the tests: with PROXYVIS_TEST_SLOW_ERROR=S, rank 0 waits S seconds before
// it reports the job's error, as a loaded machine made it: no other rank may end the job first.
void maybeSlowErrorForTest(int rank) {
  const char* s = std::getenv("PROXYVIS_TEST_SLOW_ERROR");
  if (s && rank == 0) std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(s)));
}

Image dataParallelExr(const DataParallelResult& r) {
  const size_t n = size_t(r.radiance.width) * size_t(r.radiance.height);
  Image out{r.radiance.width, r.radiance.height, 6, std::vector<float>(n * 6)};
  for (size_t i = 0; i < n; ++i) {
    float* px = &out.pixels[i * 6];
    std::copy_n(&r.radiance.pixels[i * 3], 3, px);
    px[3] = r.visibility.pixels[i];
    px[4] = r.forwards.pixels[i];
    px[5] = r.owner.pixels[i];
  }
  return out;
}

DataParallelSettings dataParallelSettings(const DataParallelRenderRequest& o, Forwarding forwarding,
                                          const JobNetwork& network) {
  DataParallelSettings settings;
  settings.forwarding = forwarding;
  settings.roulette = o.estimator == "roulette";
  settings.spp = o.spp;
  // Seed index 0 of --seed, as render and render-compare: the images agree.
  settings.seed = hashKeys(o.common.seed, 0);
  settings.passes_per_round = o.data_parallel.passes_per_round;
  settings.q_min = o.render.q_min;
  settings.forward_cost_us = o.data_parallel.forward_cost_us;
  settings.local_cost_us = o.data_parallel.local_cost_us;
  settings.proxy_route = o.data_parallel.proxyRoute();
  settings.network = network.fabric;
  settings.emulate = network.emulate;
  settings.quiet = o.common.quiet;
  return settings;
}

// The --json summary: the data-parallel row with what this run rendered.
nlohmann::json renderSummary(const DataParallelRenderRequest& o, const SceneDesc& desc,
                             Forwarding forwarding, const DataParallelResult& result,
                             const std::vector<RankFacts>& facts, const std::string& build) {
  nlohmann::json summary =
      dataParallelRow(o.estimator, forwarding, result.stats, o.data_parallel.forward_cost_us);
  summary["program"] = "render";
  summary["scene"] = desc.path.string();
  summary["output"] = o.output.string();
  summary["spp"] = result.spp;
  summary["seed"] = o.common.seed;
  summary["width"] = result.radiance.width;
  summary["height"] = result.radiance.height;
  summary["threads"] =
      int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  summary["scene_build"] = build;
  summary["per_rank"] = rankFactsJson(facts);
  summary["build"] = buildText();
  summary["version"] = versionText();
  return summary;
}

std::string renderReportText(const DataParallelRenderRequest& o, Forwarding forwarding,
                             const DataParallelResult& result, const std::vector<RankFacts>& facts,
                             int ranks) {
  const DataParallelStats& s = result.stats;
  return fmt::format(
      "render: wrote {}: {} with --forwarding {} on {} rank{}, {} spp in {:.2f} s\n"
      "  shadow segments {}: {:.4f} forwards each ({} forwards, {:.1f} MB in {} "
      "messages over {} rounds); blocked here {}, by inside proxies {}, "
      "undecided {}\n  network {}{}: modelled {:.3f} s (compute {:.3f} s, "
      "messages {:.3f} s, counts and reductions {:.3f} s)\n{}",
      o.output.string(), o.estimator, forwardingName(forwarding), ranks, ranks == 1 ? "" : "s",
      result.spp, s.seconds, s.shadow_segments, s.forwardsPerSegment(), s.forwards,
      1e-6 * double(s.forward_bytes), s.forward_messages, s.rounds, s.blocked_locally,
      s.blocked_by_inside, s.undecided, s.network.describe(),
      s.emulated ? ", emulated in the run" : "", s.modelled.seconds, s.modelled.compute_seconds,
      s.modelled.message_seconds, s.modelled.control_seconds, rankFactsText(facts));
}

}  // namespace

int runDataParallelRender(DataParallelRenderRequest& o) {
  MpiComm comm(nullptr, nullptr);
  try {
    const bool root = comm.rank() == 0;
    Forwarding forwarding{};
    RenderImageFormat format{};
    SceneDesc desc;
    std::future<void> image_module;
    // Refused on every rank alike, so that rank 0 alone prints the line (MpiComm::agree).
    comm.collectively([&] {
      if (o.seconds > 0)
        throw Error("", "--time is not available with --data-parallel", {}, "use --spp");
      if (o.output == "-")
        throw Error("-o -", "an image cannot be written to stdout", {},
                    "name an .exr or .png file");
      if (o.estimator != "exact" && o.estimator != "roulette")
        throw Error("", "--estimator " + o.estimator + " is not available with --data-parallel",
                    "forwarding decides visibility exactly or by roulette",
                    "use --estimator exact or roulette");
      forwarding = parseForwarding(o.data_parallel.forwarding);
      o.data_parallel.checkProxyRoute(forwarding == Forwarding::kProxies);
      if (root)
        checkOutputs({o.scene.string()},
                     {{"-o", o.output.string()}, {"--json", o.common.json_path}});
      format = renderImageFormat(o.output);
      // The image writer, while the scene loads.
      if (root) image_module = preloadOiioModuleFor(o.output);
      o.render.resolve();
      desc = loadSceneDesc(o.scene);
      o.render.applyTo(desc);
    });

    const auto scene = DistributedScene::load(
        desc, distributedSceneOptions(o.render, forwarding == Forwarding::kProxies, comm), comm);
    maybeDieForTest(comm.rank());
    const JobNetwork network = resolveNetwork(o.data_parallel, comm);
    // A missing image module ends every rank now, not after the render.
    comm.collectively([&] {
      if (root) image_module.get();
    });

    const DataParallelSettings settings = dataParallelSettings(o, forwarding, network);
    const DataParallelResult result = renderDataParallel(*scene, settings, comm);
    const std::vector<RankFacts> facts = gatherRankFacts(*scene, result.stats, comm);
    if (!root) return kExitOk;

    RenderMetadata meta{"render", o.estimator, result.spp, result.stats.seconds, o.common.seed, {}};
    meta.extra.push_back({"proxyvis:forwarding", std::string(forwardingName(forwarding))});
    meta.extra.push_back({"proxyvis:ranks", std::to_string(comm.size())});
    const RenderImageFile file = renderImageFile(
        format, result.radiance, [&] { return dataParallelExr(result); },
        {"R", "G", "B", "visibility.Y", "forwards.Y", "rank.Y"}, renderAttributes(desc, meta));
    const nlohmann::json summary =
        renderSummary(o, desc, forwarding, result, facts, scene->buildChoice().name());
    OutputSet outputs(MissingFolders::kCreate);
    outputs.add(o.output,
                [&](const std::filesystem::path& tmp) { writeImage(file.image, tmp, file.write); });
    if (!o.common.json_path.empty()) outputs.addText(o.common.json_path, summary.dump(2) + "\n");
    outputs.commit();

    printHumanReport(o.common, renderReportText(o, forwarding, result, facts, comm.size()));
    return kExitOk;
  } catch (const ReportedOnAnotherRank&) {
    return kExitOk;  // rank 0 reports the job's error and exit code (see ReportedOnAnotherRank)
  } catch (const Error&) {
    maybeSlowErrorForTest(comm.rank());
    throw;
  }
}

}  // namespace proxyvis
