#pragma once
// The oracle ceiling (docs/performance.md, "The ceiling"): how much more efficient than exact
// visibility any estimator built on these proxies could be, given per-region statistics measured
// on the scene. Pure functions; the measurement is render/ceiling_stats.h.
//
// Per learning region the oracle knows everything: it uses exact visibility, or roulette with
// the q that minimises that region's Var x Cost (optimalRouletteQ). Variances and costs are sums
// over the region's light samples, so they add over regions like the MSE and the time of a
// render; the ceiling is (Var x Cost) of exact everywhere over that of the oracle's choices.
#include <string>
#include <vector>

#include "estimate/roulette.h"

namespace proxyvis {

// What one learning region (screen tile x light x self) measured. Sums over its light samples;
// a sample that needs no shadow ray (back-facing light) adds only to var_fv.
struct CeilingRegionStats {
  uint32_t light = 0;
  double segments = 0;        // light samples with a shadow segment
  double blocked = 0;         // of those, V' = 0
  double mh = 0, hm = 0;      // of those, MH' and HM' (unweighted counts)
  double visibility_var = 0;  // sum over segments of the pixel's V_p(1-V_p) (unweighted)
  // MSE-weighted: f is the sample's unoccluded contribution (radiance x cosines / pdf), f^2 the
  // mean of its squared RGB channels.
  double var_fv = 0;  // sum over samples of each one's share of its pixel's Var[f V]
  double f2_mh = 0;   // sum of f^2 over MH' segments: roulette's added variance per 1/q0 - 1
  double f2_hm = 0;   // sum of f^2 over HM' segments: per 1/q1 - 1
  double cost_proxy[2] = {0, 0};     // total ns of proxy rays on segments with V' = 0, 1
  double cost_original[2] = {0, 0};  // total ns of original rays on segments with V' = 0, 1

  bool operator==(const CeilingRegionStats&) const = default;
};

// Adds b's sums into a (light is kept).
void addCeilingStats(CeilingRegionStats& a, const CeilingRegionStats& b);

// The per-sample roulette model of a region (variances MSE-weighted: var_exact = var_fv /
// segments, p_mh = f2_mh / segments, p_hm = f2_hm / segments, which rouletteVariance combines
// exactly as it does the unweighted probabilities). A V' class with fewer than kMinClassSamples
// segments borrows `fallback`'s ray costs (its weight in the region is small anyway).
inline constexpr double kMinClassSamples = 16;
RouletteModel ceilingModel(const CeilingRegionStats& r, const ClassCosts& fallback);

// Mean ray costs per V' class over the given sums (ns), with c_s = per_sample.
ClassCosts meanClassCosts(const CeilingRegionStats& all, double per_sample);

struct CeilingInput {
  std::vector<CeilingRegionStats> regions;
  uint32_t num_lights = 1;
  double per_sample_ns = 0;  // c_s: shading cost per shadow segment, paid by every estimator
  ProxyClass proxy_class = ProxyClass::kGeneral;
  double q_min = 0.05;
  bool uses_proxies = true;  // false: no object traces a proxy, the ceiling is 1
};

// One light's (or the whole scene's) totals and its ceiling.
struct CeilingSummary {
  double segments = 0;
  double p_blocked = 0, p_mh = 0, p_hm = 0;  // P(V'=0), P(MH'), P(HM') over segments
  double visibility_var = 0;                 // mean V_p(1-V_p) over segments
  ClassCosts costs;                          // mean ns per ray class; per_sample = c_s
  double var_exact = 0, cost_exact = 0;      // sums: MSE-weighted variance, ns
  double var_oracle = 0, cost_oracle = 0;
  int regions = 0, regions_roulette = 0;  // regions with segments; of those, oracle picks roulette
  double ceiling = 1;                     // (var_exact cost_exact) / (var_oracle cost_oracle)
};

struct CeilingResult {
  CeilingSummary scene;
  std::vector<CeilingSummary> lights;  // one per light
  std::string explanation;             // two sentences: what limits the gain
};

// The oracle over every region of the input. A region's choice is first the cheaper of exact and
// roulette(q*) in its own Var x Cost; because the products of sums do not follow the per-region
// products exactly, the choices are then improved against the totals (each region minimises
// var_r C + cost_r V for the current totals V, C, a few rounds) and all-exact is always a
// candidate, so the ceiling is >= 1. Without proxies or without segments: ceiling 1.
CeilingResult computeCeiling(const CeilingInput& input);

// Two sentences naming what limits the gain, chosen by rules from the measured quantities (in
// order: no proxies, no shadow rays, proxy errors exceeding exact's variance, a proxy no cheaper
// than the original where it says visible, the share of shading in each sample; otherwise what
// the oracle gains and where).
std::string explainCeiling(const CeilingSummary& scene, bool uses_proxies);

}  // namespace proxyvis
