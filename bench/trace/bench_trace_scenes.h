#pragma once
// The scenes and segments bench_trace measures: a mesh flattened and instanced on a grid, each
// built through lib/trace (TraceScene) and through the bare Embree API, the reference loop that
// traces the bare ones, and uniform random segments in a box around a scene.
#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "trace/trace_scene.h"

namespace proxyvis::trace_bench {

constexpr size_t kChunk = 1024;  // same chunking as the wrapper's batch

struct Options {
  uint64_t rays = 10'000'000;
  uint32_t instances = 1000;
  int reps = 3;
  bool robust = false;
  bool high_quality = true;
  std::string mesh;
};

struct BenchScene {
  std::string name;
  std::unique_ptr<TraceScene> wrapped;
  RTCScene bare = nullptr;  // same geometry through the bare API
  std::vector<RTCScene> bare_prototypes;
};

// n segments between independent uniform points of the scene's box grown by 10 % on every side.
std::vector<Segment> makeSegments(const Bounds3f& scene_box, uint64_t n, uint64_t seed);

// The bare reference, written against the Embree API only: rtcOccluded1 over the segments in
// the wrapper's parallel_for structure; uint8_t output like the wrapper, so both write the
// same bytes.
void bareOccluded(RTCScene scene, const std::vector<Segment>& segs, std::vector<uint8_t>& out);

// The instance grid: k instances on a cubic grid, spacing 1.2 x the mesh's largest extent, each
// turned about z by an angle keyed on its index (so the BVHs of neighbours differ).
std::vector<Affine3f> gridTransforms(const TriMesh& mesh, uint32_t k);

// The mesh as one flattened mesh, and o.instances instances of it on the grid (in the bare
// scene, instance i answers rays whose mask has bit i % 32).
BenchScene flatScene(TraceDevice& device, const TriMesh& mesh, const Options& o);
BenchScene instanceScene(TraceDevice& device, const TriMesh& mesh, const Options& o);

}  // namespace proxyvis::trace_bench
