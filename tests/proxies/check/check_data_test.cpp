// proxy-check on the bundled closed meshes (bunny, dragon, spot): outside proxies must show no
// HM' and verify as `contains`; a shifted copy (a general proxy) must show both error kinds.
// The bounding box needs no generator; the convex hull comes from proxies/outside.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io/mesh_io.h"
#include "proxies/check/pair_check.h"
#include "proxies/outside/outside_proxy.h"
#include "tests/proxies/check/check_shapes.h"
#include "tests/proxies/check/pair_check_util.h"

namespace proxyvis {
namespace {

class ClosedMesh : public testing::TestWithParam<const char*> {
 protected:
  TriMesh load() const {
    // The bundled copy (data/): the project works with it alone.
    return loadMesh(std::filesystem::path(PROXYVIS_DATA_DIR) / GetParam());
  }
  static PairCheckReport check(const TriMesh& original, const TriMesh& proxy) {
    return test::testCheckPair(original, proxy, 17);
  }
};

TEST_P(ClosedMesh, BoundingBoxIsOutside) {
  const TriMesh mesh = load();
  const Bounds3f b = mesh.bounds();
  const Vec3f margin = b.extent() * 0.01f;
  const PairCheckReport r = check(mesh, test::makeBox(b.lo - margin, b.hi + margin, "bbox"));
  EXPECT_TRUE(r.original.closed);
  EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kContains) << r.exact.detail;
  EXPECT_EQ(r.sampled.counts.hm, 0u);
  EXPECT_GT(r.sampled.counts.mh, 0u);
  EXPECT_FALSE(r.mismatch);
}

TEST_P(ClosedMesh, ShiftedCopyIsGeneral) {
  const TriMesh mesh = load();
  const Bounds3f b = mesh.bounds();
  const TriMesh shifted =
      test::transformed(mesh, b.center(), 1.0f, Vec3f(0.02f, 0.01f, 0) * b.diagonal(), "shift");
  const PairCheckReport r = check(mesh, shifted);
  EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kIntersecting);
  EXPECT_GT(r.sampled.counts.hm, 0u);
  EXPECT_GT(r.sampled.counts.mh, 0u);
  EXPECT_EQ(r.sampled_class, SampledClass::kGeneral);
}

TEST_P(ClosedMesh, ConvexHullIsOutside) {
  const TriMesh mesh = load();
  const PairCheckReport r = check(mesh, makeHullProxy(mesh));
  // The hull shares vertices with the mesh (touching), so the exact verdict may be
  // `intersecting`; the rays must still never see HM'.
  EXPECT_EQ(r.sampled.counts.hm, 0u);
  EXPECT_FALSE(r.mismatch);
}

INSTANTIATE_TEST_SUITE_P(Data, ClosedMesh,
                         testing::Values("bunny.off", "dragon.drc", "spot_triangulated.obj"));

}  // namespace
}  // namespace proxyvis
