// QemDecimater (proxies/general/qem_decimater.h) against OpenMesh's own MixedDecimaterT: the same
// mesh, collapse for collapse, with a fraction of the legality tests. Counts, not times: OpenMesh
// tests every sampled candidate (10 per multiple-choice collapse) and every outgoing half-edge of
// every vertex the queue updates; testing in cost order needs about one per choice.
#include <gtest/gtest.h>

#include <OpenMesh/Tools/Decimater/MixedDecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>

#include <cstdlib>

#include "proxies/general/general_proxy.h"
#include "proxies/general/qem_decimater.h"
#include "tests/proxies/shared/gen_test_util.h"

namespace proxyvis {
namespace {

namespace OD = OpenMesh::Decimater;

QemMesh toOpenMesh(const TriMesh& input) {
  const TriMesh welded = weldVertices(input);
  QemMesh om;
  std::vector<QemMesh::VertexHandle> vh;
  for (const Vec3f& v : welded.vertices) vh.push_back(om.add_vertex({v.x, v.y, v.z}));
  for (const Triangle& t : welded.triangles) om.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
  om.request_face_normals();
  om.update_face_normals();
  return om;
}

// Both garbage-collected (while their decimaters, which own the status flags, still live).
void expectSameMesh(const QemMesh& a, const QemMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (auto v : a.vertices()) ASSERT_EQ(a.point(v), b.point(QemMesh::VertexHandle(v.idx())));
  for (auto f : a.faces()) {
    auto fa = a.fv_range(f).begin();
    auto fb = b.fv_range(QemMesh::FaceHandle(f.idx())).begin();
    for (int k = 0; k < 3; ++k, ++fa, ++fb) ASSERT_EQ(fa->idx(), fb->idx()) << "face " << f.idx();
  }
}

class QemDecimaterTarget : public testing::TestWithParam<double> {};

TEST_P(QemDecimaterTarget, SameMeshAsMixedDecimaterWithFewerLegalityTests) {
  const TriMesh& input = gen_test::mesh("bunny.off");
  const size_t target = size_t(GetParam() * double(input.numTriangles()));

  QemMesh reference = toOpenMesh(input);
  {
    OD::MixedDecimaterT<QemMesh> d(reference);
    OD::ModQuadricT<QemMesh>::Handle quadric;
    OD::ModNormalFlippingT<QemMesh>::Handle flipping;
    d.add(quadric);
    d.add(flipping);
    ASSERT_TRUE(d.initialize());
    std::srand(1);
    d.decimate_to_faces(0, target, 0.8f);
    reference.garbage_collection();
  }
  QemMesh ours = toOpenMesh(input);
  QemDecimaterCounts counts;
  {
    OD::ModQuadricT<QemMesh>::Handle quadric;
    QemDecimater d(ours, quadric);
    OD::ModNormalFlippingT<QemMesh>::Handle flipping;
    d.add(quadric);
    d.add(flipping);
    ASSERT_TRUE(d.initialize());
    std::srand(1);
    d.decimateToFaces(target, 0.8f);
    ours.garbage_collection();
    counts = d.counts();
  }
  expectSameMesh(reference, ours);
  EXPECT_LE(ours.n_faces(), target);
  ASSERT_GT(counts.collapses, 0u);
  // OpenMesh makes at least 10 per multiple-choice collapse (80 % of them), so >= 8 per
  // collapse; in cost order about 1 per multiple-choice collapse and 6 per queue collapse (one
  // per updated vertex): 2.5 on the bunny.
  EXPECT_LT(double(counts.legality_tests) / double(counts.collapses), 3.0)
      << counts.legality_tests << " legality tests for " << counts.collapses << " collapses";
}

INSTANTIATE_TEST_SUITE_P(Targets, QemDecimaterTarget, testing::Values(0.02, 0.2));

TEST(QemSimplify, GoesThroughTheCostOrderedDecimater) {
  // An unwelded copy (every triangle with its own vertices, as plant meshes come): welded first.
  const TriMesh& input = gen_test::mesh("bunny.off");
  TriMesh soup;
  for (const Triangle& t : input.triangles) {
    const uint32_t base = uint32_t(soup.vertices.size());
    for (uint32_t i : t) soup.vertices.push_back(input.vertices[i]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  soup.source = "bunny soup";
  GeneralOptions g;
  g.ratio = 0.02;
  QemStats stats;
  const TriMesh out = simplifyQem(soup, g, &stats);
  EXPECT_LE(out.numTriangles(), generalTargetFaces(input, g));
  ASSERT_GT(stats.collapses, 0u);
  EXPECT_LT(double(stats.legality_tests) / double(stats.collapses), 3.0);
}

}  // namespace
}  // namespace proxyvis
