#include "proxies/check/scene_stream.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "util/progress.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

// One target's share of a batch of world draws, classified in index order.
void classifyBatch(const StreamTarget& t, uint64_t first, const std::vector<WorldSegment>& world,
                   const ClassifyOptions& options, Classification& result, bool& done) {
  std::vector<Segment> segs;
  std::vector<uint64_t> index;
  std::vector<uint32_t> scratch;
  Segment s;
  for (size_t i = 0; i < world.size(); ++i)
    if (segmentForMesh(*t.placements, first + i, world[i], s, scratch)) {
      segs.push_back(s);
      index.push_back(first + i);
    }
  std::vector<uint8_t> hit_o(segs.size()), hit_p(segs.size());
  Stopwatch trace;
  t.proxy->occluded(segs, hit_p);
  result.seconds_proxy += trace.seconds();
  trace.restart();
  t.original->occluded(segs, hit_o);
  result.seconds_original += trace.seconds();
  for (size_t j = 0; j < segs.size() && !done; ++j) {
    const bool o = hit_o[j], p = hit_p[j];
    ClassCounts& c = result.counts;
    ++(o ? (p ? c.hh : c.hm) : (p ? c.mh : c.mm));
    if (o != p && result.errors.size() < options.max_error_segments)
      result.errors.push_back(
          {segs[j].org + segs[j].tnear * segs[j].dir, segs[j].org + segs[j].tfar * segs[j].dir, o});
    if (c.total() == options.segments) {
      result.attempts = index[j] + 1;
      done = true;
    }
  }
  if (!done) result.attempts = first + world.size();
  result.skipped = result.attempts - result.counts.total();
}

}  // namespace

std::vector<Classification> classifySceneStream(const WorldSegmentSource& world,
                                                const std::vector<StreamTarget>& targets,
                                                const ClassifyOptions& options) {
  const Stopwatch whole;
  const size_t n_targets = targets.size();
  std::vector<Classification> results(n_targets);
  std::vector<char> done(n_targets, options.segments == 0);
  const uint64_t cap = std::max(options.max_attempts, options.segments);
  const size_t batch = std::max<size_t>(1, options.batch);
  Progress progress("Classifying segments", options.segments * n_targets, options.quiet);
  std::vector<WorldSegment> draws;
  for (uint64_t first = 0; first < cap; first += batch) {
    if (std::all_of(done.begin(), done.end(), [](char d) { return d != 0; })) break;
    draws.resize(size_t(std::min<uint64_t>(batch, cap - first)));
    tbb::parallel_for(size_t(0), draws.size(), [&](size_t i) { draws[i] = world(first + i); });
    tbb::parallel_for(size_t(0), n_targets, [&](size_t t) {
      if (done[t]) return;
      const uint64_t before = results[t].counts.total();
      bool finished = false;
      classifyBatch(targets[t], first, draws, options, results[t], finished);
      done[t] = finished;
      progress.update(results[t].counts.total() - before);
    });
  }
  progress.done();
  for (Classification& r : results) r.seconds = whole.seconds();
  return results;
}

}  // namespace proxyvis
