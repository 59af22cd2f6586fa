#include "study/study_merge.h"

#include <fmt/format.h>
#include <tbb/info.h>

#include <algorithm>

#include "util/error.h"
#include "util/parallel_in_order.h"

namespace proxyvis {

namespace fs = std::filesystem;

StudyMerge::StudyMerge(const CompareOptions& o, const StudyPlan& plan, const SceneDesc& desc)
    : o_(o), plan_(plan), desc_(desc) {
  // The cells in table order: equal-spp by spp, then equal-time; estimators in --estimators order.
  for (int spp : o.spp_list)
    for (EstimatorKind kind : o.estimator_list) {
      equal_spp_[{spp, kind}] = out_.cells.size();
      out_.cells.emplace_back();
      out_.stems.push_back(fmt::format("{}_{}", estimatorName(kind), spp));
    }
  first_equal_time_ = out_.cells.size();
  if (o.equal_time > 0)
    for (EstimatorKind kind : o.estimator_list) {
      out_.cells.emplace_back();
      out_.stems.push_back(fmt::format("{}_equal-time", estimatorName(kind)));
    }
}

void StudyMerge::addReferencePartial(const RenderResult& partial) {
  partials_.add(partial.radiance.pixels);
  reference_seconds_ += partial.seconds;
}

void StudyMerge::finishReference(bool flattened, const fs::path& dir) {
  reference_ = proxyvis::finishReference(desc_, flattened, partials_, plan_.reference_per_partial,
                                         reference_seconds_, dir);
  partials_ = ImageVarianceAccumulator{};
}

void StudyMerge::useCachedReference(Reference reference) {
  reference_ = std::move(reference);
}

std::vector<RunScore> StudyMerge::score(const UnitResult& result) const {
  std::vector<RunScore> scores;
  for (const RenderResult& r : result.renders)
    scores.push_back(scoreRun(r.radiance, reference_->radiance));
  return scores;
}

void StudyMerge::addCellUnit(size_t unit, UnitResult result, const std::vector<RunScore>& scores) {
  const PlannedUnit& u = plan_.units.at(unit);
  if (!have_facts_) out_.facts = result.facts, have_facts_ = true;
  const Image& reference = reference_->radiance;
  if (u.kind == UnitKind::kEqualSpp) {
    addRun(out_.cells[equal_spp_.at({u.spp, u.estimator})], std::move(result.renders.at(0)),
           scores.at(0), reference, desc_.path, o_, u.estimator, kEqualSppTable, u.run, o_.seeds);
  } else if (u.kind == UnitKind::kEqualTime) {
    const int runs = o_.seeds * o_.repeats;
    for (size_t e = 0; e < o_.estimator_list.size(); ++e)
      addRun(out_.cells[first_equal_time_ + e], std::move(result.renders.at(e)), scores.at(e),
             reference, desc_.path, o_, o_.estimator_list[e], kEqualTimeTable, u.run, runs);
  } else if (u.kind == UnitKind::kCeiling && result.ceiling) {
    ceiling_unit_ = std::move(result);
  }
}

StudyMerge::Cells StudyMerge::finish() {
  size_t i = 0;
  for (int spp : o_.spp_list)
    for (EstimatorKind kind : o_.estimator_list) {
      (void)spp;
      finishCell(out_.cells[i++], kind, kEqualSppTable, 0, o_.seeds, 1);
    }
  if (o_.equal_time > 0)
    for (EstimatorKind kind : o_.estimator_list)
      finishCell(out_.cells[i++], kind, kEqualTimeTable, o_.equal_time, o_.seeds, o_.repeats);
  for (CellResult& c : out_.cells) scoreCell(c);
  if (ceiling_unit_) {
    // c_s priced with the exact cells' first renders, or the unit's own exact render when the
    // study has none; the ceiling's share of the renders' time from the cells.
    std::vector<const RenderResult*> exact;
    double renders_seconds = 0;
    for (const CellResult& c : out_.cells) {
      renders_seconds += c.row.seconds * c.row.seeds;
      if (c.row.estimator == estimatorName(EstimatorKind::kExact)) exact.push_back(&c.first);
    }
    if (exact.empty())
      for (const RenderResult& r : ceiling_unit_->renders) exact.push_back(&r);
    out_.ceiling = finishCeiling(*ceiling_unit_->ceiling, exact, ceiling_unit_->facts.proxy_class,
                                 ceiling_unit_->facts.uses_proxies, o_);
    out_.ceiling.run_share = renders_seconds > 0 ? out_.ceiling.seconds / renders_seconds : 0;
  }
  return std::move(out_);
}

StudyMerge::Cells mergeUnitFiles(StudyMerge& merge, const fs::path& dir, const StudyPlan& plan,
                                 const SceneDesc& desc, const fs::path& report_dir) {
  std::vector<size_t> reference, cells;
  for (size_t k = 0; k < plan.units.size(); ++k)
    (plan.units[k].kind == UnitKind::kReference ? reference : cells).push_back(k);
  // A batch of units is read (and scored) in parallel, then added in unit order: the first bad
  // unit in that order is the one reported, and only a batch is in memory at once.
  const size_t batch = std::max<size_t>(4, 2 * size_t(tbb::info::default_concurrency()));
  std::vector<UnitResult> results;
  std::vector<std::vector<RunScore>> scores;
  auto forEachBatch = [&](const std::vector<size_t>& units, bool score, auto&& add) {
    for (size_t first = 0; first < units.size(); first += batch) {
      const size_t n = std::min(batch, units.size() - first);
      results.assign(n, {});
      scores.assign(n, {});
      parallelInOrder(n, [&](size_t i) {
        results[i] =
            readUnitResult(dir, plan, units[first + i], desc.camera.width, desc.camera.height);
        if (score) scores[i] = merge.score(results[i]);
      });
      for (size_t i = 0; i < n; ++i) add(units[first + i], results[i], scores[i]);
    }
  };
  bool flattened = false;
  forEachBatch(reference, false, [&](size_t, UnitResult& r, const std::vector<RunScore>&) {
    flattened = r.facts.instances_flattened;
    merge.addReferencePartial(r.renders.at(0));
    r = UnitResult{};
  });
  merge.finishReference(flattened, report_dir);
  forEachBatch(cells, true, [&](size_t k, UnitResult& r, const std::vector<RunScore>& s) {
    merge.addCellUnit(k, std::move(r), s);
  });
  return merge.finish();
}

}  // namespace proxyvis
