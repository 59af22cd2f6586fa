#include "distributed/forwarding_round.h"

#include <tbb/parallel_for.h>

#include <cstring>

#include "distributed/distributed_scene.h"

namespace proxyvis {

void RoundEntries::reset(size_t n, size_t slots) {
  samples.assign(n, {});
  state.assign(n, kNoVisibility);
  estimate.assign(n, 0.0);
  weight.assign(n, 1.0);
  outcome.assign(n, kBlockedLocally);
  forwarded.assign(n, 0);
  forwards.assign(n, 0);
  candidates.assign(n * slots, 0);
  num_candidates.assign(n, 0);
  next.assign(n, 0);
  region.assign(n, 0);
  via_proxies.assign(n, 0);
  route_seconds.assign(n, -1.0f);
}

void answerRequests(void* context, const uint8_t* requests, size_t count, uint8_t* answers) {
  const auto* scene = static_cast<const DistributedScene*>(context);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        Segment s;
                        std::memcpy(&s, requests + i * sizeof(Segment), sizeof(Segment));
                        answers[i] = scene->ownOccluded(s) ? 1 : 0;
                      }
                    });
}

}  // namespace proxyvis
