// Segments aimed exactly at shared edges and vertices of a closed mesh: the cases where a float
// test may slip between two triangles. Each segment runs from outside the sphere to its centre
// (and back), so it crosses the surface exactly once, at the aimed point: the right answer is
// always "occluded". Measured with Embree 3.13.5 on this icosphere (2 x 2562 vertex and
// 2 x 7680 edge segments): the default mode misses 638 edge (4.2 %) and 560 vertex (10.9 %)
// segments; RTC_SCENE_FLAG_ROBUST misses no edge and 15 vertex segments (0.3 %). Random segments
// almost never come that close (see trace_scene_test.cpp: no disagreement in 10^5).
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <utility>

#include "test_meshes.h"
#include "trace/trace_scene.h"

namespace proxyvis::test {
namespace {

struct Misses {
  size_t vertex = 0, vertex_segments = 0, edge = 0, edge_segments = 0;
};

Misses missedCrossings(bool robust) {
  TraceDevice device;
  const Vec3f c(0.1f, -0.2f, 0.3f);
  TriMesh sphere = icosphere(4, c, 1.0f);
  TraceSceneOptions options;
  options.robust = robust;
  TraceSceneBuilder builder(device, options);
  builder.addMesh(sphere);
  auto scene = builder.build();
  auto missed = [&](const Vec3f& target) {
    Vec3f outside = c + (target - c) * 3.0f;
    return size_t(!scene->occluded(Segment{outside, 0, c - outside, 1})) +
           size_t(!scene->occluded(Segment{c, 0, outside - c, 1}));
  };
  Misses m;
  for (const Vec3f& v : sphere.vertices) {
    m.vertex += missed(v);
    m.vertex_segments += 2;
  }
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const Triangle& t : sphere.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  for (auto [a, b] : edges) {
    m.edge += missed((sphere.vertices[a] + sphere.vertices[b]) * 0.5f);
    m.edge_segments += 2;
  }
  std::printf("[ info ] %s mode: missed %zu of %zu vertex and %zu of %zu edge segments\n",
              robust ? "robust" : "default", m.vertex, m.vertex_segments, m.edge, m.edge_segments);
  return m;
}

// RTC_SCENE_FLAG_ROBUST is the mode to use when a miss matters (e.g. containment checks).
TEST(Watertight, RobustSceneNeverMissesSharedEdges) {
  Misses m = missedCrossings(true);
  EXPECT_EQ(m.edge, 0u);
  EXPECT_LE(m.vertex, m.vertex_segments / 100);
}

// The default (fast) mode is not watertight at exact edges and vertices; this pins down how
// often, so that a change of Embree version or of our ray set-up that makes it worse shows up.
TEST(Watertight, DefaultSceneRarelyMissesExactEdges) {
  Misses m = missedCrossings(false);
  EXPECT_LE(m.edge, m.edge_segments / 10);
  EXPECT_LE(m.vertex, m.vertex_segments / 5);
}

}  // namespace
}  // namespace proxyvis::test
