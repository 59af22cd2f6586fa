#include "study/data_parallel_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

#include "distributed/data_parallel_render.h"
#include "distributed/distributed_scene.h"
#include "distributed/mpi_comm.h"
#include "image/image_io.h"
#include "image/oiio_module.h"
#include "metrics/image_error.h"
#include "scene/scene_desc.h"
#include "study/data_parallel_rows.h"
#include "util/atomic_write.h"
#include "util/build_info.h"
#include "util/rng.h"
#include "util/staged_folder.h"

namespace proxyvis {

namespace {

using dp_study::imageName;
using dp_study::Row;

// What the flags and the scene file ask for, checked on every rank.
struct DataParallelPlan {
  std::vector<Forwarding> policies;
  std::vector<std::string> estimators;
  SceneDesc desc;
  double cost_us = -1;  // roulette's fixed forward cost, or < 0
  JobNetwork network;
};

DataParallelPlan planStudy(CompareOptions& o, const DataParallelFlags& flags,
                           const StudyFlagsGiven& given, const MpiComm& comm) {
  DataParallelPlan plan;
  comm.collectively([&] {
    if (o.out.empty()) throw Error("", "--out is required", {}, "name the report's folder");
    for (const auto& [flag, name] :
         {std::pair{given.equal_time, "--equal-time"}, std::pair{given.repeats, "--repeats"}})
      if (flag)
        throw Error("", std::string(name) + " is not available with --data-parallel",
                    "the data-parallel study compares at equal samples",
                    "drop it; its rows give measured and modelled time at each --spp");
    if (!given.estimators) o.estimators = "exact,roulette";
    o.resolve();
    for (EstimatorKind k : o.estimator_list) {
      const std::string name = estimatorName(k);
      if (name != "exact" && name != "roulette")
        throw Error("", "--estimators " + name + " is not available with --data-parallel",
                    "forwarding decides visibility exactly or by roulette",
                    "use --estimators exact,roulette");
      plan.estimators.push_back(name);
    }
    for (const std::string& name : splitCommaList(flags.forwarding)) {
      const Forwarding f = parseForwarding(name);
      if (std::find(plan.policies.begin(), plan.policies.end(), f) == plan.policies.end())
        plan.policies.push_back(f);
    }
    if (plan.policies.empty()) throw Error("", "--forwarding is empty", {}, "name a policy");
    flags.checkProxyRoute(std::find(plan.policies.begin(), plan.policies.end(),
                                    Forwarding::kProxies) != plan.policies.end());
    if (o.spp_list.empty()) throw Error("", "--spp is empty", {}, "e.g. --spp 16");
    if (comm.rank() == 0) oiioModule();
    plan.desc = loadSceneDesc(o.scene);
    o.render.applyTo(plan.desc);
  });
  plan.cost_us = flags.forward_cost_us;
  plan.network = resolveNetwork(flags, comm);
  return plan;
}

// Renders the reference and every cell (spp x policy x estimator, each over the seeds) on every
// rank; the images and errors are rank 0's.
class StudyRenders {
 public:
  StudyRenders(const CompareOptions& o, const DataParallelFlags& flags,
               const DataParallelPlan& plan, const DistributedScene& scene, const MpiComm& comm)
      : o_(o), flags_(flags), plan_(plan), scene_(scene), comm_(comm) {}

  // The reference: exact, any policy (all give the same image), its own seed stream.
  DataParallelResult reference(int reference_spp) const {
    if (comm_.rank() == 0 && !o_.common.quiet)
      std::fprintf(stderr, "render-compare: reference: exact, %d spp on %d ranks\n", reference_spp,
                   comm_.size());
    DataParallelSettings settings = settingsFor("exact", plan_.policies.front(), reference_spp,
                                                hashKeys(o_.common.seed, 1u << 20));
    settings.quiet = o_.common.quiet;
    return renderDataParallel(scene_, settings, comm_);
  }

  // Every cell; with an emulated fabric each cell twice, on this machine's shared memory and
  // under the emulation, their seeds interleaved (the machine's load drifts).
  std::vector<Row> rows(const Image& reference, std::vector<Image>& first_images) const {
    std::vector<Row> rows;
    const bool emulate = plan_.network.emulate;
    for (int spp : o_.spp_list)
      for (Forwarding f : plan_.policies)
        for (const std::string& estimator : plan_.estimators) {
          std::vector<Row> pair = cells(spp, f, estimator, emulate, reference, first_images);
          for (Row& row : pair) {
            if (comm_.rank() == 0 && !o_.common.quiet)
              std::fprintf(stderr,
                           "render-compare: %s, --forwarding %s, %d spp%s: MSE %.3e, %.3f s "
                           "(modelled on %s: %.3f s)\n",
                           estimator.c_str(), forwardingName(f), spp,
                           row.emulated() ? ", emulated" : "", row.mse, row.stats.seconds,
                           plan_.network.fabric.name.c_str(), row.stats.modelled.seconds);
            rows.push_back(std::move(row));
          }
        }
    return rows;
  }

 private:
  DataParallelSettings settingsFor(const std::string& estimator, Forwarding f, int spp,
                                   uint64_t seed) const {
    DataParallelSettings s;
    s.forwarding = f;
    s.roulette = estimator == "roulette";
    s.spp = spp;
    s.seed = seed;
    s.passes_per_round = flags_.passes_per_round;
    s.q_min = o_.render.q_min;
    s.forward_cost_us = plan_.cost_us;
    s.local_cost_us = flags_.local_cost_us;
    s.proxy_route = flags_.proxyRoute();
    s.network = plan_.network.fabric;
    s.quiet = true;
    return s;
  }

  // One cell on shared memory, and with `emulate` once more under the emulated fabric.
  std::vector<Row> cells(int spp, Forwarding f, const std::string& estimator, bool emulate,
                         const Image& reference, std::vector<Image>& first_images) const {
    const bool root = comm_.rank() == 0;
    std::vector<Row> rows(emulate ? 2 : 1);
    for (size_t k = 0; k < rows.size(); ++k) {
      rows[k].spp = spp;
      rows[k].estimator = estimator;
      rows[k].forwarding = f;
    }
    std::vector<Image> firsts(rows.size());
    for (int seed = 0; seed < o_.seeds; ++seed)
      for (size_t k = 0; k < rows.size(); ++k) {
        Row& row = rows[k];
        DataParallelSettings settings =
            settingsFor(estimator, f, spp, hashKeys(o_.common.seed, uint64_t(seed)));
        settings.emulate = k == 1;
        const DataParallelResult r = renderDataParallel(scene_, settings, comm_);
        row.addSeed(r.stats, seed == 0);
        if (seed == 0 && root) firsts[k] = r.radiance;
        if (root) row.mse += meanSquaredError(r.radiance.pixels, reference.pixels);
      }
    for (size_t k = 0; k < rows.size(); ++k) {
      rows[k].finishSeeds(o_.seeds);
      if (root) first_images.push_back(std::move(firsts[k]));
    }
    return rows;
  }

  const CompareOptions& o_;
  const DataParallelFlags& flags_;
  const DataParallelPlan& plan_;
  const DistributedScene& scene_;
  const MpiComm& comm_;
};

// Efficiency 1/(MSE x time), relative to exact with replicated instance boxes at the same spp
// and on the same fabric (shared memory, or emulated) (the fair baseline), else the first exact
// row.
void scoreRows(std::vector<Row>& rows) {
  for (Row& r : rows) {
    const double seconds = r.stats.seconds, modelled = r.stats.modelled.seconds;
    r.efficiency = r.mse > 0 && seconds > 0 ? 1 / (r.mse * seconds) : 0;
    r.modelled_efficiency = r.mse > 0 && modelled > 0 ? 1 / (r.mse * modelled) : 0;
  }
  for (Row& r : rows) {
    const Row* base = nullptr;
    for (const Row& b : rows)
      if (b.spp == r.spp && b.estimator == "exact" && b.emulated() == r.emulated() &&
          (!base || b.forwarding == Forwarding::kInstanceBoxes))
        base = &b;
    if (!base) base = &rows.front();
    r.relative = base->efficiency > 0 ? r.efficiency / base->efficiency : 0;
    r.modelled_relative =
        base->modelled_efficiency > 0 ? r.modelled_efficiency / base->modelled_efficiency : 0;
  }
}

nlohmann::json rowsJson(const std::vector<Row>& rows, int seeds, double cost_us) {
  nlohmann::json json_rows = nlohmann::json::array();
  for (const Row& r : rows) {
    nlohmann::json j = dataParallelRow(r.estimator, r.forwarding, r.stats, cost_us);
    j["table"] = "equal-spp";
    j["spp"] = r.spp;
    j["seeds"] = seeds;
    j["mse"] = r.mse;
    j["efficiency"] = r.efficiency;
    j["relative_efficiency"] = r.relative;
    j["modelled_efficiency"] = r.modelled_efficiency;
    j["modelled_relative_efficiency"] = r.modelled_relative;
    j["image"] = "images/" + imageName(r) + ".exr";
    json_rows.push_back(j);
  }
  return json_rows;
}

// Why each row that forwards fewer rays than its baseline still loses to it in measured time:
// where its time went, against the baseline's.
std::vector<std::string> losingNotes(const std::vector<Row>& rows) {
  std::vector<std::string> notes;
  for (const Row& r : rows) {
    if (r.relative >= 1 || r.forwarding != Forwarding::kProxies) continue;
    const Row* base = nullptr;
    for (const Row& b : rows)
      if (b.spp == r.spp && b.estimator == "exact" && b.emulated() == r.emulated() &&
          b.forwarding == Forwarding::kInstanceBoxes)
        base = &b;
    if (!base) continue;
    notes.push_back(fmt::format(
        "{} with proxies at {} spp{} measured {:.2f}x instance boxes: the slowest rank's compute "
        "{:.3f} s against {:.3f} s (traces of proxies and answers), its time in exchanges {:.3f} "
        "s against {:.3f} s, for {:.4f} forwards per segment against {:.4f}{}.",
        r.estimator, r.spp, r.emulated() ? " (emulated " + r.stats.network.name + ")" : "",
        r.relative, r.stats.max_compute_seconds, base->stats.max_compute_seconds,
        r.stats.max_exchange_seconds, base->stats.max_exchange_seconds,
        r.stats.forwardsPerSegment(), base->stats.forwardsPerSegment(),
        r.mse > base->mse * 1.0001
            ? fmt::format(", and an MSE {:.3g}x the baseline's", r.mse / base->mse)
            : ""));
  }
  return notes;
}

}  // namespace

int runDataParallelStudy(CompareOptions& o, const DataParallelFlags& flags,
                         const StudyFlagsGiven& given) {
  MpiComm comm(nullptr, nullptr);
  try {
    const DataParallelPlan plan = planStudy(o, flags, given, comm);
    const SceneDesc& desc = plan.desc;
    const double cost_us = plan.cost_us;
    const NetworkFabric& fabric = plan.network.fabric;
    const bool proxies = std::find(plan.policies.begin(), plan.policies.end(),
                                   Forwarding::kProxies) != plan.policies.end();
    const auto scene =
        DistributedScene::load(desc, distributedSceneOptions(o.render, proxies, comm), comm);
    const StudyRenders renders(o, flags, plan, *scene, comm);
    const int reference_spp = o.referenceSpp(o.spp_list.back());
    const DataParallelResult reference = renders.reference(reference_spp);
    std::vector<Image> first_images;
    std::vector<Row> rows = renders.rows(reference.radiance, first_images);
    const std::vector<RankFacts> facts = gatherRankFacts(*scene, reference.stats, comm);
    if (comm.rank() != 0) return kExitOk;

    scoreRows(rows);
    std::string model_note = fmt::format(
        "Measured: wall time on this machine, whose ranks talk through shared memory ({}){}. "
        "Modelled: an alpha-beta model of {} from the measured per-round counts, not a "
        "measurement: the sum over exchange rounds of the slowest rank's (compute, as wall time "
        "outside MPI calls, + its messages x alpha + its bytes / beta), plus each round's count "
        "exchange (ceil(log2 P) alpha) and the hit and image reductions.",
        plan.network.shm.describe(),
        plan.network.emulate ? fmt::format("; rows run on 'emulated {}' waited in the run for "
                                           "what that fabric charges",
                                           fabric.name)
                             : "",
        fabric.describe());
    for (const std::string& why : losingNotes(rows)) model_note += " " + why;
    const std::string resolution = fmt::format("{}x{}", desc.camera.width, desc.camera.height);
    const nlohmann::json report = {
        {"program", "render-compare"},
        {"mode", "data-parallel"},
        {"scene", desc.path.string()},
        {"scene_name", desc.displayName()},
        {"ranks", comm.size()},
        {"resolution", resolution},
        {"seeds", o.seeds},
        {"seed", o.common.seed},
        {"reference_spp", reference_spp},
        {"reference_seconds", reference.stats.seconds},
        {"forward_cost_us", cost_us >= 0 ? nlohmann::json(cost_us) : nlohmann::json(nullptr)},
        {"network", fabric.name},
        {"network_alpha_us", fabric.alpha_us},
        {"network_beta_gbps", fabric.beta_gbps},
        {"network_description", fabric.describe()},
        {"shm_alpha_us", plan.network.shm.alpha_us},
        {"shm_beta_gbps", plan.network.shm.beta_gbps},
        {"emulated", plan.network.emulate},
        {"scene_build", scene->buildChoice().name()},
        {"notes", {model_note}},
        {"per_rank", rankFactsJson(facts)},
        {"rows", rowsJson(rows, o.seeds, cost_us)},
        {"build", buildText()},
        {"version", versionText()}};
    const TextTable table_cells = dp_study::studyTable(rows, fabric.name);
    const std::string table = markdownTable(table_cells);
    const std::string md = fmt::format(
        "# render-compare (data-parallel): {}\n\n{} ranks, {}, reference exact {} spp; {} "
        "seed(s) per cell; efficiency = 1/(MSE x time) relative to exact with instance-box "
        "forwarding.\n\n{}\n{}\n\nRanks:\n\n{}",
        desc.displayName(), comm.size(), resolution, reference_spp, o.seeds, table, model_note,
        rankFactsText(facts));

    StagedFolder folder(o.out, "render-compare");
    StudyReportFiles files{
        report.dump(2) + "\n",
        md,
        fmt::format("{} (data-parallel, {} ranks)", desc.displayName(), comm.size()),
        htmlTable(table_cells),
        {model_note},
        &reference.radiance,
        {}};
    for (size_t i = 0; i < rows.size(); ++i)
      files.images.emplace_back(imageName(rows[i]), &first_images[i]);
    writeStudyReport(folder.path(), files);
    folder.commit();
    printHumanReport(o.common, table + "\n" + model_note + "\n" +
                                   "report: " + (folder.target() / "report.html").string() + "\n");
    return kExitOk;
  } catch (const ReportedOnAnotherRank&) {
    return kExitOk;  // rank 0 reports the job's error and exit code (see ReportedOnAnotherRank)
  }
}

}  // namespace proxyvis
