#include "study/ceiling_phase.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "estimate/ceiling.h"
#include "render/ceiling_stats.h"
#include "render/render_scene.h"
#include "util/json_field.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

// Samples per pixel of the exact render made for c_s when the study has no exact cell.
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

}  // namespace

bool ceilingNeedsOwnRender(const CompareOptions& o) {
  const bool exact_cells = std::find(o.estimator_list.begin(), o.estimator_list.end(),
                                     EstimatorKind::kExact) != o.estimator_list.end() &&
                           (!o.spp_list.empty() || o.equal_time > 0);
  return !exact_cells;
}

CeilingUnitMeasurement measureCeiling(const RenderScene& scene, const CompareOptions& o,
                                      double planned_seconds, RenderResult* own_exact) {
  const Stopwatch clock;
  RenderSettings settings;
  settings.estimator = o.render.estimatorSetup(EstimatorKind::kExact);
  settings.seed = hashKeys(o.common.seed, uint64_t(0));  // the segments of every cell's seed 1
  settings.quiet = true;
  CeilingUnitMeasurement unit;
  unit.measurement =
      measureCeilingStats(scene, settings, kCeilingPasses, kCeilingTimeShare * planned_seconds);
  if (own_exact) {
    settings.spp = kShadingRenderSpp;
    *own_exact = render(scene, settings);
  }
  unit.seconds = clock.seconds();
  unit.pixels = double(scene.camera().width()) * scene.camera().height();
  return unit;
}

ReportCeiling finishCeiling(const CeilingUnitMeasurement& unit,
                            const std::vector<const RenderResult*>& exact_renders,
                            ProxyClass proxy_class, bool uses_proxies, const CompareOptions& o) {
  const CeilingMeasurement& m = unit.measurement;
  // ceilingInput() (render/ceiling_stats.h) without the scene: the merge has only its facts.
  CeilingInput input;
  input.regions = m.regions;
  input.num_lights = m.num_lights;
  input.per_sample_ns = shadingNsPerSegment(exact_renders, m);
  input.proxy_class = proxy_class;
  input.q_min = o.render.q_min;
  input.uses_proxies = uses_proxies;
  ReportCeiling c;
  c.result = computeCeiling(input);
  c.model = kModel;
  c.passes = m.passes;
  c.seconds = unit.seconds;
  c.exact_mse_1spp = m.passes > 0 ? c.result.scene.var_exact / m.passes / unit.pixels : 0;
  if (!o.common.quiet)
    std::fprintf(stderr, "render-compare: ceiling %.3fx exact (%d passes, %.2f s): %s\n", c.value(),
                 c.passes, c.seconds, c.result.explanation.c_str());
  return c;
}

void to_json(nlohmann::json& j, const CeilingUnitMeasurement& unit) {
  j = unit.measurement;
  j["seconds"] = unit.seconds;
  j["pixels"] = unit.pixels;
}

void from_json(const nlohmann::json& j, CeilingUnitMeasurement& unit) {
  const JsonField f(j);
  unit.measurement = f.get<CeilingMeasurement>();
  unit.seconds = f["seconds"].asDouble();
  unit.pixels = f["pixels"].asDouble();
}

void applyCeiling(Report& report, const ReportCeiling& ceiling) {
  report.ceiling = ceiling;
  for (ReportRow& r : report.rows) r.ceiling = ceiling.value();
}

}  // namespace proxyvis
