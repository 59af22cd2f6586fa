#include "study/out_of_core_study.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>

#include "image/image_io.h"
#include "image/oiio_module.h"
#include "metrics/image_error.h"
#include "outofcore/geometry_budget.h"
#include "outofcore/out_of_core_scene.h"
#include "scene/scene_desc.h"
#include "study/out_of_core_rows.h"
#include "util/atomic_write.h"
#include "util/build_info.h"
#include "util/output_path.h"
#include "util/rng.h"
#include "util/staged_folder.h"

namespace proxyvis {

namespace {

using OocRow = ooc_study::Row;

// Queued light samples of one reference batch at most: the queues of a whole frame of a
// converged reference would not fit in memory.
constexpr size_t kReferenceBatchItems = size_t(1) << 22;

struct StudyPlanOoc {
  std::vector<OutOfCorePolicy> policies;
  std::vector<int> batch_passes;
  SceneDesc desc;
};

StudyPlanOoc planStudy(CompareOptions& o, const OutOfCoreStudyFlags& flags,
                       const StudyFlagsGiven& given) {
  if (o.out.empty()) throw Error("", "--out is required", {}, "name the report's folder");
  for (const auto& [flag, name] :
       {std::pair{given.equal_time, "--equal-time"}, std::pair{given.repeats, "--repeats"},
        std::pair{given.estimators, "--estimators"}})
    if (flag)
      throw Error("", std::string(name) + " is not available with --geometry-budget",
                  "the out-of-core study compares its policies at equal samples",
                  "drop it; --ooc-policies names what is compared, and each row gives its "
                  "efficiency 1/(MSE x time)");
  o.estimators = "exact";
  o.equal_time = 0;
  o.resolve();
  StudyPlanOoc plan;
  for (const std::string& name : splitCommaList(flags.policies)) {
    const OutOfCorePolicy p = parseOutOfCorePolicy(name);
    if (std::find(plan.policies.begin(), plan.policies.end(), p) == plan.policies.end())
      plan.policies.push_back(p);
  }
  if (plan.policies.empty()) throw Error("", "--ooc-policies is empty", {}, "name a policy");
  const CLI::Validator passes = integerIn(0, 1 << 20);
  for (const std::string& item : splitCommaList(flags.batch_passes)) {
    if (const std::string problem = passes(item); !problem.empty())
      throw Error("", "--batch-passes: " + problem, {}, "give a list such as 0,4");
    const int n = std::stoi(item);
    if (std::find(plan.batch_passes.begin(), plan.batch_passes.end(), n) == plan.batch_passes.end())
      plan.batch_passes.push_back(n);
  }
  if (plan.batch_passes.empty()) throw Error("", "--batch-passes is empty", {}, "e.g. 0");
  OutOfCoreSettings check;
  applyLoadQ(flags.load_q, check);  // a bad --load-q fails before the scene loads
  checkOutputs({o.scene.string()}, {{"--out", o.out.string(), /*is_folder=*/true}});
  plan.desc = loadSceneDesc(o.scene);
  o.render.applyTo(plan.desc);
  return plan;
}

class OutOfCoreStudy {
 public:
  OutOfCoreStudy(const CompareOptions& o, const OutOfCoreStudyFlags& flags,
                 const StudyPlanOoc& plan, const OutOfCoreScene& scene, uint64_t budget)
      : o_(o), flags_(flags), plan_(plan), scene_(scene), budget_(budget) {}

  // Every configuration over the seeds, interleaved seed by seed (the machine's load drifts);
  // each render's image is kept until the reference scores it.
  void renderRows() {
    for (int spp : o_.spp_list)
      for (int passes : plan_.batch_passes)
        for (bool cold : {false, true})
          for (OutOfCorePolicy p : plan_.policies) {
            if (cold && !flags_.cold_reads) continue;
            OocRow r;
            r.cold_reads = cold;
            r.policy = p;
            r.spp = spp;
            r.batch_passes = passes;
            r.budget_bytes = budget_;
            if (p == OutOfCorePolicy::kProxiesRoulette)
              r.load_q = loadQText(settingsFor(p, spp, passes));
            rows_.push_back(r);
          }
    images_.resize(rows_.size());
    for (int seed = 0; seed < o_.seeds; ++seed)
      for (size_t i = 0; i < rows_.size(); ++i) {
        OocRow& row = rows_[i];
        OutOfCoreSettings s = settingsFor(row.policy, row.spp, row.batch_passes);
        s.seed = hashKeys(o_.common.seed, uint64_t(seed));
        s.cold_reads = row.cold_reads;
        // Its peak RSS its own: the render hands the heap's freed memory back and resets the
        // high-water mark before it starts (util/peak_rss.h).
        const OutOfCoreResult r = renderOutOfCore(scene_, s);
        if (!o_.common.quiet)
          std::fprintf(
              stderr,
              "render-compare: %s, %d spp, %s%s, seed %d/%d: %.2f s, %llu loads (%.2f s), "
              "peak RSS %.0f MiB\n",
              outOfCorePolicyName(row.policy), row.spp,
              row.batch_passes > 0 ? fmt::format("{} passes per batch", row.batch_passes).c_str()
                                   : "one batch",
              row.cold_reads ? ", cold reads" : "", seed + 1, o_.seeds, r.stats.seconds,
              static_cast<unsigned long long>(r.stats.cache.loads), r.stats.cache.loadSeconds(),
              double(r.stats.peak_rss_bytes) / double(1 << 20));
        row.add(r.stats, 0);
        images_[i].push_back(r.radiance);
      }
  }

  // The exact reference at reference_spp: everything resident (the budget is the whole scene),
  // in batches that fit in memory; rendered after the rows so that its memory is not theirs.
  OutOfCoreResult reference(int reference_spp) const {
    if (!o_.common.quiet)
      std::fprintf(stderr, "render-compare: reference: exact, %d spp, every original resident\n",
                   reference_spp);
    const size_t pixels = size_t(plan_.desc.camera.width) * size_t(plan_.desc.camera.height);
    const int passes = int(std::clamp<size_t>(kReferenceBatchItems / std::max<size_t>(pixels, 1), 1,
                                              size_t(reference_spp)));
    OutOfCoreSettings s = settingsFor(OutOfCorePolicy::kExactBatched, reference_spp, passes);
    s.budget_bytes = std::max(budget_, scene_.inCoreBytes());
    s.seed = hashKeys(o_.common.seed, 1u << 20);
    s.quiet = o_.common.quiet;
    return renderOutOfCore(scene_, s);
  }

  // MSE of every kept image against the reference; the rows' means and scores.
  std::vector<OocRow> score(const Image& reference) {
    for (size_t i = 0; i < rows_.size(); ++i) {
      for (const Image& image : images_[i])
        rows_[i].mse += meanSquaredError(image.pixels, reference.pixels);
      rows_[i].finish();
    }
    ooc_study::scoreRows(rows_);
    return rows_;
  }

  // The first seed's image of each row.
  const Image& firstImage(size_t row) const { return images_[row].front(); }

 private:
  OutOfCoreSettings settingsFor(OutOfCorePolicy p, int spp, int passes) const {
    OutOfCoreSettings s;
    s.policy = p;
    s.spp = spp;
    s.batch_passes = passes;
    s.budget_bytes = budget_;
    if (p == OutOfCorePolicy::kProxiesRoulette) applyLoadQ(flags_.load_q, s);
    s.q_min = o_.render.q_min;
    s.quiet = true;
    return s;
  }

  const CompareOptions& o_;
  const OutOfCoreStudyFlags& flags_;
  const StudyPlanOoc& plan_;
  const OutOfCoreScene& scene_;
  const uint64_t budget_;
  std::vector<OocRow> rows_;
  std::vector<std::vector<Image>> images_;
};

// What one ceiling means, in words (the report's notes; stdout repeats the largest spp's).
std::string ceilingNote(const ooc_study::Ceiling& c) {
  return fmt::format(
      "Oracle ceiling at {} spp: {:.2f}x the baseline's efficiency (modelled from measured "
      "parts, not run): a load-level roulette that knew each (batch, mesh) queue's proxy "
      "errors and cost, with the q minimising MSE x time per queue, from the proxies-exact "
      "run ({}): {:.3f} s and MSE {:.3e} against the baseline's {:.3f} s and {:.3e}; of "
      "{:.1f} queues per frame it skips {:.1f} outright (the proxies right for every segment), "
      "mean q {:.2f}. Skipped loads would also evict less, which this leaves out.",
      c.spp, c.relative_efficiency,
      c.batch_passes > 0 ? fmt::format("{} passes per batch", c.batch_passes) : "one batch",
      c.oracle_seconds, c.oracle_mse, c.baseline_seconds, c.baseline_mse, c.queues, c.skipped,
      c.mean_q);
}

// The report's notes: how it was measured, the ceiling, and the memory against the budget.
std::vector<std::string> studyNotes(const std::vector<OocRow>& rows,
                                    const std::vector<ooc_study::Ceiling>& ceilings,
                                    const OutOfCoreScene& scene, uint64_t budget) {
  std::vector<std::string> notes{
      "Measured on this machine (warm page cache, or cold reads where the row says so: each "
      "original's file dropped from the page cache before it loads): each row is the mean over its "
      "seeds of the "
      "render's wall time (the scene's scan, the same for every row, left out), the seeds of all "
      "rows interleaved. Rows compare at equal samples; efficiency = 1/(MSE x seconds), relative "
      "to the most efficient exact-batched row at the same spp (marked baseline)."};
  for (const ooc_study::Ceiling& c : ceilings) notes.push_back(ceilingNote(c));
  const OocRow* worst = nullptr;
  for (const OocRow& r : rows)
    if (!worst || r.bounded_peak_bytes > worst->bounded_peak_bytes) worst = &r;
  const double mib = double(1 << 20);
  if (worst)
    notes.push_back(fmt::format(
        "Memory (RSS, measured): each render hands the heap's freed memory back and resets the "
        "high-water mark before it starts. The largest growth over the rows was {:.1f} MiB over "
        "the {:.0f} MiB resident before that render (the program and its libraries, the resident "
        "scene, the images the study keeps); with the proxies (resident before, {:.1f} MiB) that "
        "is {:.1f} MiB against budget {:.1f} + proxies {:.1f} + image {:.1f} + overhead {:.1f} "
        "(10 %) = {:.1f} MiB: {}. Of {:.1f} MiB of originals in core. {} of {} rows within.",
        double(worst->peak_rss_growth_bytes) / mib, double(worst->rss_before_bytes) / mib,
        double(worst->proxy_bytes) / mib, double(worst->bounded_peak_bytes) / mib,
        double(budget) / mib, double(worst->proxy_bytes) / mib, double(worst->image_bytes) / mib,
        double(worst->overhead_bytes) / mib, double(worst->rss_bound_bytes) / mib,
        worst->within_rss_bound ? "within" : "over", double(scene.inCoreBytes()) / mib,
        std::count_if(rows.begin(), rows.end(), [](const OocRow& r) { return r.within_rss_bound; }),
        rows.size()));
  return notes;
}

}  // namespace

void addOutOfCoreStudyFlags(CLI::App& app, OutOfCoreStudyFlags& f) {
  addOutOfCoreCommonFlags(app, f, "Compare the out-of-core policies", "With --geometry-budget: ");
  app.add_option("--ooc-policies", f.policies,
                 "With --geometry-budget: the policies compared (exact-batched, proxies-exact, "
                 "proxies-roulette)")
      ->capture_default_str();
  app.add_option("--batch-passes", f.batch_passes,
                 "With --geometry-budget: passes per batch, a list (0: the whole frame); every "
                 "policy runs at each, and the best exact-batched one is the baseline")
      ->capture_default_str();
}

int runOutOfCoreStudy(CompareOptions& o, const OutOfCoreStudyFlags& flags,
                      const StudyFlagsGiven& given) {
  const StudyPlanOoc plan = planStudy(o, flags, given);
  const GeometryBudget budget_flag = parseGeometryBudget(flags.geometry_budget);
  // Staged before any rendering: an unwritable --out fails in a second.
  StagedFolder folder(o.out, "render-compare", "report.json");
  oiioModule();
  OutOfCoreSceneOptions scene_options;
  scene_options.scene = o.render.sceneOptions(o.common.quiet);
  scene_options.proxies = std::any_of(plan.policies.begin(), plan.policies.end(),
                                      [](auto p) { return p != OutOfCorePolicy::kExactBatched; });
  const auto scene = OutOfCoreScene::load(plan.desc, scene_options);
  const uint64_t budget = budget_flag.resolve(scene->inCoreBytes());

  OutOfCoreStudy study(o, flags, plan, *scene, budget);
  study.renderRows();
  const int reference_spp = o.referenceSpp(o.spp_list.back());
  const OutOfCoreResult reference = study.reference(reference_spp);
  const std::vector<OocRow> rows = study.score(reference.radiance);
  const size_t pixels = size_t(reference.radiance.width) * size_t(reference.radiance.height);
  const std::vector<ooc_study::Ceiling> ceilings =
      ooc_study::ceilings(rows, pixels, o.render.q_min);
  const std::vector<std::string> notes = studyNotes(rows, ceilings, *scene, budget);

  const SceneDesc& desc = plan.desc;
  const std::string resolution = fmt::format("{}x{}", desc.camera.width, desc.camera.height);
  nlohmann::json json_rows = nlohmann::json::array(), json_ceilings = nlohmann::json::array();
  for (const OocRow& r : rows) json_rows.push_back(ooc_study::rowJson(r));
  for (const ooc_study::Ceiling& c : ceilings) json_ceilings.push_back(ooc_study::ceilingJson(c));
  const nlohmann::json report = {
      {"program", "render-compare"},
      {"mode", "out-of-core"},
      {"scene", desc.path.string()},
      {"scene_name", desc.displayName()},
      {"resolution", resolution},
      {"seeds", o.seeds},
      {"seed", o.common.seed},
      {"geometry_budget", flags.geometry_budget},
      {"geometry_budget_bytes", budget},
      {"in_core_bytes", scene->inCoreBytes()},
      {"proxy_bytes", scene->proxyBytes()},
      {"scan_seconds", scene->scanSeconds()},
      {"scene_build", scene->buildChoice().name()},
      {"reference_spp", reference_spp},
      {"reference_seconds", reference.stats.seconds},
      {"ceiling", ceilings.empty() ? nlohmann::json(nullptr) : json_ceilings.back()},
      {"ceilings", json_ceilings},
      {"notes", notes},
      {"rows", json_rows},
      {"build", buildText()},
      {"version", versionText()}};
  const TextTable table = ooc_study::studyTable(rows);
  std::string md = fmt::format(
      "# render-compare (out of core): {}\n\n{}, geometry budget {} ({:.1f} MiB of {:.1f} MiB "
      "in core), reference exact {} spp; {} seed(s) per row.\n\n{}\n",
      desc.displayName(), resolution, flags.geometry_budget, double(budget) / double(1 << 20),
      double(scene->inCoreBytes()) / double(1 << 20), reference_spp, o.seeds, markdownTable(table));
  for (const std::string& n : notes) md += "\n" + n + "\n";

  StudyReportFiles files{report.dump(2) + "\n",
                         md,
                         fmt::format("{} (out of core, geometry budget {})", desc.displayName(),
                                     flags.geometry_budget),
                         htmlTable(table),
                         notes,
                         &reference.radiance,
                         {}};
  for (size_t i = 0; i < rows.size(); ++i)
    files.images.emplace_back(ooc_study::imageName(rows[i]), &study.firstImage(i));
  writeStudyReport(folder.path(), files);
  folder.commit();
  printHumanReport(o.common,
                   markdownTable(table) + "\n" +
                       (ceilings.empty() ? std::string() : ceilingNote(ceilings.back()) + "\n") +
                       "HTML report: " + (folder.target() / "report.html").string() + "\n");
  return kExitOk;
}

}  // namespace proxyvis
