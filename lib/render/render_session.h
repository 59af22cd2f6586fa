#pragma once
// A render that can be paused at pass boundaries and resumed: render() in slices. It holds one
// estimator's per-pixel sums, its learner (the estimator) and its pass counter, so several
// sessions can take turns on the machine (render-compare interleaves estimators this way, so
// that drift in the machine's speed lands on all of them alike).
//
// The passes, their samples and the estimator's calls are exactly those of render() with the
// same settings, however the passes are split into slices: for a fixed seed and spp the image
// is bit-identical to render() in one go. Each session has its own clock, which runs only
// inside its own construction and slices: a time budget (RenderSettings::time_budget) is spent
// on that clock, and the last pass is fitted to the time it has left, as render() does.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "render/renderer.h"

namespace proxyvis {

class RenderSession {
 public:
  // Makes its estimator with makeEstimator(estimatorSetupFor(scene, settings)). Traces the
  // primary rays (timed on the session's clock). Throws Error for bad settings.
  RenderSession(const RenderScene& scene, const RenderSettings& settings);
  // With a caller-made estimator, which must outlive the session (see render()).
  RenderSession(const RenderScene& scene, const RenderSettings& settings,
                VisibilityEstimator& estimator);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // True once the spp cap is reached or the time budget is spent on this session's clock.
  bool finished() const;
  // Runs up to n more passes (fewer if the session finishes first); returns how many ran.
  int runPasses(int n);
  // Runs passes until this slice has taken `seconds` of wall time or the session finishes: at
  // least one pass unless finished, and never a pass cut short (the slice may end past
  // `seconds` by part of a pass). Returns the slice's wall time.
  double runFor(double seconds);
  // Runs until finished (the spp cap, or the whole time budget).
  void runToEnd();

  int passes() const;
  int spp() const;  // light samples per pixel taken so far
  // This session's clock: wall time of its construction and its slices.
  double seconds() const;
  // Process CPU time (all threads) spent inside those same intervals.
  double cpuSeconds() const;

  // The image and statistics so far (valid after any number of passes, at least one).
  RenderResult result() const;

 private:
  void start(const RenderScene& scene, const RenderSettings& settings,
             VisibilityEstimator& estimator);
  struct State;
  std::unique_ptr<VisibilityEstimator> owned_;
  std::unique_ptr<State> state_;
};

// Hands the machine to the sessions in turns until every one is finished: each turn is
// runFor(slice_seconds) of one session, and round r visits the unfinished sessions starting at
// index (first + r) mod n, so that no session always goes first. With time budgets, each
// session stops when it has spent its own budget on its own clock. Returns the session index of
// every turn taken, in order (for tests and logs).
std::vector<size_t> runInterleaved(std::span<RenderSession* const> sessions, double slice_seconds,
                                   size_t first = 0);

}  // namespace proxyvis
