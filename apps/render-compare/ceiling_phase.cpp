#include "ceiling_phase.h"

#include <cstdio>

#include "estimate/ceiling.h"
#include "render/ceiling_stats.h"
#include "render/render_scene.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

// Samples per pixel of the exact render made for c_s when the run has no exact cell.
constexpr int kShadingRenderSpp = 4;

constexpr const char* kModel =
    "Model: per region (screen tile × light × whether the shading point's object uses a proxy) "
    "an oracle knows P(MH'), P(HM'), P(V'=0), the four ray costs and exact's per-pixel variance "
    "of f·V (f = the sample's unoccluded contribution, radiance × cosines / pdf) and picks exact "
    "or roulette with its optimal q, which adds f²·(1/q − 1) per error; ceiling = Var × time of "
    "exact over that of the oracle, summed over regions. Simplifications: rays are timed one by "
    "one in this phase, not inside the renders; c_s (primary rays and light sampling) is the exact "
    "renders' shading time priced at what their visibility time bought (their accumulation left "
    "out, so c_s is a little low and the ceiling a little high) and one number for all regions; "
    "learning, probes and bookkeeping of real "
    "estimators are not counted; variances and error rates come from the passes above.";

ReportCeilingLight toReport(const std::string& name, const CeilingSummary& s) {
  ReportCeilingLight l;
  l.light = name;
  l.segments = s.segments;
  l.p_blocked = s.p_blocked;
  l.p_mh = s.p_mh;
  l.p_hm = s.p_hm;
  l.visibility_var = s.visibility_var;
  for (int i = 0; i < 2; ++i) {
    l.cost_proxy[i] = s.costs.proxy[i];
    l.cost_original[i] = s.costs.original[i];
  }
  l.cost_shading = s.costs.per_sample;
  l.regions = s.regions;
  l.regions_roulette = s.regions_roulette;
  l.ceiling = s.ceiling;
  return l;
}

}  // namespace

ReportCeiling runCeilingPhase(const RenderScene& scene, const CompareOptions& o,
                              const std::vector<CellResult>& cells, double planned_seconds) {
  const Stopwatch clock;
  double renders_seconds = 0;
  std::vector<const RenderResult*> exact;
  for (const CellResult& c : cells) {
    renders_seconds += c.row.seconds * c.row.seeds;
    if (c.row.estimator == estimatorName(EstimatorKind::kExact)) exact.push_back(&c.first);
  }
  if (planned_seconds >= 0) renders_seconds = planned_seconds;
  RenderSettings settings;
  settings.estimator = o.render.estimatorSetup(EstimatorKind::kExact);
  settings.seed = hashKeys(o.common.seed, uint64_t(0));  // the segments of every cell's seed 1
  settings.quiet = true;
  const CeilingMeasurement m =
      measureCeilingStats(scene, settings, kCeilingPasses, kCeilingTimeShare * renders_seconds);
  RenderResult own;
  if (exact.empty()) {
    settings.spp = kShadingRenderSpp;
    own = render(scene, settings);
    exact.push_back(&own);
  }
  const double c_s = shadingNsPerSegment(exact, m);
  const CeilingResult result = computeCeiling(ceilingInput(scene, m, c_s, o.render.q_min));

  ReportCeiling c;
  c.value = result.scene.ceiling;
  c.explanation = result.explanation;
  c.model = kModel;
  c.passes = m.passes;
  c.seconds = clock.seconds();
  c.run_share = renders_seconds > 0 ? c.seconds / renders_seconds : 0;
  const double pixels = double(scene.camera().width()) * scene.camera().height();
  c.exact_mse_1spp = m.passes > 0 ? result.scene.var_exact / m.passes / pixels : 0;
  for (size_t i = 0; i < result.lights.size(); ++i)
    c.lights.push_back(toReport(std::to_string(i), result.lights[i]));
  c.lights.push_back(toReport("all", result.scene));
  if (!o.common.quiet)
    std::fprintf(stderr, "render-compare: ceiling %.3fx exact (%d passes, %.2f s): %s\n", c.value,
                 c.passes, c.seconds, c.explanation.c_str());
  return c;
}

void applyCeiling(Report& report, const ReportCeiling& ceiling) {
  report.ceiling = ceiling;
  for (ReportRow& r : report.rows) r.ceiling = ceiling.value;
}

}  // namespace proxyvis
