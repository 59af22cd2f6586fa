// The acceptance test: Embree occlusion against brute-force Möller–Trumbore in double on
// 100 000 random segments on the bunny (closed, 6 966 triangles), endpoints uniform in the
// bunny's box grown by 20 % per side. Every disagreement must be a segment that passes within
// 1e-5 of the diagonal of an edge, a vertex or its own endpoint (where float rounding decides).
#include <gtest/gtest.h>

#include <filesystem>

#include "brute_force.h"
#include "mesh/io/mesh_io.h"
#include "test_meshes.h"
#include "trace/trace_scene.h"
#include "trace_compare.h"

namespace proxyvis::test {
namespace {

void checkBunny(bool robust, uint64_t seed) {
  TriMesh bunny = loadMesh(std::filesystem::path(PROXYVIS_DATA_DIR) / "bunny.off");
  ASSERT_EQ(bunny.numTriangles(), 6966u);
  TraceDevice device;
  TraceSceneOptions options;
  options.robust = robust;
  TraceSceneBuilder builder(device, options);
  builder.addMesh(bunny);
  auto scene = builder.build();
  BruteForceMesh ref(bunny);
  auto segs = randomSegments(grown(bunny.bounds(), 0.2f), seed, 100000);
  OcclusionAgreement a = compareOcclusion(*scene, ref, segs, 1e-5 * bunny.diagonal());
  std::printf(
      "[ info ] bunny (%s): %zu segments, %zu occluded, %zu disagreements (%zu not near "
      "an edge)\n",
      robust ? "robust" : "default", a.segments, a.occluded, a.disagreements, a.unexplained);
  EXPECT_EQ(a.unexplained, 0u) << "seed " << seed << ", first unexplained segment "
                               << (a.unexplained_indices.empty() ? 0 : a.unexplained_indices[0]);
  EXPECT_LE(a.disagreements, 10u) << "seed " << seed;
  EXPECT_GT(a.occluded, a.segments / 10);
  EXPECT_LT(a.occluded, a.segments - a.segments / 10);
  EXPECT_EQ(scene->raysTraced(), a.segments);
}

TEST(Bunny, OcclusionMatchesBruteForceOn100kSegments) {
  checkBunny(false, 31);
}
TEST(Bunny, RobustOcclusionMatchesBruteForceOn100kSegments) {
  checkBunny(true, 32);
}

}  // namespace
}  // namespace proxyvis::test
