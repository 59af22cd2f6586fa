// The out-of-core renderer's queues (contract in out_of_core_queue.h).
#include "outofcore/out_of_core_queue.h"

#include "distributed/box_index.h"
#include "trace/trace_scene.h"

namespace proxyvis {

std::vector<uint32_t> visitOrder(const std::vector<uint64_t>& counts, const GeometryCache& cache) {
  std::vector<uint32_t> order;
  for (uint32_t m = 0; m < counts.size(); ++m)
    if (counts[m] && cache.resident(m)) order.push_back(m);
  for (uint32_t m = 0; m < counts.size(); ++m)
    if (counts[m] && !cache.resident(m)) order.push_back(m);
  return order;
}

uint32_t queueSegment(const OutOfCoreScene& scene, OutOfCorePolicy policy, const Segment& s,
                      uint32_t own_mesh, uint32_t item, QueueBuilder& builder, uint8_t& flags) {
  thread_local std::vector<LabelEntry> labels;
  thread_local std::vector<BoxIndex::BoxEntry> boxes;
  thread_local std::vector<TraceScene::Candidate> candidates;
  thread_local std::vector<uint32_t> groups;
  thread_local std::vector<uint8_t> found;
  uint32_t queued = 0;
  if (policy == OutOfCorePolicy::kExactBatched) {
    labels.clear();
    scene.objectBoxes().labelsAlong(s, labels);
    for (const LabelEntry& e : labels)
      if (e.label != own_mesh) builder.add(e.label, item), ++queued;
    return queued;
  }
  // Other meshes only where their proxies cannot decide.
  boxes.clear();
  scene.objectBoxes().boxesAlong(s, boxes);
  candidates.clear();
  groups.clear();
  for (const BoxIndex::BoxEntry& b : boxes) {
    if (b.label == own_mesh) continue;
    size_t g = std::find(groups.begin(), groups.end(), b.label) - groups.begin();
    if (g == groups.size()) groups.push_back(b.label);
    candidates.push_back({b.id, uint32_t(g)});
  }
  if (candidates.empty()) return 0;
  found.assign(groups.size(), 0);
  const TraceScene* inside = scene.insideProxies();
  if (inside && inside->crossedGroups(s, candidates, found, 1) > 0) {
    flags |= kBlocked;
    return 0;
  }
  std::fill(found.begin(), found.end(), 0);
  const TraceScene* outside = scene.outsideProxies();
  if (outside) outside->crossedGroups(s, candidates, found, groups.size());
  // A mesh whose outside proxy the segment crosses (the proxies' answer: blocked), or without
  // an outside proxy (none, or an inside one only: it cannot be ruled out).
  for (size_t g = 0; g < groups.size(); ++g)
    if (found[g] || scene.meshes()[groups[g]].outside < 0) builder.add(groups[g], item), ++queued;
  return queued;
}

}  // namespace proxyvis
