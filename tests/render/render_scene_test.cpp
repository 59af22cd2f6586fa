// RenderScene: the self-shadowing rule (docs/design.md, pitfall 1), the light checks (pitfall 2),
// the proxy class the estimators are told, proxy selection, instances.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/scene_tracer.h"
#include "render_test_util.h"

namespace proxyvis {
namespace {

using test::BoxScene;
using test::ScratchDir;

struct SegmentClasses {
  uint64_t total = 0, hm = 0, mh = 0, culling_wrong = 0, naive_proxy_hit_but_visible = 0;
};

// Classifies every shadow segment of pass 0 leaving object `object` (all objects if -1).
SegmentClasses classify(const RenderScene& scene, int object, int pass = 0) {
  RenderSettings settings;
  const PassSegments ps = passSegments(scene, settings, pass);
  SegmentClasses c;
  for (size_t i = 0; i < ps.segments.size(); ++i) {
    if (object >= 0 && ps.objects[i] != uint32_t(object)) continue;
    const SceneTracer tracer(scene, ps.objects[i]);
    const Segment& s = ps.segments[i];
    const bool v = tracer.originalVisible(s), vp = tracer.proxyVisible(s);
    ++c.total;
    c.hm += (!v && vp);
    c.mh += (v && !vp);
    const bool culling = vp ? true : v;
    c.culling_wrong += (culling != v);
    c.naive_proxy_hit_but_visible += (scene.proxies().occluded(s) && v);
  }
  return c;
}

TEST(RenderScene, SelfShadowingTracesOwnOriginal) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kOutsideProxy);
  ASSERT_EQ(scene->objects().size(), 2u);
  EXPECT_EQ(scene->proxyClass(), ProxyClass::kOutside);
  EXPECT_TRUE(scene->usesProxies());
  EXPECT_TRUE(scene->warnings().empty());

  const SegmentClasses on_box = classify(*scene, 1);
  ASSERT_GT(on_box.total, 30u);  // the camera sees the box
  EXPECT_EQ(on_box.hm, 0u);      // outside proxy: no HM', including the box's own segments
  EXPECT_EQ(on_box.culling_wrong, 0u);
  // Teeth: without the rule, the box's points lie inside its own proxy, so the proxy scene
  // blocks most of their segments although the box's top and sides see the light.
  EXPECT_GT(on_box.naive_proxy_hit_but_visible, on_box.total / 2);

  const SegmentClasses all = classify(*scene, -1);
  EXPECT_EQ(all.hm, 0u);
  EXPECT_EQ(all.culling_wrong, 0u);
  EXPECT_GT(all.mh, 0u);  // ground points in the proxy's shadow but not the box's
}

// The box's outside proxy has at least as many triangles as the box: by default it cannot make
// a ray cheaper, so the renderer skips it (and says so) and the box is its own exact proxy.
TEST(RenderScene, ProxyNotSmallerThanOriginalIsSkipped) {
  ScratchDir dir;
  BoxScene b;
  b.proxies_json = test::kOutsideProxy;
  RenderSceneOptions o = test::quiet();
  o.keep_larger_proxies = false;
  const auto scene = loadRenderScene(b.write(dir), o);
  EXPECT_FALSE(scene->usesProxies());
  ASSERT_EQ(scene->warnings().size(), 1u);
  EXPECT_NE(scene->warnings()[0].find("not cheaper"), std::string::npos);
  for (const RenderObject& obj : scene->objects()) EXPECT_EQ(obj.proxy, -1);
  EXPECT_EQ(scene->proxyTriangles(), scene->originalTriangles());
}

TEST(RenderScene, SelfShadowingWithRotatedScaledInstances) {
  ScratchDir dir;
  dir.write("inst.txt",
            "box 4 0 0\n"
            "box 0 -1.2 0 -4  1.2 0 0 0  0 0 1.2 -3   # rotated 90 degrees about z, scaled\n"
            "box 0.8660254 0 0.5 0  0 1 0 0  -0.5 0 0.8660254 3\n");
  BoxScene b;
  b.proxies_json = test::kOutsideProxy;
  b.instances_file = "inst.txt";
  b.res = 32;
  const auto scene = loadRenderScene(b.write(dir), test::quiet());
  ASSERT_EQ(scene->objects().size(), 5u);  // ground, box, 3 instances
  EXPECT_EQ(scene->proxyClass(), ProxyClass::kOutside);
  uint64_t instance_segments = 0;
  for (int o = 2; o < 5; ++o) {
    const SegmentClasses c = classify(*scene, o);
    instance_segments += c.total;
    EXPECT_EQ(c.hm, 0u) << "instance " << o;
    EXPECT_EQ(c.culling_wrong, 0u) << "instance " << o;
  }
  EXPECT_GT(instance_segments, 30u);
  EXPECT_EQ(classify(*scene, -1).hm, 0u);
}

// Flattened instances trace the same geometry as Embree instances: the same shading points, the
// same V and V' for the renderer's segments, apart from the rare segment grazing an edge where
// the two float paths (pre-transformed vertices, transformed ray) round differently.
TEST(RenderScene, FlattenedInstancesTraceLikeInstances) {
  ScratchDir dir;
  dir.write("inst.txt", "box 4 0 0\nbox 0 -1.2 0 -4  1.2 0 0 0  0 0 1.2 -3\nbox -4 0 3\n");
  BoxScene b;
  b.proxies_json = test::kOutsideProxy;
  b.instances_file = "inst.txt";
  b.res = 32;
  const std::filesystem::path path = b.write(dir);
  RenderSceneOptions o = test::quiet();
  const auto instanced = loadRenderScene(path, o);
  o.instance_build = InstanceBuild::kFlat;
  const auto flat = loadRenderScene(path, o);
  EXPECT_FALSE(instanced->instancesFlattened());
  EXPECT_TRUE(flat->instancesFlattened());
  // auto: flattened when the estimated bytes of originals + proxies fit the budget, instanced
  // otherwise (the estimate is a fixed number of bytes per flattened triangle).
  RenderSceneOptions a = test::quiet();
  a.instance_build = InstanceBuild::kAuto;
  const uint64_t flat_triangles = flat->originalTriangles() + flat->proxyTriangles();
  a.memory_budget_bytes = kFlatBytesPerTriangle * double(flat_triangles);
  const auto fits = loadRenderScene(path, a);
  EXPECT_TRUE(fits->instancesFlattened());
  EXPECT_EQ(fits->buildChoice().flat_triangles, flat_triangles);
  EXPECT_STREQ(fits->buildChoice().name(), "flat");
  a.memory_budget_bytes = kFlatBytesPerTriangle * double(flat_triangles - 1);
  const auto over = loadRenderScene(path, a);
  EXPECT_FALSE(over->instancesFlattened());
  EXPECT_STREQ(over->buildChoice().name(), "instanced");
  EXPECT_NE(over->buildChoice().reason.find("over the memory budget"), std::string::npos);
  EXPECT_EQ(flat->originalTriangles(), instanced->originalTriangles());
  EXPECT_EQ(flat->proxyTriangles(), instanced->proxyTriangles());
  RenderSettings settings;
  uint64_t total = 0, differ = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const PassSegments a = passSegments(*instanced, settings, pass);
    const PassSegments f = passSegments(*flat, settings, pass);
    ASSERT_EQ(a.segments.size(), f.segments.size());
    for (size_t i = 0; i < a.segments.size(); ++i) {
      ASSERT_EQ(a.objects[i], f.objects[i]);
      const SceneTracer ta(*instanced, a.objects[i]), tf(*flat, f.objects[i]);
      ++total;
      differ += ta.originalVisible(a.segments[i]) != tf.originalVisible(f.segments[i]) ||
                ta.proxyVisible(a.segments[i]) != tf.proxyVisible(f.segments[i]);
    }
  }
  EXPECT_GT(total, 1000u);
  EXPECT_LE(differ, total / 1000);
}

TEST(RenderScene, LightInsideAnOutsideProxyDowngradesToGeneral) {
  ScratchDir dir;
  BoxScene b;
  b.proxies_json = test::kOutsideProxy;
  // A small light just above the box top, inside the proxy's box (y up to 2.3).
  b.light = R"({"type": "quad", "corner": [-0.2, 2.1, -0.2], "edge_u": [0.4, 0, 0],
      "edge_v": [0, 0, 0.4], "radiance": [6, 6, 6]})";
  const auto scene = loadRenderScene(b.write(dir), test::quiet());
  EXPECT_EQ(scene->proxyClass(), ProxyClass::kGeneral);
  ASSERT_EQ(scene->warnings().size(), 1u);
  EXPECT_NE(scene->warnings()[0].find("pitfall 2"), std::string::npos);
  // The downgrade is needed: this light produces HM' segments against the outside proxy.
  EXPECT_GT(classify(*scene, -1).hm, 0u);
}

TEST(RenderScene, ClassesUnverifiedMixedAndSelection) {
  ScratchDir dir;
  BoxScene b;
  b.proxies_json = R"([{"kind": "outside", "file": "box_out.obj"},
                       {"kind": "inside", "file": "box_in.obj", "class": "inside"}])";
  const auto path = b.write(dir);
  {
    const auto scene = loadRenderScene(path, test::quiet());  // first listed: unverified
    EXPECT_EQ(scene->proxyClass(), ProxyClass::kGeneral);
    EXPECT_EQ(scene->objects()[1].proxy, 0);
    EXPECT_EQ(scene->warnings().size(), 1u);
  }
  {
    const auto scene = loadRenderScene(path, test::quiet("inside"));
    EXPECT_EQ(scene->proxyClass(), ProxyClass::kInside);
    EXPECT_EQ(scene->objects()[1].proxy, 1);
    EXPECT_EQ(classify(*scene, -1).mh, 0u);  // inside proxy: no MH'
  }
  {
    const auto scene = loadRenderScene(path, test::quiet("", false));
    EXPECT_FALSE(scene->usesProxies());
    EXPECT_EQ(scene->proxyClass(), ProxyClass::kGeneral);
    const SegmentClasses c = classify(*scene, -1);
    EXPECT_EQ(c.hm + c.mh, 0u);  // no proxies: V' = V
  }
  {
    BoxScene m;  // two meshes with different verified classes
    m.proxies_json = test::kOutsideProxy;
    m.extra_meshes = R"(, {"name": "box2", "file": "box.obj",
        "transform": {"translate": [4, 0, 0]}, "proxies": )" +
                     std::string(test::kInsideProxy) + "}";
    const auto scene = loadRenderScene(m.write(dir), test::quiet());
    EXPECT_EQ(scene->proxyClass(), ProxyClass::kGeneral);
  }
}

TEST(RenderScene, GeneralProxyHasBothErrorKinds) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kGeneralProxy);
  EXPECT_EQ(scene->proxyClass(), ProxyClass::kGeneral);
  const SegmentClasses c = classify(*scene, -1);
  EXPECT_GT(c.hm, 0u);
  EXPECT_GT(c.mh, 0u);
}

}  // namespace
}  // namespace proxyvis
