#include "view3d/view_decimate.h"

#include <gtest/gtest.h>

#include "mesh/primitives.h"

namespace proxyvis {
namespace {

TEST(ViewDecimate, MeshUnderTheCapIsKeptAsItIs) {
  const TriMesh sphere = makeUvSphere({1, 2, 3}, 2, 16, 8);
  const ViewMesh view = decimateForView(sphere, sphere.numTriangles());
  EXPECT_EQ(view.grid, 0u);
  EXPECT_EQ(view.mesh.triangles, sphere.triangles);
  EXPECT_EQ(view.mesh.numVertices(), sphere.numVertices());
}

TEST(ViewDecimate, LargeMeshFitsTheCapAndKeepsItsShape) {
  const TriMesh sphere = makeUvSphere({1, 2, 3}, 2, 400, 200);  // 159,200 triangles
  for (size_t cap : {50'000u, 5'000u, 300u}) {
    const ViewMesh view = decimateForView(sphere, cap);
    EXPECT_GT(view.grid, 0u);
    EXPECT_LE(view.mesh.numTriangles(), cap);
    EXPECT_GT(view.mesh.numTriangles(), cap / 4) << "the grid is far coarser than needed";
    // Every kept vertex is the mean of vertices of one cell: within a cell of the sphere.
    const float cell = 4.0f / float(view.grid);
    for (const Vec3f& v : view.mesh.vertices)
      EXPECT_NEAR(length(v - Vec3f(1, 2, 3)), 2.0f, 2 * cell);
    const Bounds3f box = view.mesh.bounds();
    EXPECT_NEAR(box.extent().x, 4.0f, 2 * cell);
    for (const Triangle& t : view.mesh.triangles) {
      EXPECT_NE(t[0], t[1]);
      EXPECT_NE(t[1], t[2]);
      EXPECT_NE(t[0], t[2]);
      for (uint32_t i : t) EXPECT_LT(i, view.mesh.numVertices());
    }
  }
}

TEST(ViewDecimate, TinyCapStillGivesAtMostThatMany) {
  const TriMesh sphere = makeUvSphere({0, 0, 0}, 1, 64, 32);
  EXPECT_LE(decimateForView(sphere, 1).mesh.numTriangles(), 1u);
  EXPECT_THROW(decimateForView(sphere, 0), std::invalid_argument);
}

TEST(ViewDecimate, ClusteringMergesTheVerticesOfOneCell) {
  // Two triangles sharing an edge, one of them thin: on a 1-cell grid both collapse.
  TriMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  EXPECT_EQ(clusterVertices(m, 1000).numTriangles(), 2u);
  const TriMesh one = clusterVertices(m, 1);  // cells [0,1) and [1, 1]: corners stay apart
  EXPECT_EQ(one.numTriangles(), 2u);
  TriMesh close = m;
  close.vertices[3] = {0.001f, 0.001f, 0};  // in vertex 0's cell on a coarse grid
  EXPECT_EQ(clusterVertices(close, 4).numTriangles(), 1u);
  EXPECT_THROW(clusterVertices(m, 0), std::invalid_argument);
}

}  // namespace
}  // namespace proxyvis
