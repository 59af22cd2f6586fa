// Estimator efficiency on synthetic class mixes: per light sample, variance, expected cost (in the
// scenario's cost units, e.g. ns per ray) and efficiency 1/(Var x Cost) relative to exact, from
// the closed forms (selection.h, roulette.h) and measured by running the runtime estimators on a
// SyntheticTracer that charges each ray its class cost. Prints a table; never fails.
//
//   bench_estimators [--samples N]
// Scenarios follow docs/design.md, measured costs (foliage: c_o/c_p 1.2-2.5, P(MH') 0.16-0.28,
// V(1-V) ~0.05; per-class costs) plus a cheap-proxy case (c_o/c_p = 10). Paper estimators get 16
// probe rays per shading point and 16 light samples per point (one probe per sample, each traced
// against both); their closed-form rows use the true class probabilities (an oracle: free probes).
#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "estimate/region_learner.h"
#include "estimate/roulette.h"
#include "estimate/selection.h"
#include "estimate/synthetic_tracer.h"
#include "estimate/visibility_estimator.h"
#include "util/stats.h"
#include "util/stopwatch.h"

using namespace proxyvis;

namespace {

constexpr int kSamplesPerPoint = 16;  // paper-*: light samples and probes per shading point
constexpr uint64_t kSeed = 2014;

struct Scenario {
  std::string name;
  ProxyClass cls;
  ClassProbabilities mix;
  ClassCosts costs;
};

ClassCosts costs(double cp0, double cp1, double co0, double co1, double per_sample = 0) {
  ClassCosts c;
  c.per_sample = per_sample;
  c.proxy[0] = cp0;
  c.proxy[1] = cp1;
  c.original[0] = co0;
  c.original[1] = co1;
  return c;
}

// The same scenario with `ns` of shading added to every light sample.
Scenario withShading(Scenario s, double ns) {
  s.name += fmt::format(", +{:g} ns shading", ns);
  s.costs.per_sample = ns;
  return s;
}

std::vector<Scenario> scenarios() {
  // ecosys-like: proxy-visible segments cost the same against both; blocked ones 100 / 250.
  const ClassCosts foliage = costs(100, 60, 250, 58);
  // dragon over a plane: most segments never come near the dragon.
  const Scenario dragon{"dragon-plane, outside",
                        ProxyClass::kOutside,
                        {0.15, 0.0, 0.02, 0.83},
                        costs(60, 23, 120, 23)};
  // a proxy 10x cheaper than the original everywhere.
  const ClassCosts cheap = costs(10, 10, 100, 100);
  const Scenario cheap_outside{
      "cheap proxy, outside", ProxyClass::kOutside, {0.30, 0.0, 0.05, 0.65}, cheap};
  return {
      {"foliage, outside, P(MH')=0.20", ProxyClass::kOutside, {0.05, 0.0, 0.20, 0.75}, foliage},
      {"foliage, outside, P(MH')=0.16",
       ProxyClass::kOutside,
       {0.12, 0.0, 0.16, 0.72},
       costs(90, 60, 190, 60)},
      {"foliage, general", ProxyClass::kGeneral, {0.06, 0.03, 0.17, 0.74}, foliage},
      dragon,
      withShading(dragon, 30),
      cheap_outside,
      withShading(cheap_outside, 100),
      {"cheap proxy, general", ProxyClass::kGeneral, {0.30, 0.03, 0.05, 0.62}, cheap},
      {"cheap proxy, inside", ProxyClass::kInside, {0.35, 0.08, 0.0, 0.57}, cheap},
  };
}

struct Row {
  std::string name, params;
  double var = NAN, cost = NAN;    // closed form
  double mvar = NAN, mcost = NAN;  // measured
};

double meanProbeCost(const Scenario& s) {
  const ClassProbabilities& c = s.mix;
  return c.proxyBlocked() * (s.costs.proxy[0] + s.costs.original[0]) +
         c.proxyVisible() * (s.costs.proxy[1] + s.costs.original[1]);
}

double selectionCost(const Scenario& s, const SelectionProbabilities& p, bool probes) {
  const ClassProbabilities& c = s.mix;
  double cost = s.costs.per_sample +
                c.proxyBlocked() * (s.costs.proxy[0] + p.p_plus * s.costs.original[0]) +
                c.proxyVisible() * (s.costs.proxy[1] + p.p_minus * s.costs.original[1]);
  return probes ? cost + meanProbeCost(s) : cost;  // one probe per light sample
}

// Runs the runtime estimator: `points` shading points of the scenario's mix, each pass one
// query per point. Probe estimators take all kSamplesPerPoint samples in one pass (as the
// renderer does); the others one sample per pass, so roulette learns across passes.
void measure(const Scenario& s, EstimatorKind kind, uint64_t samples, Row& row) {
  SyntheticTracer tracer({s.mix}, hashKeys(kSeed, 0x7ace, uint64_t(kind)));
  EstimatorSetup setup;
  setup.kind = kind;
  setup.proxy_class = s.cls;
  setup.probes_per_point = kSamplesPerPoint;
  const uint32_t points = 512;
  setup.num_points = points;
  setup.fixed_costs = s.costs;
  const auto e = makeEstimator(setup);
  tracer.chargeCosts(s.costs);
  const int per_query = e->probesPerPoint() > 0 ? kSamplesPerPoint : 1;
  const uint64_t passes = std::max<uint64_t>(1, samples / (uint64_t(points) * per_query));
  RunningStats stats;
  RayCounts counts;
  std::vector<Segment> segs(per_query), probes(e->probesPerPoint());
  std::vector<double> out(per_query);
  uint64_t next = 0;
  for (uint64_t pass = 0; pass < passes; ++pass) {
    e->beginPass(int(pass));
    for (uint32_t p = 0; p < points; ++p) {
      for (auto& sg : segs) sg = SyntheticTracer::segment(0, next++);
      for (auto& sg : probes) sg = SyntheticTracer::segment(0, next++);
      ShadingPointQuery q;
      q.segments = segs;
      q.probes = probes;
      q.tracer = &tracer;
      q.point = p;
      Rng rng(kSeed, hashKeys(p, pass, uint64_t(kind)));
      e->estimate(q, rng, out, counts);
      for (double x : out) stats.add(x);
    }
    e->endPass();
  }
  row.mvar = stats.variance();
  row.mcost = tracer.spent() / double(stats.count()) + s.costs.per_sample;
}

void printScenario(const Scenario& s, uint64_t samples) {
  const ClassProbabilities& c = s.mix;
  const RouletteModel model = RouletteModel::fromPoint(c, s.costs);
  const double v = c.vAvg();
  fmt::print("\n## {}\n", s.name);
  fmt::print(
      "P(HH')={:.2f} P(HM')={:.2f} P(MH')={:.2f} P(MM')={:.2f}  V(1-V)={:.4f}  "
      "c_p|V'=0,1 = {:g},{:g}  c_o|V'=0,1 = {:g},{:g}  per sample {:g}\n\n",
      c.hh, c.hm, c.mh, c.mm, v * (1 - v), s.costs.proxy[0], s.costs.proxy[1], s.costs.original[0],
      s.costs.original[1], s.costs.per_sample);

  std::vector<Row> rows;
  auto add = [&](EstimatorKind kind, std::string params, double var, double cost) {
    Row r{estimatorName(kind), std::move(params), var, cost};
    measure(s, kind, samples, r);
    rows.push_back(r);
  };
  add(EstimatorKind::kExact, "", v * (1 - v), exactCost(model));
  const RouletteQ cull{s.cls == ProxyClass::kInside ? 0.0 : 1.0,
                       s.cls == ProxyClass::kOutside ? 0.0 : 1.0};
  add(EstimatorKind::kCulling, s.cls == ProxyClass::kGeneral ? "= exact (general)" : "",
      v * (1 - v), s.cls == ProxyClass::kGeneral ? exactCost(model) : rouletteCost(model, cull));
  // A paper estimator's row; `probes`: it pays one probe per light sample.
  auto add_paper = [&](EstimatorKind kind, const SelectionProbabilities& p, bool probes) {
    add(kind, fmt::format("p=({:.2f},{:.2f},{:.2f})", p.p0, p.p_plus, p.p_minus),
        selectionVariance(c, p), selectionCost(s, p, probes));
  };
  add_paper(EstimatorKind::kPaperEqual, equalProbabilities(s.cls), false);
  const SelectionProbabilities po = optimalProbabilities(c, s.cls);
  add_paper(EstimatorKind::kPaperOptimal, po, true);
  add_paper(EstimatorKind::kPaperCost, costHeuristicProbabilities(po, c.error()), true);
  const RegionDecision d = decideRegion(model, s.cls, 0.05, 0.05);
  const RouletteQ q = d.q;
  add(EstimatorKind::kRoulette,
      fmt::format("{} q=({:.2f},{:.2f}); roulette alone {:.2f}x", d.roulette ? "proxy" : "exact",
                  q.q0, q.q1, rouletteEfficiencyVsExact(model, q)),
      d.roulette ? rouletteVariance(model, q) : v * (1 - v),
      d.roulette ? rouletteCost(model, q) : exactCost(model));

  const Row& ex = rows[0];
  fmt::print("| {:<13} | {:>8} | {:>8} | {:>7} | {:>8} | {:>8} | {:>7} | {}\n", "estimator", "Var",
             "Cost", "eff", "Var meas", "Cost meas", "eff meas", "parameters");
  fmt::print("|{:-<15}|{:-<10}|{:-<10}|{:-<9}|{:-<10}|{:-<11}|{:-<10}|{:-<30}\n", "", "", "", "",
             "", "", "", "");
  for (const Row& r : rows) {
    const double eff = (ex.var * ex.cost) / (r.var * r.cost);
    const double meff = (ex.mvar * ex.mcost) / (r.mvar * r.mcost);
    fmt::print(
        "| {:<13} | {:>8.4f} | {:>8.1f} | {:>6.2f}x | {:>8.4f} | {:>9.1f} | {:>7.2f}x | {}\n",
        r.name, r.var, r.cost, eff, r.mvar, r.mcost, meff, r.params);
  }
}

// Wall time per segment of estimate() on the synthetic tracer (one segment per query, as the
// renderer calls it), against the tracer calls alone: the estimator's own overhead, which counts
// against it in equal-time comparisons.
void printOverhead(uint64_t samples) {
  const Scenario s = scenarios()[5];
  SyntheticTracer tracer({s.mix}, 7);
  const uint32_t points = 4096;
  const uint64_t passes = std::max<uint64_t>(4, samples / points);
  auto time_calls = [&] {
    const Stopwatch watch;
    int sink = 0;
    for (uint64_t i = 0; i < passes * points; ++i)
      sink += tracer.proxyVisible(SyntheticTracer::segment(0, i));
    const double ns = 1e9 * watch.seconds();
    return ns / double(passes * points) + (sink == -1 ? 1 : 0);
  };
  const double call_ns = time_calls();
  fmt::print("\n## overhead per segment (ns; synthetic tracer call = {:.1f} ns)\n\n", call_ns);
  fmt::print("| {:<13} | {:>8} | {:>12} | {:>10}\n", "estimator", "ns/seg", "tracer calls",
             "overhead");
  fmt::print("|{:-<15}|{:-<10}|{:-<14}|{:-<11}\n", "", "", "", "");
  for (EstimatorKind kind : allEstimators()) {
    for (bool measured : {false, true}) {
      if (measured && kind != EstimatorKind::kRoulette) continue;
      EstimatorSetup setup;
      setup.kind = kind;
      setup.proxy_class = s.cls;
      setup.num_regions = 16;
      setup.num_points = points;
      if (!measured) setup.fixed_costs = s.costs;
      const auto e = makeEstimator(setup);
      RayCounts counts;
      double out = 0;
      const Stopwatch watch;
      for (uint64_t pass = 0; pass < passes; ++pass) {
        e->beginPass(int(pass));
        for (uint32_t p = 0; p < points; ++p) {
          const Segment seg = SyntheticTracer::segment(0, pass * points + p);
          ShadingPointQuery q;
          q.segments = std::span<const Segment>(&seg, 1);
          q.tracer = &tracer;
          q.region = p / 256;
          q.point = p;
          Rng rng(kSeed, hashKeys(p, pass));
          e->estimate(q, rng, std::span<double>(&out, 1), counts);
        }
        e->endPass();
      }
      const double n = double(passes * points);
      const double ns = 1e9 * watch.seconds() / n;
      const double calls = double(counts.proxy + counts.original) / n;
      fmt::print("| {:<13} | {:>8.1f} | {:>12.2f} | {:>10.1f}\n",
                 std::string(estimatorName(kind)) + (measured ? " (timed)" : ""), ns, calls,
                 ns - calls * call_ns);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t samples = 262144;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--samples") == 0 && i + 1 < argc) {
      samples = std::strtoull(argv[++i], nullptr, 10);
    } else {
      fmt::print(stderr, "usage: bench_estimators [--samples N]\n");
      return 2;
    }
  }
  fmt::print("# bench_estimators: per light sample, closed form vs measured ({} samples each)\n",
             samples);
  fmt::print(
      "eff = Var_exact*Cost_exact / (Var*Cost); roulette = per-region exact-or-proxy "
      "decision (measured: learned over passes, with exploration)\n");
  for (const Scenario& s : scenarios()) printScenario(s, samples);
  printOverhead(samples * 8);
  return 0;
}
