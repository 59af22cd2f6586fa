// RenderSession: passes split into any slices give render()'s image bit for bit (1 and 2 threads,
// a learning estimator and a probe estimator included); the session's clock runs only inside
// its own slices; a time budget is spent on that clock and ends the session.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>

#include "estimate/roulette.h"
#include "render/render_scene.h"
#include "render/render_session.h"
#include "render/renderer.h"
#include "render_test_util.h"
#include "util/stopwatch.h"

namespace proxyvis {
namespace {

using test::ScratchDir;

// Roulette with fixed costs (deterministic, learns across passes) told the box's outside proxy is
// general, so that it plays roulette where the proxy is cheap enough: its state carries from pass
// to pass.
RenderSettings rouletteSettings() {
  RenderSettings s;
  s.estimator.kind = EstimatorKind::kRoulette;
  ClassCosts costs;
  costs.original[0] = costs.original[1] = 10;
  s.estimator.fixed_costs = costs;
  s.spp = 24;  // the learner leaves exact after its warm-up passes
  s.force_general_proxies = true;
  s.seed = 17;
  s.tile_size = 7;  // tiles that do not divide the image
  s.quiet = true;
  return s;
}

// The session run in slices of the given pass counts, inside an arena of `threads`.
RenderResult sliced(int threads, const RenderScene& scene, const RenderSettings& settings,
                    const std::vector<int>& slices) {
  tbb::task_arena arena(threads);
  RenderResult r;
  arena.execute([&] {
    RenderSession session(scene, settings);
    for (int n : slices) EXPECT_EQ(session.runPasses(n), n);
    EXPECT_TRUE(session.finished());
    r = session.result();
  });
  return r;
}

RenderResult whole(int threads, const RenderScene& scene, const RenderSettings& settings) {
  tbb::task_arena arena(threads);
  RenderResult r;
  arena.execute([&] { r = render(scene, settings); });
  return r;
}

void expectSameImage(const RenderResult& a, const RenderResult& b) {
  EXPECT_EQ(a.radiance.pixels, b.radiance.pixels);
  EXPECT_EQ(a.visibility.pixels, b.visibility.pixels);
  EXPECT_EQ(a.cost.pixels, b.cost.pixels);
  EXPECT_EQ(a.rays.proxy, b.rays.proxy);
  EXPECT_EQ(a.rays.original, b.rays.original);
  EXPECT_EQ(a.spp, b.spp);
  EXPECT_EQ(a.passes, b.passes);
  EXPECT_EQ(a.learned.regions_roulette, b.learned.regions_roulette);
}

TEST(RenderSession, SlicesAreBitIdenticalToOneRenderAtOneAndTwoThreads) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kOutsideProxy);
  const RenderSettings settings = rouletteSettings();
  const RenderResult reference = whole(1, *scene, settings);
  ASSERT_EQ(reference.passes, 24);
  ASSERT_GT(reference.learned.regions_roulette, 0u);  // the learner's state matters
  ASSERT_GT(reference.rays.proxy, 0u);
  for (int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    expectSameImage(whole(threads, *scene, settings), reference);
    expectSameImage(sliced(threads, *scene, settings, std::vector<int>(24, 1)), reference);
    expectSameImage(sliced(threads, *scene, settings, {4, 2, 3, 15}), reference);
    expectSameImage(sliced(threads, *scene, settings, {24}), reference);
  }
  // Teeth: stopping early is another image (the comparison can fail).
  tbb::task_arena arena(1);
  arena.execute([&] {
    RenderSession session(*scene, settings);
    session.runPasses(23);
    EXPECT_FALSE(session.finished());
    EXPECT_NE(session.result().radiance.pixels, reference.radiance.pixels);
  });
}

TEST(RenderSession, ProbePassesSplitLikeOneRender) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kGeneralProxy);
  RenderSettings settings;
  settings.estimator.kind = EstimatorKind::kPaperOptimal;
  settings.estimator.probes_per_point = 4;
  settings.spp = 7;
  settings.samples_per_pass = 3;  // passes of 3, 3, 1 samples
  settings.seed = 3;
  settings.quiet = true;
  const RenderResult reference = whole(2, *scene, settings);
  ASSERT_EQ(reference.passes, 3);
  ASSERT_GT(reference.rays.probe, 0u);
  expectSameImage(sliced(2, *scene, settings, {1, 2}), reference);
  expectSameImage(sliced(1, *scene, settings, {2, 1}), reference);
}

TEST(RenderSession, PassesStopAtTheSppCap) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir);
  RenderSettings settings = test::quietSettings(5);
  RenderSession session(*scene, settings);
  EXPECT_EQ(session.runPasses(3), 3);
  EXPECT_EQ(session.spp(), 3);
  EXPECT_EQ(session.runPasses(10), 2);  // only two were left
  EXPECT_TRUE(session.finished());
  EXPECT_EQ(session.runPasses(1), 0);
  EXPECT_EQ(session.runFor(1.0), 0.0);
  EXPECT_EQ(session.result().spp, 5);
}

TEST(RenderSession, ClockCountsOnlyItsOwnSlices) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir);
  RenderSettings settings = test::timeBudgetSettings(0.3);
  const Stopwatch wall;
  RenderSession session(*scene, settings);
  double slices = session.seconds();  // construction: primary rays, buffers
  const double cpu_after_start = session.cpuSeconds();
  int rounds = 0;
  while (!session.finished()) {
    const double spent = session.runFor(0.02);
    // A slice runs until its time is spent, in whole passes, unless the budget ends first.
    if (!session.finished()) {
      EXPECT_GE(spent, 0.02);
    }
    slices += spent;
    ++rounds;
    // Time outside the session (another estimator's slice) is not on its clock.
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  EXPECT_NEAR(session.seconds(), slices, 1e-9);
  EXPECT_GE(session.seconds(), settings.time_budget);
  // The sleeps are not counted. The upper bound is loose: a loaded machine stretches every sleep.
  EXPECT_GE(wall.seconds() - session.seconds(), 0.03 * rounds);
  EXPECT_LT(wall.seconds() - session.seconds(), 3 * 0.03 * rounds + 2.0);
  // 0.3 s in slices of 0.02 s: fewer than 3 only if slices stalled for 0.1 s each.
  EXPECT_GE(rounds, 3);
  EXPECT_GT(session.cpuSeconds(), cpu_after_start);
  const RenderResult r = session.result();
  EXPECT_EQ(r.seconds, session.seconds());
  EXPECT_EQ(r.passes, session.passes());
  EXPECT_GE(r.spp, rounds);  // at least one pass per slice
  EXPECT_GT(r.cpu_seconds, 0);
  // The budget was spent on the session's own clock: no more passes.
  const int passes = session.passes();
  EXPECT_EQ(session.runFor(1.0), 0.0);
  EXPECT_EQ(session.passes(), passes);
}

TEST(RenderSession, InterleavedTurnsRotateUntilEachSpentItsOwnBudget) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir);
  RenderSettings settings = test::timeBudgetSettings(0.3);
  std::vector<std::unique_ptr<RenderSession>> owned;
  std::vector<RenderSession*> sessions;
  std::vector<double> construction;  // on each clock before the schedule
  for (int i = 0; i < 3; ++i) {
    settings.seed = uint64_t(i);
    owned.push_back(std::make_unique<RenderSession>(*scene, settings));
    sessions.push_back(owned.back().get());
    construction.push_back(sessions.back()->seconds());
  }
  const Stopwatch wall;
  const std::vector<size_t> turns = runInterleaved(sessions, 0.01, 1);
  const double elapsed = wall.seconds();
  // The first three rounds (about 0.03 s of each 0.3 s budget: nobody is done yet) start at
  // session 1, 2, 0 and give every session one turn each.
  ASSERT_GE(turns.size(), 9u);
  const std::vector<size_t> first_rounds(turns.begin(), turns.begin() + 9);
  EXPECT_EQ(first_rounds, (std::vector<size_t>{1, 2, 0, 2, 0, 1, 0, 1, 2}));
  double on_clocks = 0;
  for (size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    EXPECT_TRUE(sessions[i]->finished());
    EXPECT_GE(sessions[i]->seconds(), settings.time_budget);
    // Past it by part of a pass; loose because a loaded machine can stall one pass.
    EXPECT_LT(sessions[i]->seconds(), settings.time_budget + 1.0);
    EXPECT_GE(std::count(turns.begin(), turns.end(), i), 3);
    on_clocks += sessions[i]->seconds() - construction[i];
  }
  // Each clock ran only in its own turns, and the turns do not overlap: their sum is the wall
  // time of the schedule, less the moments between turns.
  EXPECT_LE(on_clocks, elapsed);
  EXPECT_GT(on_clocks, 0.5 * elapsed);
}

}  // namespace
}  // namespace proxyvis
