// proxy-check SCENE.json under the scene distribution: a placed mesh's exact check runs in object
// space, where its class was proved, and on the placed float copies the renderer traces. A tight
// inside proxy (a box within an ulp of its original's faces) is contained in object space; its
// copies rounded through the placement's float transform cross, and the check says so.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <limits>
#include <string>

#include "mesh/io/mesh_io.h"
#include "mesh/tri_mesh.h"
#include "proxies/check/containment.h"
#include "proxies/check/scene_pairs.h"
#include "proxies/check/scene_segments.h"
#include "scene/scene_desc.h"
#include "tests/support/scratch_dir.h"

namespace proxyvis {
namespace {

// The box [-h, h]^3 as OFF text, 12 outward triangles.
std::string boxOff(double h) {
  std::string s = "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i)
    s += fmt::format("{:.9g} {:.9g} {:.9g}\n", i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& t : f) s += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
  return s;
}

constexpr const char* kScene = R"({
  "camera": {"eye": [0, 30, 40], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40,
             "resolution": [32, 32]},
  "lights": [{"type": "quad", "corner": [-2, 40, -2], "edge_u": [4, 0, 0], "edge_v": [0, 0, 4],
              "radiance": [10, 10, 10]}],
  "meshes": [
    {"name": "ground", "file": "ground.obj", "make_proxy": false},
    {"name": "box", "file": "box.off",
     "transform": {"translate": [0.3, 8.1, -0.2], "rotate": [0.3, 1, 0.2, 20], "scale": 8},
     "proxies": [{"kind": "inside", "file": "inner.off", "class": "inside"}]}
  ]
})";

TEST(ScenePairSpace, PlacedProxyIsCheckedInObjectSpaceAndOnThePlacedCopies) {
  test::ScratchDir dir;
  dir.write("ground.obj", "v -50 0 -50\nv 50 0 -50\nv 50 0 50\nv -50 0 50\nf 1 3 2\nf 1 4 3\n");
  dir.write("box.off", boxOff(1.0));
  dir.write("scene.json", kScene);
  // The gap from 1 ulp of 1.0 up: the first whose rounded world copies cross.
  bool crossing_found = false;
  for (int ulps = 1; ulps <= 8 && !crossing_found; ++ulps) {
    dir.write("inner.off", boxOff(1.0 - ulps * double(std::numeric_limits<float>::epsilon())));
    const SceneDesc scene = loadSceneDesc(dir / "scene.json");
    const SceneMeshDesc& box = scene.meshes[1];
    const TriMesh original = loadMesh(box.file), proxy = loadMesh(box.proxies[0].file);
    ASSERT_EQ(checkContainment(original, proxy).verdict, ContainmentVerdict::kContained) << ulps;
    if (checkContainment(transformedMesh(original, box.transform),
                         transformedMesh(proxy, box.transform))
            .verdict == ContainmentVerdict::kContained)
      continue;
    crossing_found = true;
    PairCheckOptions options;
    options.rays = 200;
    options.quiet = true;
    const std::vector<ScenePair> pairs = checkScenePairs(scene, options, true);
    ASSERT_EQ(pairs.size(), 1u);
    const PairCheckReport& r = pairs[0].report;
    // Proved in object space, where proxy-gen proved it, and refuted on the placed float copies
    // the renderer traces: the check says both, and fails (the class is general there).
    EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kContained) << r.exact.detail;
    ASSERT_TRUE(r.exact_placed.has_value());
    EXPECT_NE(r.exact_placed->verdict, ContainmentVerdict::kContained);
    EXPECT_TRUE(r.placed_mismatch.has_value());
    EXPECT_TRUE(r.failed());
    EXPECT_EQ(provenClass(r), ProxyClass::kGeneral);
    EXPECT_FALSE(r.mismatch.has_value()) << *r.mismatch;
    EXPECT_EQ(r.distribution, "scene");
    EXPECT_GT(r.sampled.counts.total(), 0u);  // the world-space segments still reach the box
  }
  EXPECT_TRUE(crossing_found) << "no gap of 1-8 ulps made the rounded copies cross: the test "
                                 "no longer shows what it is for";
}

}  // namespace
}  // namespace proxyvis
