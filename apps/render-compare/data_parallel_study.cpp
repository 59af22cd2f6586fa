#include "data_parallel_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

#include "distributed/data_parallel_render.h"
#include "distributed/distributed_scene.h"
#include "distributed/mpi_comm.h"
#include "metrics/image_error.h"
#include "render/image_io.h"
#include "render/oiio_module.h"
#include "scene/scene_desc.h"
#include "util/atomic_write.h"
#include "util/build_info.h"
#include "util/rng.h"
#include "util/staged_folder.h"

namespace proxyvis {

namespace {

// Roulette's and the model's cost of a forward when --forward-cost-us is not given: the low end
// of the 20-200 us range of cluster interconnects with a remote trace (docs/data_parallel.md).
constexpr double kDefaultForwardCostUs = 20;

struct Row {
  int spp = 0;
  std::string estimator;
  Forwarding forwarding{};
  double mse = 0, seconds = 0, modelled_seconds = 0;
  DataParallelStats stats;  // of the first seed; counts summed over seeds below
  uint64_t segments = 0, forwards = 0, bytes = 0, messages = 0, peak_rss = 0;
  double efficiency = 0, modelled_efficiency = 0, relative = 0, modelled_relative = 0;
};

std::string imageName(const Row& r) {
  return fmt::format("{}_{}_{}spp", r.estimator, forwardingName(r.forwarding), r.spp);
}

void writePair(const Image& image, const std::filesystem::path& stem, float exposure) {
  ImageWriteOptions exr;
  exr.full_float = true;
  writeImage(image, stem.string() + ".exr", exr);
  ImageWriteOptions png;
  png.exposure = exposure;
  writeImage(image, stem.string() + ".png", png);
}

// The table's columns and each row's cells, shared by report.md and report.html.
std::vector<std::string> tableHeader(double cost_us) {
  return {"spp",
          "estimator",
          "forwarding",
          "forwards / shadow segment",
          "forward MB",
          "messages",
          "rank peak RSS MiB",
          "seconds",
          "MSE",
          "efficiency (measured)",
          fmt::format("efficiency at {:g} us / forward (model)", cost_us)};
}

std::vector<std::string> tableCells(const Row& r) {
  return {std::to_string(r.spp),
          r.estimator,
          forwardingName(r.forwarding),
          fmt::format("{:.4f}", r.segments ? double(r.forwards) / double(r.segments) : 0.0),
          fmt::format("{:.2f}", 1e-6 * double(r.bytes)),
          std::to_string(r.messages),
          fmt::format("{:.0f}", double(r.peak_rss) / double(1 << 20)),
          fmt::format("{:.3f}", r.seconds),
          fmt::format("{:.3e}", r.mse),
          fmt::format("{:.2f}x", r.relative),
          fmt::format("{:.2f}x", r.modelled_relative)};
}

std::string markdownTable(const std::vector<Row>& rows, double cost_us) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string t = "|";
    for (const std::string& c : cells) t += " " + c + " |";
    return t + "\n";
  };
  std::string t =
      line(tableHeader(cost_us)) + "|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows) t += line(tableCells(r));
  return t;
}

std::string htmlTable(const std::vector<Row>& rows, double cost_us) {
  std::string t = "<table><tr>";
  for (const std::string& h : tableHeader(cost_us)) t += "<th>" + h + "</th>";
  t += "</tr>";
  for (const Row& r : rows) {
    t += "<tr>";
    for (const std::string& c : tableCells(r)) t += "<td>" + c + "</td>";
    t += "</tr>";
  }
  return t + "</table>";
}

}  // namespace

int runDataParallelStudy(CompareOptions& o, const DataParallelFlags& flags, bool estimators_given) {
  MpiComm comm(nullptr, nullptr);
  try {
    const bool root = comm.rank() == 0;
    std::vector<Forwarding> policies;
    std::vector<std::string> estimators;
    SceneDesc desc;
    comm.collectively([&] {
      if (o.out.empty()) throw Error("", "--out is required", {}, "name the report's folder");
      if (!estimators_given) o.estimators = "exact,roulette";
      o.resolve();
      for (EstimatorKind k : o.estimator_list) {
        const std::string name = estimatorName(k);
        if (name != "exact" && name != "roulette")
          throw Error("", "--estimators " + name + " is not available with --data-parallel",
                      "forwarding decides visibility exactly or by roulette",
                      "use --estimators exact,roulette");
        estimators.push_back(name);
      }
      for (const std::string& name : splitCommaList(flags.forwarding)) {
        const Forwarding f = parseForwarding(name);
        if (std::find(policies.begin(), policies.end(), f) == policies.end()) policies.push_back(f);
      }
      if (policies.empty()) throw Error("", "--forwarding is empty", {}, "name a policy");
      if (o.spp_list.empty()) throw Error("", "--spp is empty", {}, "e.g. --spp 16");
      if (root) oiioModule();
      desc = loadSceneDesc(o.scene);
      o.render.applyTo(desc);
    });
    const double cost_us =
        flags.forward_cost_us >= 0 ? flags.forward_cost_us : kDefaultForwardCostUs;
    const bool proxies =
        std::find(policies.begin(), policies.end(), Forwarding::kProxies) != policies.end();
    const auto scene =
        DistributedScene::load(desc, distributedSceneOptions(o.render, proxies), comm);

    auto settingsFor = [&](const std::string& estimator, Forwarding f, int spp, uint64_t seed) {
      DataParallelSettings s;
      s.forwarding = f;
      s.roulette = estimator == "roulette";
      s.spp = spp;
      s.seed = seed;
      s.passes_per_round = flags.passes_per_round;
      s.q_min = o.render.q_min;
      s.forward_cost_us = cost_us;
      s.local_cost_us = flags.local_cost_us;
      s.quiet = true;
      return s;
    };
    // The reference: exact, any policy (all give the same image), its own seed stream.
    const int largest = o.spp_list.back();
    const int reference_spp = o.referenceSpp(largest);
    if (root && !o.common.quiet)
      std::fprintf(stderr, "render-compare: reference: exact, %d spp on %d ranks\n", reference_spp,
                   comm.size());
    DataParallelSettings ref_settings =
        settingsFor("exact", policies.front(), reference_spp, hashKeys(o.common.seed, 1u << 20));
    ref_settings.quiet = o.common.quiet;
    const DataParallelResult reference = renderDataParallel(*scene, ref_settings, comm);

    std::vector<Row> rows;
    std::vector<Image> first_images;
    for (int spp : o.spp_list)
      for (Forwarding f : policies)
        for (const std::string& estimator : estimators) {
          Row row;
          row.spp = spp;
          row.estimator = estimator;
          row.forwarding = f;
          for (int seed = 0; seed < o.seeds; ++seed) {
            const DataParallelResult r = renderDataParallel(
                *scene, settingsFor(estimator, f, spp, hashKeys(o.common.seed, uint64_t(seed))),
                comm);
            const DataParallelStats& s = r.stats;
            if (seed == 0) {
              row.stats = s;
              if (root) first_images.push_back(r.radiance);
            }
            if (root) row.mse += meanSquaredError(r.radiance.pixels, reference.radiance.pixels);
            row.seconds += s.seconds;
            row.modelled_seconds += s.modelledSeconds(cost_us);
            row.segments += s.shadow_segments;
            row.forwards += s.forwards;
            row.bytes += s.forward_bytes;
            row.messages += s.forward_messages;
            row.peak_rss = std::max(row.peak_rss, s.rank_peak_rss_bytes);
          }
          row.mse /= o.seeds;
          row.seconds /= o.seeds;
          row.modelled_seconds /= o.seeds;
          if (root && !o.common.quiet)
            std::fprintf(stderr, "render-compare: %s, --forwarding %s, %d spp: MSE %.3e, %.3f s\n",
                         estimator.c_str(), forwardingName(f), spp, row.mse, row.seconds);
          rows.push_back(row);
        }
    const std::vector<RankFacts> facts = gatherRankFacts(*scene, reference.stats, comm);
    if (!root) return kExitOk;

    // Efficiency 1/(MSE x time), relative to exact with replicated instance boxes at the same
    // spp (the fair baseline), else the first exact row.
    for (Row& r : rows) {
      r.efficiency = r.mse > 0 && r.seconds > 0 ? 1 / (r.mse * r.seconds) : 0;
      r.modelled_efficiency =
          r.mse > 0 && r.modelled_seconds > 0 ? 1 / (r.mse * r.modelled_seconds) : 0;
    }
    for (Row& r : rows) {
      const Row* base = nullptr;
      for (const Row& b : rows)
        if (b.spp == r.spp && b.estimator == "exact" &&
            (!base || b.forwarding == Forwarding::kInstanceBoxes))
          base = &b;
      if (!base) base = &rows.front();
      r.relative = base->efficiency > 0 ? r.efficiency / base->efficiency : 0;
      r.modelled_relative =
          base->modelled_efficiency > 0 ? r.modelled_efficiency / base->modelled_efficiency : 0;
    }

    nlohmann::json json_rows = nlohmann::json::array();
    for (const Row& r : rows) {
      nlohmann::json j = dataParallelRow(r.estimator, r.forwarding, r.stats, cost_us);
      j["table"] = "equal-spp";
      j["spp"] = r.spp;
      j["seeds"] = o.seeds;
      // Over all seeds (the stats of dataParallelRow are the first seed's).
      j["shadow_segments"] = r.segments;
      j["forwards"] = r.forwards;
      j["forwards_per_shadow_segment"] = r.segments ? double(r.forwards) / double(r.segments) : 0.0;
      j["forward_bytes"] = r.bytes / uint64_t(o.seeds);
      j["forward_messages"] = r.messages / uint64_t(o.seeds);
      j["rank_peak_rss_bytes"] = r.peak_rss;
      j["seconds"] = r.seconds;
      j["modelled_seconds"] = r.modelled_seconds;
      j["mse"] = r.mse;
      j["efficiency"] = r.efficiency;
      j["relative_efficiency"] = r.relative;
      j["modelled_efficiency"] = r.modelled_efficiency;
      j["modelled_relative_efficiency"] = r.modelled_relative;
      j["image"] = "images/" + imageName(r) + ".exr";
      json_rows.push_back(j);
    }
    const std::string model_note = fmt::format(
        "Modelled efficiency: a model from the measured counts, not a measurement: time = the "
        "slowest rank's compute time (MPI waits excluded) + the busiest rank's forwards x {:g} "
        "us per forward. Measured efficiency uses the wall time on this machine, where a forward "
        "costs what shared-memory MPI costs (a few us).",
        cost_us);
    nlohmann::json report = {
        {"program", "render-compare"},
        {"mode", "data-parallel"},
        {"scene", desc.path.string()},
        {"scene_name", desc.displayName()},
        {"ranks", comm.size()},
        {"resolution", fmt::format("{}x{}", desc.camera.width, desc.camera.height)},
        {"seeds", o.seeds},
        {"seed", o.common.seed},
        {"reference_spp", reference_spp},
        {"reference_seconds", reference.stats.seconds},
        {"forward_cost_us", cost_us},
        {"scene_build", scene->buildChoice().name()},
        {"notes", {model_note}},
        {"per_rank", rankFactsJson(facts)},
        {"rows", json_rows},
        {"build", buildText()},
        {"version", versionText()}};

    const std::string table = markdownTable(rows, cost_us);
    std::string md = fmt::format(
        "# render-compare (data-parallel): {}\n\n{} ranks, {}, reference exact {} spp; {} "
        "seed(s) per cell; efficiency = 1/(MSE x time) relative to exact with instance-box "
        "forwarding.\n\n{}\n{}\n\nRanks:\n\n{}",
        desc.displayName(), comm.size(), report["resolution"].get<std::string>(), reference_spp,
        o.seeds, table, model_note, rankFactsText(facts));
    std::string html =
        "<!doctype html><html><head><meta charset=\"utf-8\"><title>render-compare "
        "(data-parallel)</title><style>body{font-family:sans-serif}table{border-"
        "collapse:collapse}td,th{border:1px solid #ccc;padding:3px 6px}img{image-"
        "rendering:pixelated;width:320px}</style></head><body>";
    html += fmt::format("<h1>{} (data-parallel, {} ranks)</h1><p>{}</p>{}", desc.displayName(),
                        comm.size(), model_note, htmlTable(rows, cost_us));
    html +=
        "<h2>Images</h2><p><figure style=\"display:inline-block\"><img "
        "src=\"images/reference.png\"><figcaption>reference</figcaption></figure>";
    for (const Row& r : rows)
      html += fmt::format(
          "<figure style=\"display:inline-block\"><img src=\"images/{}.png\">"
          "<figcaption>{}</figcaption></figure>",
          imageName(r), imageName(r));
    html += "</p></body></html>\n";

    StagedFolder folder(o.out, "render-compare");
    const std::filesystem::path dir = folder.path();
    std::filesystem::create_directories(dir / "images");
    const float exposure = autoExposure(reference.radiance);
    writePair(reference.radiance, dir / "images" / "reference", exposure);
    for (size_t i = 0; i < rows.size(); ++i)
      writePair(first_images[i], dir / "images" / imageName(rows[i]), exposure);
    writeTextAtomically(dir / "report.json", report.dump(2) + "\n");
    writeTextAtomically(dir / "report.md", md);
    writeTextAtomically(dir / "report.html", html);
    folder.commit();
    printHumanReport(o.common, table + "\n" + model_note + "\n" +
                                   "report: " + (folder.target() / "report.html").string() + "\n");
    return kExitOk;
  } catch (const ReportedOnAnotherRank&) {
    return kExitOk;  // rank 0 reports the job's error and exit code (see ReportedOnAnotherRank)
  }
}

}  // namespace proxyvis
