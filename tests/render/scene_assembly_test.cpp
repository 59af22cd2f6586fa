// The scene assembly both renderers share (render/scene_assembly.h): which proxy a mesh is traced
// with (its kind, and the rule that drops a proxy not cheaper than its original), the objects,
// and the triangles the build decision counts. No file is read: the scenes are descriptions only.
#include "render/scene_assembly.h"

#include <gtest/gtest.h>

#include <string>

namespace proxyvis {
namespace {

ProxyRef proxy(const std::string& kind, const std::string& file) {
  ProxyRef p;
  p.kind = kind;
  p.file = "/scene/" + file;
  return p;
}

SceneMeshDesc mesh(const std::string& name, std::vector<ProxyRef> proxies, bool place = true) {
  SceneMeshDesc m;
  m.name = name;
  m.file = "/scene/" + name + ".obj";
  m.place = place;
  m.proxies = std::move(proxies);
  return m;
}

RenderSceneOptions kind(const std::string& k) {
  RenderSceneOptions o;
  o.proxy_kind = k;
  return o;
}

// A triangle count that must not be asked for.
uint64_t notAsked(size_t) {
  ADD_FAILURE() << "the proxy's triangles were asked for";
  return 0;
}

TEST(SceneAssembly, RequestedProxyFollowsTheKind) {
  const SceneMeshDesc m =
      mesh("dragon", {proxy("outside", "d.outside.ply"), proxy("inside", "d.inside.ply")});
  EXPECT_EQ(requestedProxy(m, {}), 0);  // no kind: the first listed
  EXPECT_EQ(requestedProxy(m, kind("outside")), 0);
  EXPECT_EQ(requestedProxy(m, kind("inside")), 1);
  EXPECT_EQ(requestedProxy(m, kind("general")), -1);
  RenderSceneOptions none;
  none.use_proxies = false;
  EXPECT_EQ(requestedProxy(m, none), -1);
  EXPECT_EQ(requestedProxy(mesh("ground", {}), {}), -1);
}

TEST(SceneAssembly, ChooseProxyKeepsACheaperProxy) {
  const SceneMeshDesc m =
      mesh("dragon", {proxy("outside", "d.outside.ply"), proxy("inside", "d.inside.ply")});
  size_t asked = 99;
  const ProxyChoice c = chooseProxy(m, kind("inside"), 1000, [&](size_t p) {
    asked = p;
    return uint64_t(999);
  });
  EXPECT_EQ(asked, 1u);  // the requested proxy's count, nobody else's
  EXPECT_EQ(c.proxy, 1);
  EXPECT_TRUE(c.dropped.empty());
}

TEST(SceneAssembly, ChooseProxyDropsAProxyNotCheaper) {
  const SceneMeshDesc m = mesh("box", {proxy("outside", "box.outside.ply")});
  for (uint64_t proxy_triangles : {uint64_t(12), uint64_t(40)}) {
    const ProxyChoice c = chooseProxy(m, {}, 12, [&](size_t) { return proxy_triangles; });
    EXPECT_EQ(c.proxy, -1) << proxy_triangles;
    EXPECT_NE(c.dropped.find("mesh 'box'"), std::string::npos) << c.dropped;
    EXPECT_NE(c.dropped.find("box.outside.ply"), std::string::npos) << c.dropped;
    EXPECT_NE(c.dropped.find("not cheaper"), std::string::npos) << c.dropped;
  }
  RenderSceneOptions keep;
  keep.keep_larger_proxies = true;
  const ProxyChoice kept = chooseProxy(m, keep, 12, [](size_t) { return uint64_t(40); });
  EXPECT_EQ(kept.proxy, 0);
  EXPECT_TRUE(kept.dropped.empty());
}

TEST(SceneAssembly, ChooseProxyAsksNothingWithoutARequest) {
  const SceneMeshDesc m = mesh("dragon", {proxy("outside", "d.outside.ply")});
  EXPECT_EQ(chooseProxy(m, kind("inside"), 1000, notAsked).proxy, -1);
  EXPECT_EQ(chooseProxy(mesh("ground", {}), {}, 2, notAsked).proxy, -1);
}

// Two placed meshes and a prototype placed twice by instances; the fourth mesh is not used.
SceneDesc fourMeshScene() {
  SceneDesc d;
  d.path = "/scene/scene.json";
  d.meshes.push_back(mesh("ground", {}));
  d.meshes.push_back(
      mesh("dragon", {proxy("outside", "d.outside.ply"), proxy("inside", "d.inside.ply")}));
  d.meshes.push_back(mesh("tree", {proxy("outside", "t.outside.ply")}, false));
  d.meshes.push_back(mesh("unused", {proxy("outside", "u.outside.ply")}, false));
  d.instances.push_back({2, Affine3f::translation({1, 0, 0})});
  d.instances.push_back({2, Affine3f::translation({2, 0, 0})});
  return d;
}

TEST(SceneAssembly, ObjectsCarryTheirMeshProxy) {
  const SceneDesc d = fourMeshScene();
  SceneAssembly a = assembleScene(d, kind("outside"));
  ASSERT_EQ(a.objects.size(), 4u);  // ground, dragon, two trees
  EXPECT_EQ(a.proxy, (std::vector<int>{-1, 0, 0, 0}));
  EXPECT_EQ(a.used, (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(a.objects[2].instance, 0);
  EXPECT_EQ(a.objects[3].mesh, 2u);
  EXPECT_EQ(a.objects[3].proxy, 0);
  EXPECT_TRUE(a.anyProxy());
  a.setProxy(2, -1);  // the trees' proxy was not cheaper
  EXPECT_EQ(a.objects[2].proxy, -1);
  EXPECT_EQ(a.objects[3].proxy, -1);
  EXPECT_EQ(a.objects[1].proxy, 0);
  a.setProxy(1, -1);
  EXPECT_FALSE(a.anyProxy());

  const SceneAssembly inside = assembleScene(d, kind("inside"));
  EXPECT_EQ(inside.proxy, (std::vector<int>{-1, 1, -1, -1}));
}

TEST(SceneAssembly, BuildCountsOriginalsAndTheProxiesInUse) {
  const SceneDesc d = fourMeshScene();
  RenderSceneOptions o = kind("outside");
  o.instance_build = InstanceBuild::kFlat;
  const std::vector<uint64_t> originals = {2, 1000, 500, 7};
  const std::vector<uint64_t> proxies = {0, 100, 50, 3};
  SceneAssembly a = assembleScene(d, o);
  BuildChoice b = chooseSceneBuild(a, d, o, originals, proxies);
  EXPECT_TRUE(b.flat);
  EXPECT_TRUE(b.has_instances);
  // Originals 2 + 1000 + 2 x 500; the proxies' scene holds the ground's original, the dragon's
  // and the trees' proxies.
  EXPECT_EQ(b.flat_triangles, 2002u + 2u + 100u + 2u * 50u);
  a.setProxy(2, -1);
  b = chooseSceneBuild(a, d, o, originals, proxies);
  EXPECT_EQ(b.flat_triangles, 2002u + 2u + 100u + 2u * 500u);
  a.setProxy(1, -1);  // no proxy anywhere: the proxies' scene is the originals' own
  b = chooseSceneBuild(a, d, o, originals, proxies);
  EXPECT_EQ(b.flat_triangles, 2002u);
}

}  // namespace
}  // namespace proxyvis
