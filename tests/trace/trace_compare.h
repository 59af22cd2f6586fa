#pragma once
// Embree against the brute-force reference on many segments, disagreements counted and classified.
#include <cstdint>
#include <memory>
#include <vector>

#include "brute_force.h"
#include "trace/trace_scene.h"

namespace proxyvis::test {

struct OcclusionAgreement {
  size_t segments = 0;
  size_t occluded = 0;       // by the reference
  size_t disagreements = 0;  // Embree != reference
  size_t unexplained = 0;    // disagreements not within eps of an edge, vertex or endpoint
  std::vector<size_t> unexplained_indices;
};

// Traces `segs` with scene.occluded (batch) and with the reference; a disagreement is explained
// if reference.nearBoundary(segment, eps).
OcclusionAgreement compareOcclusion(const TraceScene& scene, const BruteForceMesh& reference,
                                    const std::vector<Segment>& segs, double eps);

std::vector<Segment> randomSegments(const Bounds3f& box, uint64_t seed, size_t n);

// The seed of the trace tests' random segments and meshes.
inline constexpr uint64_t kSeed = 20140623;

// A scene of `mesh` alone, user id 7.
inline std::unique_ptr<TraceScene> flatScene(TraceDevice& device, const TriMesh& mesh,
                                             const TraceSceneOptions& options = {}) {
  TraceSceneBuilder builder(device, options);
  builder.addMesh(mesh, 7);
  return builder.build();
}

}  // namespace proxyvis::test
