#include "estimate/ceiling.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace proxyvis {

namespace {

// One region's two options, as sums over its samples.
struct RegionOptions {
  double var_exact = 0, cost_exact = 0;
  double var_roulette = 0, cost_roulette = 0;
  bool roulette_possible = false;
};

// Rounds of improving the choices against the totals: each round is one pass over the regions,
// and the choices settle in two or three on every scene measured; the cap bounds an oscillation.
constexpr int kImproveRounds = 8;

struct Totals {
  double var = 0, cost = 0;
  int roulette = 0;
  double product() const { return var * cost; }
};

Totals totalsOf(const std::vector<RegionOptions>& options, const std::vector<char>& choice,
                double fixed_var) {
  Totals t{fixed_var, 0, 0};
  for (size_t i = 0; i < options.size(); ++i) {
    const RegionOptions& o = options[i];
    t.var += choice[i] ? o.var_roulette : o.var_exact;
    t.cost += choice[i] ? o.cost_roulette : o.cost_exact;
    t.roulette += choice[i];
  }
  return t;
}

// The oracle's best totals over the regions (see computeCeiling in the header).
Totals oracleTotals(const std::vector<RegionOptions>& options, double fixed_var) {
  std::vector<char> choice(options.size(), 0);
  const Totals exact = totalsOf(options, choice, fixed_var);
  for (size_t i = 0; i < options.size(); ++i) {
    const RegionOptions& o = options[i];
    choice[i] =
        o.roulette_possible && o.var_roulette * o.cost_roulette < o.var_exact * o.cost_exact;
  }
  Totals current = totalsOf(options, choice, fixed_var);
  Totals best = current.product() < exact.product() ? current : exact;
  for (int round = 0; round < kImproveRounds; ++round) {
    bool changed = false;
    for (size_t i = 0; i < options.size(); ++i) {
      const RegionOptions& o = options[i];
      // d(V C) ~ C dV + V dC: the region's share of the product at the current totals.
      const bool use =
          o.roulette_possible && o.var_roulette * current.cost + o.cost_roulette * current.var <
                                     o.var_exact * current.cost + o.cost_exact * current.var;
      changed = changed || use != bool(choice[i]);
      choice[i] = use;
    }
    current = totalsOf(options, choice, fixed_var);
    if (current.product() < best.product()) best = current;
    if (!changed) break;
  }
  return best;
}

CeilingSummary summarise(const std::vector<const CeilingRegionStats*>& regions,
                         const CeilingInput& in, const ClassCosts& scene_costs) {
  CeilingRegionStats all;
  for (const CeilingRegionStats* r : regions) addCeilingStats(all, *r);
  CeilingSummary s;
  s.segments = all.segments;
  if (all.segments > 0) {
    s.p_blocked = all.blocked / all.segments;
    s.p_mh = all.mh / all.segments;
    s.p_hm = all.hm / all.segments;
    s.visibility_var = all.visibility_var / all.segments;
  }
  s.costs = meanClassCosts(all, in.per_sample_ns);
  // Each class's mean borrows the scene's where this group saw too few segments of it.
  for (int i = 0; i < 2; ++i) {
    const double n = i == 0 ? all.blocked : all.segments - all.blocked;
    if (n < kMinClassSamples) {
      s.costs.proxy[i] = scene_costs.proxy[i];
      s.costs.original[i] = scene_costs.original[i];
    }
  }

  std::vector<RegionOptions> options;
  double fixed_var = 0;  // variance of regions without segments: paid alike by every estimator
  for (const CeilingRegionStats* r : regions) {
    if (r->segments <= 0) {
      fixed_var += r->var_fv;
      continue;
    }
    const RouletteModel m = ceilingModel(*r, scene_costs);
    const RouletteQ q = optimalRouletteQ(m, in.proxy_class, in.q_min);
    RegionOptions o;
    o.var_exact = r->var_fv;
    o.cost_exact = r->segments * exactCost(m);
    o.var_roulette = r->segments * rouletteVariance(m, q);
    o.cost_roulette = r->segments * rouletteCost(m, q);
    o.roulette_possible = in.uses_proxies && std::isfinite(o.var_roulette);
    options.push_back(o);
  }
  s.regions = int(options.size());
  std::vector<char> none(options.size(), 0);
  const Totals exact = totalsOf(options, none, fixed_var);
  const Totals oracle = oracleTotals(options, fixed_var);
  s.var_exact = exact.var, s.cost_exact = exact.cost;
  s.var_oracle = oracle.var, s.cost_oracle = oracle.cost;
  s.regions_roulette = oracle.roulette;
  s.ceiling = oracle.product() > 0 && exact.product() > 0 && oracle.roulette > 0
                  ? exact.product() / oracle.product()
                  : 1.0;
  return s;
}

std::string ns(double v) {
  return fmt::format("{:.0f} ns", v);
}

}  // namespace

void addCeilingStats(CeilingRegionStats& a, const CeilingRegionStats& b) {
  a.segments += b.segments;
  a.blocked += b.blocked;
  a.mh += b.mh;
  a.hm += b.hm;
  a.visibility_var += b.visibility_var;
  a.var_fv += b.var_fv;
  a.f2_mh += b.f2_mh;
  a.f2_hm += b.f2_hm;
  for (int i = 0; i < 2; ++i) {
    a.cost_proxy[i] += b.cost_proxy[i];
    a.cost_original[i] += b.cost_original[i];
  }
}

ClassCosts meanClassCosts(const CeilingRegionStats& all, double per_sample) {
  ClassCosts c;
  c.per_sample = per_sample;
  for (int i = 0; i < 2; ++i) {
    const double n = i == 0 ? all.blocked : all.segments - all.blocked;
    c.proxy[i] = n > 0 ? all.cost_proxy[i] / n : 0;
    c.original[i] = n > 0 ? all.cost_original[i] / n : 0;
  }
  return c;
}

RouletteModel ceilingModel(const CeilingRegionStats& r, const ClassCosts& fallback) {
  RouletteModel m;
  const double n = r.segments;
  if (!(n > 0)) return m;
  m.var_exact = r.var_fv / n;
  m.p_mh = r.f2_mh / n;
  m.p_hm = r.f2_hm / n;
  m.p_blocked = r.blocked / n;
  m.costs = meanClassCosts(r, fallback.per_sample);
  for (int i = 0; i < 2; ++i) {
    const double ni = i == 0 ? r.blocked : n - r.blocked;
    if (ni < kMinClassSamples) {
      m.costs.proxy[i] = fallback.proxy[i];
      m.costs.original[i] = fallback.original[i];
    }
  }
  return m;
}

CeilingResult computeCeiling(const CeilingInput& in) {
  CeilingRegionStats all;
  for (const CeilingRegionStats& r : in.regions) addCeilingStats(all, r);
  const ClassCosts scene_costs = meanClassCosts(all, in.per_sample_ns);

  CeilingResult result;
  std::vector<const CeilingRegionStats*> every;
  std::vector<std::vector<const CeilingRegionStats*>> by_light(
      std::max<uint32_t>(1, in.num_lights));
  for (const CeilingRegionStats& r : in.regions) {
    every.push_back(&r);
    if (r.light < by_light.size()) by_light[r.light].push_back(&r);
  }
  result.scene = summarise(every, in, scene_costs);
  for (const auto& regions : by_light) result.lights.push_back(summarise(regions, in, scene_costs));
  result.explanation = explainCeiling(result.scene, in.uses_proxies);
  return result;
}

std::string explainCeiling(const CeilingSummary& s, bool uses_proxies) {
  if (!uses_proxies)
    return "No proxies: no object of this scene traces a proxy, so every estimator traces the "
           "originals and the ceiling is 1. Generate proxies with proxy-gen and compare the scene "
           "it writes to measure one.";
  if (!(s.segments > 0))
    return "No shadow rays: nothing in view is lit, so there is no visibility to estimate and "
           "the ceiling is 1. Move the camera or the lights to compare estimators.";
  std::vector<std::string> limits;
  const double errors = s.p_mh + s.p_hm;
  if (errors > 0 && errors >= s.visibility_var) {
    const std::string what = s.p_hm <= 0   ? fmt::format("P(MH') = {:.3f}", s.p_mh)
                             : s.p_mh <= 0 ? fmt::format("P(HM') = {:.3f}", s.p_hm)
                                           : fmt::format("P(MH') + P(HM') = {:.3f}", errors);
    limits.push_back(fmt::format(
        "{} {} the visibility variance V(1-V) = {:.3f}, so correcting the proxy's errors costs "
        "more variance than it saves time.",
        what, errors > s.visibility_var ? "exceeds" : "equals", s.visibility_var));
  }
  // "No cheaper": a proxy ray saving less than a tenth of the original ray's cost.
  if (s.costs.proxy[1] >= 0.9 * s.costs.original[1])
    limits.push_back(fmt::format(
        "The proxy is no cheaper than the original where it says visible (c_p|1 = {} vs c_o|1 "
        "= {}).",
        ns(s.costs.proxy[1]), ns(s.costs.original[1])));
  const double per_segment = s.segments > 0 ? s.cost_exact / s.segments : 0;
  const double shading_share = per_segment > 0 ? s.costs.per_sample / per_segment : 0;
  if (shading_share >= 0.5)
    limits.push_back(fmt::format(
        "Shading costs {:.0f} % of each sample, which caps any visibility gain at {:.1f}x.",
        100 * shading_share, 1 / shading_share));
  const std::string summary = fmt::format(
      "An oracle choosing per region uses roulette in {} of {} regions: ceiling {:.3f}x.",
      s.regions_roulette, s.regions, s.ceiling);
  if (limits.empty())
    limits.push_back(fmt::format(
        "The proxy is cheaper where it says visible (c_p|1 = {} vs c_o|1 = {}) and its errors "
        "(P(MH') + P(HM') = {:.3f}) stay below the visibility variance V(1-V) = {:.3f}.",
        ns(s.costs.proxy[1]), ns(s.costs.original[1]), errors, s.visibility_var));
  if (limits.size() < 2) limits.push_back(summary);
  return limits[0] + " " + limits[1];
}

}  // namespace proxyvis
