// The film bench's helpers on hand-made inputs: the linear fit recovers known coefficients, and
// the scene variants keep the right meshes and place copies on distinct tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "instance_variants.h"
#include "linear_fit.h"

namespace proxyvis::bench {
namespace {

TEST(FilmBenchFit, RecoversExactCoefficients) {
  // y = 120 * x1 + 900 * x2 + 5e7, at scales like the bench's (1e7 triangles, 1e5 instances).
  const std::vector<double> x1 = {3.4e6, 3.4e6, 3.4e6, 0.9e6, 0.9e6};
  const std::vector<double> x2 = {4685, 46850, 468500, 1200, 12000};
  std::vector<double> y;
  for (size_t i = 0; i < x1.size(); ++i) y.push_back(120 * x1[i] + 900 * x2[i] + 5e7);
  const auto fit = fitLinear2(x1, x2, y);
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->a, 120, 1e-6);
  EXPECT_NEAR(fit->b, 900, 1e-6);
  EXPECT_NEAR(fit->c, 5e7, 1e-1);
  EXPECT_LT(fit->max_relative_residual, 1e-9);
}

TEST(FilmBenchFit, RefusesUndeterminedPoints) {
  // Prototype triangles never vary: a and c cannot be told apart.
  EXPECT_FALSE(fitLinear2({1e6, 1e6, 1e6}, {10, 100, 1000}, {1, 2, 3}).has_value());
  EXPECT_FALSE(fitLinear2({1, 2}, {3, 4}, {5, 6}).has_value());
}

SceneDesc threeMeshScene() {
  SceneDesc s;
  s.meshes.resize(4);
  s.meshes[0].name = "ground";  // placed, no instances
  for (int m = 1; m < 4; ++m) {
    s.meshes[size_t(m)].name = "plant" + std::to_string(m);
    s.meshes[size_t(m)].place = false;
  }
  for (uint32_t m : {1u, 2u, 3u, 3u, 2u}) {
    SceneInstanceDesc i;
    i.mesh = m;
    i.transform = Affine3f::translation({float(m), 10.0f * float(m), 0});
    s.instances.push_back(i);
  }
  return s;
}

TEST(FilmBenchVariants, PrototypeCopiesShareOutTheInstances) {
  const SceneDesc s = withPrototypeCopies(threeMeshScene(), 2);
  // ground once; plant1..3 and one copy of each.
  ASSERT_EQ(s.meshes.size(), 7u);
  EXPECT_EQ(s.meshes[4].name, "plant1_copy1");
  EXPECT_EQ(s.meshes[6].name, "plant3_copy1");
  ASSERT_EQ(s.instances.size(), 5u);
  // Instances in order: plant1, plant2, plant3, plant3 (its 2nd: the copy), plant2 (the copy).
  const std::vector<uint32_t> expected = {1, 2, 3, 6, 5};
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(s.instances[i].mesh, expected[i]) << i;
  EXPECT_EQ(instancedMeshCount(s), 5);  // plant1's copy has no instance of its own
}

TEST(FilmBenchVariants, CopiesLandOnDistinctTilesAroundTheOriginal) {
  const SceneDesc base = threeMeshScene();
  const SceneDesc s = withInstanceCopies(base, 9);
  ASSERT_EQ(s.instances.size(), 9 * base.instances.size());
  // The first copy is the original, unchanged.
  for (size_t i = 0; i < base.instances.size(); ++i)
    EXPECT_EQ(s.instances[i].transform.m[0][3], base.instances[i].transform.m[0][3]);
  // Every copy of the first instance sits at its own place; 9 copies fill the 3x3 block.
  std::set<std::pair<float, float>> places;
  for (size_t c = 0; c < 9; ++c) {
    const Affine3f& t = s.instances[c * base.instances.size()].transform;
    places.insert({t.m[0][3], t.m[1][3]});
    // Within one tile step of the original (x extent 2, y extent 20, plus 1 %).
    EXPECT_LE(std::abs(t.m[0][3] - 1.0f), 2.03f);
    EXPECT_LE(std::abs(t.m[1][3] - 10.0f), 20.3f);
  }
  EXPECT_EQ(places.size(), 9u);
}

}  // namespace
}  // namespace proxyvis::bench
