#pragma once
// One forwarding round's entries and the answer to a forwarded segment: the data the
// data-parallel render loop (data_parallel_render.cpp) keeps between its steps.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/integrator_steps.h"

namespace proxyvis {

enum EntryState : uint8_t { kNoVisibility = 0, kDecided = 1, kPending = 2 };
// How a segment was decided before any forward.
enum Outcome : uint8_t { kBlockedLocally, kBlockedByInside, kNoRemoteRank, kUndecided };

// The entries of one round: light samples of `count` passes for every pixel this rank shades.
struct RoundEntries {
  std::vector<PreparedSample> samples;
  std::vector<uint8_t> state;
  std::vector<double> estimate;  // V~ once decided
  std::vector<double> weight;    // what a visible answer is worth: 1, or 1/q under roulette
  std::vector<uint8_t> outcome;  // Outcome, once the local trace and the route are known
  std::vector<uint8_t> forwarded;
  std::vector<uint16_t> forwards;    // ranks asked so far
  std::vector<uint16_t> candidates;  // (ranks - 1) slots per entry
  std::vector<uint8_t> num_candidates, next;
  std::vector<uint32_t> region;
  std::vector<uint8_t> via_proxies;  // routed through the proxies (else the instance boxes)
  std::vector<float> route_seconds;  // the route's time when it was timed, else -1

  // Every entry reset for n samples and `slots` candidate slots each.
  void reset(size_t n, size_t slots);
};

// A forwarded segment's answer: 1 if this rank's own originals block it. `context` is the
// DistributedScene (the signature MpiComm::exchange calls).
void answerRequests(void* context, const uint8_t* requests, size_t count, uint8_t* answers);

}  // namespace proxyvis
