#include "study/study_report.h"

#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "metrics/html_report.h"
#include "metrics/image_error.h"
#include "study/outputs.h"
#include "util/atomic_write.h"
#include "util/output_set.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

constexpr const char* kNoProxiesNote =
    "no mesh of this scene has a proxy: every estimator traces the originals, so the comparison "
    "only measures estimator overhead (generate proxies with proxy-gen, then compare the scene "
    "it writes)";

std::string listText(const std::vector<int>& v) {
  std::string s;
  for (int x : v) s += (s.empty() ? "" : ",") + std::to_string(x);
  return s;
}

void addReferenceNotes(Report& report, const Reference& ref, bool quiet) {
  double min_mse = std::numeric_limits<double>::infinity();
  for (const ReportRow& r : report.rows) min_mse = std::min(min_mse, r.mse);
  double ratio = min_mse > 0 ? ref.variance_of_mean / min_mse : 0;
  report.meta["reference_to_min_mse"] = ratio;
  std::string text = fmt::format(
      "Reference: exact, {} spp ({} partial renders, {:.1f} s{}); its own estimated variance of "
      "the mean, averaged over the image, is {:.2e} = {:.2g}% of the smallest MSE compared "
      "({:.2e}).",
      ref.spp, ref.partials, ref.seconds,
      ref.cached ? ", rendered by an earlier run and cached" : "", ref.variance_of_mean,
      100 * ratio, min_mse);
  report.notes.push_back(text);
  if (ratio > 0.1) {
    std::string warning = fmt::format(
        "WARNING: the reference is not converged relative to the MSEs compared (its variance is "
        "{:.0f}% of the smallest MSE); raise --reference-spp.",
        100 * ratio);
    report.notes.push_back(warning);
    if (!quiet) std::fprintf(stderr, "render-compare: %s\n", warning.c_str());
  }
}

// Equal time means equal measured time: the renderer fits its last pass to the budget, but a
// render can still end past it (its first pass, a slow last sample). Said when any row of the
// table ends more than 5 % past the budget, so its efficiency is read with that in mind.
void addOvershootNote(Report& report, double budget) {
  if (!(budget > 0)) return;
  double worst = 0;
  std::string who;
  for (const ReportRow& r : report.rows)
    if (r.table == kEqualTimeTable && r.seconds - budget > worst)
      worst = r.seconds - budget, who = r.estimator;
  report.meta["equal_time_max_overshoot_seconds"] = worst;
  if (worst > 0.05 * budget)
    report.notes.push_back(fmt::format(
        "Equal time: {} took {:.3f} s for a budget of {:g} s ({:+.0f}%); the efficiency column "
        "uses the measured times.",
        who, budget + worst, budget, 100 * worst / budget));
}

Report makeReport(const CompareOptions& o, const SceneDesc& desc, const SceneFacts& scene,
                  const Reference& ref) {
  Report report;
  report.title = "render-compare: visibility estimators compared";
  report.scene_name = desc.displayName();
  report.meta["scene"] = desc.path.string();
  report.meta["scene_hash"] = sceneHash(desc);
  report.meta["resolution"] = fmt::format("{}x{}", desc.camera.width, desc.camera.height);
  report.meta["spp"] = listText(o.spp_list);
  report.meta["equal_time_seconds"] = o.equal_time;
  report.meta["seeds"] = o.seeds;
  report.meta["repeats"] = o.repeats;
  report.meta["timing"] = interleavedTimingMeta(o);
  report.meta["seed"] = o.common.seed;
  report.meta["threads"] =
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  report.meta["proxy_class"] = proxyClassName(scene.proxy_class);
  report.meta["uses_proxies"] = scene.uses_proxies;
  report.meta["original_triangles"] = scene.original_triangles;
  report.meta["proxy_triangles"] = scene.proxy_triangles;
  report.meta["reference_spp"] = ref.spp;
  report.meta["reference_partials"] = ref.partials;
  report.meta["reference_seconds"] = ref.seconds;
  report.meta["reference_variance_of_mean"] = ref.variance_of_mean;
  report.meta["reference_file"] = ref.file.filename().string();
  report.meta["reference_cached"] = ref.cached;
  report.meta["relmse_epsilon"] = kRelMseEpsilon;
  // Each proxy's class status (class_trust.h): a note per proxy whose claim was not taken as is,
  // and every proxy in the JSON meta.
  for (const std::string& note : scene.trust_notes) report.notes.push_back(note);
  report.meta["proxy_classes"] = scene.proxy_classes;
  for (const std::string& w : scene.warnings) report.notes.push_back("Scene: " + w);
  if (o.equal_time > 0) report.notes.push_back(interleavedTimingNote(o));
  if (!scene.uses_proxies) report.notes.push_back(std::string("Warning: ") + kNoProxiesNote + ".");
  // The exact baseline should be the fastest exact configuration that fits in memory: say which.
  report.meta["build"] = scene.build;
  report.meta["build_reason"] = scene.build_reason;
  report.notes.push_back("Exact baseline: " + scene.build_description + ": " + scene.build_reason +
                         ".");
  report.notes.push_back(
      o.render.fixed_costs
          ? "roulette uses the fixed costs of --roulette-costs: bit-reproducible."
          : "roulette measures its ray costs with the CPU tick counter: its choices (never its "
            "expectation) depend on timing, so its images are unbiased but not bit-reproducible "
            "(--roulette-costs fixes them).");
  return report;
}

// Images and heat-maps; one colour scale per kind of map and table, so the maps of the
// estimators in one table compare.
HtmlReportLayout writeStudyImages(const CompareOptions& o, const SceneDesc& desc,
                                  const Reference& ref, const Report& report,
                                  std::vector<CellResult>& cells,
                                  const std::vector<std::string>& stems, const fs::path& dir) {
  float exposure = autoExposure(ref.radiance);
  const std::string reference_png = "reference.png";
  const std::string reference_exr = ref.file.filename().string();
  ImageWriteOptions reference_png_options;
  reference_png_options.exposure = exposure;
  reference_png_options.attributes =
      referenceAttributes(desc, ref, "radiance of the exact reference, tone-mapped");
  writeImage(ref.radiance, dir / reference_png, reference_png_options);
  writeColorBar(dir);
  HtmlReportLayout layout;
  layout.plots.push_back(mseTimePlot(report.rows));
  std::vector<TableImages> tables;
  auto addTable = [&](std::string_view table, double spp, const std::string& title) {
    std::vector<CellImages> images;
    std::vector<const std::vector<float>*> error_maps, cost_ptrs;
    std::vector<std::vector<float>> cost_maps;
    for (size_t i = 0; i < cells.size(); ++i) {
      const ReportRow& row = cells[i].row;
      if (row.table != table || (table == kEqualSppTable && row.spp != spp)) continue;
      images.push_back({stems[i], &cells[i]});
      error_maps.push_back(&cells[i].error_map);
      cost_maps.push_back(raysPerPixel(cells[i].first.cost));
    }
    for (const auto& m : cost_maps) cost_ptrs.push_back(&m);
    HeatMapRange error_range = sharedLogRange(error_maps), cost_range = sharedLogRange(cost_ptrs);
    tables.push_back({images, error_range, cost_range});  // written below, all in parallel
    return cellGalleries(title, reference_png, reference_exr, images, error_range, cost_range);
  };
  auto add = [&](const std::vector<HtmlGallery>& g, bool shown) {
    if (shown) layout.galleries.insert(layout.galleries.end(), g.begin(), g.end());
  };
  if (o.equal_time > 0)
    add(addTable(kEqualTimeTable, 0, fmt::format("Equal time ({:g} s)", o.equal_time)), true);
  // Every equal-spp cell gets its files; the HTML shows the largest spp.
  for (int spp : o.spp_list)
    add(addTable(kEqualSppTable, spp, fmt::format("Equal samples ({} spp)", spp)),
        spp == o.spp_list.back());
  writeReportImages(tables, desc, dir, exposure);
  std::vector<CellImages> all_cells;
  for (size_t i = 0; i < cells.size(); ++i) all_cells.push_back({stems[i], &cells[i]});
  layout.files = runFileGroups(reference_png, reference_exr, all_cells);
  return layout;
}

}  // namespace

Report reportStudy(const CompareOptions& o, const SceneDesc& desc, StudyMerge::Cells study,
                   const Reference& ref, StagedFolder& folder) {
  const fs::path& dir = folder.path();
  const SceneFacts& facts = study.facts;
  if (!facts.uses_proxies && !o.common.quiet)
    std::fprintf(stderr, "render-compare: warning: %s: %s\n", desc.path.filename().string().c_str(),
                 kNoProxiesNote);
  std::vector<CellResult>& cells = study.cells;
  const std::vector<std::string>& stems = study.stems;
  if (!o.common.quiet)
    std::fprintf(stderr,
                 "render-compare: reference %s (exact, %d spp in %d partial renders, %.1f s, "
                 "variance of mean %.2e)%s\n",
                 (o.out / ref.file.filename()).string().c_str(), ref.spp, ref.partials, ref.seconds,
                 ref.variance_of_mean, ref.cached ? " [cached: rendered by an earlier run]" : "");

  Report report = makeReport(o, desc, facts, ref);
  for (const CellResult& c : cells) report.rows.push_back(c.row);
  fillRelativeEfficiency(report.rows, kEqualSppTable);
  fillRelativeEfficiency(report.rows, kEqualTimeTable);
  // The attainable gain, from this run's own measurements (docs/performance.md, the ceiling).
  applyCeiling(report, study.ceiling);
  if (std::find(o.estimator_list.begin(), o.estimator_list.end(), EstimatorKind::kExact) ==
      o.estimator_list.end())
    report.notes.push_back(
        "exact was not among --estimators: efficiencies are n/a (null in the JSON).");
  addReferenceNotes(report, ref, o.common.quiet);
  addOvershootNote(report, o.equal_time);
  requireFiniteRows(report.rows, desc.path);
  for (size_t i = 0; i < cells.size(); ++i) cells[i].row = report.rows[i];

  const HtmlReportLayout layout = writeStudyImages(o, desc, ref, report, cells, stems, dir);

  nlohmann::json json = reportToJson(report);
  const std::string json_text = json.dump(2) + "\n";
  writeTextAtomically(dir / "report.json", json_text);
  writeTextAtomically(dir / "report.csv", reportToCsv(report.rows));
  writeTextAtomically(dir / "report.md", reportToMarkdown(report));
  writeTextAtomically(dir / "report.html", reportToHtml(report, layout));
  folder.commit();  // the manifest last, then the folder in place
  if (!o.common.json_path.empty()) {
    OutputSet json_output(MissingFolders::kCreate);
    json_output.addText(o.common.json_path, json_text);
    json_output.commit();
  }

  return report;
}

}  // namespace proxyvis
