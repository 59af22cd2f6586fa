#pragma once
// Sampled one-sided surface distance between two triangle meshes (a Hausdorff estimate).
#include <cstdint>

#include "mesh/tri_mesh.h"

namespace proxyvis {

// Work done by one call (for tests and benchmarks).
struct MeshDistanceStats {
  uint64_t points = 0;        // samples + vertices measured
  uint64_t tree_queries = 0;  // of those, the ones that needed a closest-point query
};

// max over `samples` points of `from` (uniform by area, Rng(seed, i), plus every vertex) of the
// distance to the surface of `to`. A lower bound of the one-sided Hausdorff distance h(from, to)
// that converges to it as samples grows. Both meshes must be non-empty. Points that provably
// cannot raise the maximum skip the closest-point query (`stats` counts the queries made).
double sampledOneSidedDistance(const TriMesh& from, const TriMesh& to, uint64_t samples = 20000,
                               uint64_t seed = 0, MeshDistanceStats* stats = nullptr);

}  // namespace proxyvis
