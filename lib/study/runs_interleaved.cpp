// Equal-time cells with the estimators interleaved (runs.h). Rendering one estimator after the
// other lets the machine's drift (other processes, clock frequency, caches) land on whichever
// runs later: the same exact render has reached 955 spp in one run and 1,160 a minute later.
// So each run (seed, repeat) keeps one RenderSession per estimator and hands out the machine in
// slices of budget/16, round-robin, until every session has spent the budget on its own clock.
// Before the run, each estimator renders a throw-away warm-up slice (caches, page faults, TBB's
// threads, the estimator's code), whose samples and time are discarded.
#include <fmt/format.h>

#include <memory>

#include "render/render_session.h"
#include "study/runs.h"

namespace proxyvis {

namespace {

// A slice is this fraction of the budget (at least one pass): small enough that drift within a
// run is shared out finely, large enough that switching sessions (cache refills) costs little.
constexpr int kSlicesPerBudget = 16;

double sliceSeconds(double budget) {
  return budget / kSlicesPerBudget;
}
// The warm-up: one slice's worth of passes per estimator.
double warmupSeconds(double budget) {
  return sliceSeconds(budget);
}

// The estimator of turn `turn` in the warm-up and creation of run `run`: the order starts
// elsewhere in each run, as runInterleaved() starts its rounds.
size_t turnEstimator(size_t turn, int run, size_t n) {
  return (turn + size_t(run)) % n;
}

}  // namespace

std::vector<RenderResult> runEqualTimeRun(const RenderScene& scene, const CompareOptions& options,
                                          double time_budget, int run) {
  const std::vector<EstimatorKind>& kinds = options.estimator_list;
  const size_t n = kinds.size();
  std::vector<RenderSettings> settings;
  for (EstimatorKind kind : kinds) {
    settings.push_back(runSettings(options, kind, 0, time_budget, run));
    settings.back().quiet = true;  // sessions take turns: one bar each would flicker
  }
  for (size_t turn = 0; turn < n; ++turn) {
    const size_t e = turnEstimator(turn, run, n);
    RenderSession warmup(scene, settings[e]);
    warmup.runFor(warmupSeconds(time_budget));
  }
  // Created in turn order too: the primary rays are on each session's own clock.
  std::vector<std::unique_ptr<RenderSession>> sessions(n);
  for (size_t turn = 0; turn < n; ++turn) {
    const size_t e = turnEstimator(turn, run, n);
    sessions[e] = std::make_unique<RenderSession>(scene, settings[e]);
  }
  std::vector<RenderSession*> order;
  for (const auto& session : sessions) order.push_back(session.get());
  runInterleaved(order, sliceSeconds(time_budget), size_t(run) % n);
  std::vector<RenderResult> results;
  for (size_t e = 0; e < n; ++e) {
    results.push_back(sessions[e]->result());
    requireFinitePixels(results.back().radiance, scene.desc().path,
                        fmt::format("the {} render (seed {})", estimatorName(kinds[e]), run + 1));
  }
  return results;
}

std::string interleavedTimingNote(const CompareOptions& o) {
  return fmt::format(
      "Timing: equal-time renders are interleaved. For each of the {} seed(s) x {} repeat(s), "
      "every estimator first renders a throw-away warm-up of {:.3g} s, then the estimators take "
      "turns in slices of {:.3g} s (budget/{}, whole passes), their order rotating each round, "
      "until each has spent {:g} s on its own clock (the wall time of its own slices; its last "
      "pass fitted to the time left). Equal-spp renders alternate estimators seed by seed. The "
      "[lowest–highest, s.e.] beside an efficiency is its ratio run by run against exact's run "
      "with the same seed and repeat.",
      o.seeds, o.repeats, warmupSeconds(o.equal_time), sliceSeconds(o.equal_time), kSlicesPerBudget,
      o.equal_time);
}

nlohmann::json interleavedTimingMeta(const CompareOptions& o) {
  return {{"equal_time", "interleaved"},
          {"equal_spp", "alternating by seed"},
          {"repeats", o.repeats},
          {"slice_seconds", sliceSeconds(o.equal_time)},
          {"warmup_seconds", warmupSeconds(o.equal_time)},
          {"order", "rotates each round"}};
}

}  // namespace proxyvis
