// The bundled ecosys scene as a whole: it loads with every prototype and placement, its expanded
// triangle count and bounds match what the test computes itself from the instance file and the
// meshes; the self-shadowing rule holds with real plant instances and a box proxy per prototype
// in both the instanced and the flattened build; a small render is the same at 1 and 2 threads.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "mesh/io/mesh_io.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/scene_tracer.h"
#include "render_test_util.h"

namespace proxyvis {
namespace {

using test::ScratchDir;

const std::filesystem::path kEcosys = std::filesystem::path(PROXYVIS_SCENES_DIR) / "ecosys.json";

struct Placement {
  std::string name;
  Vec3f t;  // every ecosys matrix is a pure translation (data/ecosys/instances.txt says so)
};

// The instance file read here on its own: "NAME m00 .. m33" per line, '#' comments.
std::vector<Placement> readPlacements(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<Placement> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Placement p;
    double m[16];
    fields >> p.name;
    for (double& x : m) fields >> x;
    EXPECT_TRUE(bool(fields)) << line;
    EXPECT_EQ(m[0], 1);
    EXPECT_EQ(m[5], 1);
    EXPECT_EQ(m[10], 1);
    p.t = Vec3f(float(m[3]), float(m[7]), float(m[11]));
    out.push_back(p);
  }
  return out;
}

TEST(EcosysScene, LoadsEveryPrototypeAndInstanceWithTheExpandedTriangleCount) {
  const SceneDesc desc = loadSceneDesc(kEcosys);
  ASSERT_EQ(desc.meshes.size(), 45u);  // the terrain and 44 plant prototypes
  EXPECT_EQ(desc.meshes[0].name, "terrain");
  EXPECT_TRUE(desc.meshes[0].place);
  for (size_t m = 1; m < desc.meshes.size(); ++m) EXPECT_FALSE(desc.meshes[m].place);
  ASSERT_EQ(desc.instances.size(), 4685u);
  EXPECT_EQ(desc.lights.size(), 2u);

  const std::vector<Placement> placements = readPlacements(desc.instances_file);
  ASSERT_EQ(placements.size(), 4685u);
  std::map<std::string, TriMesh> meshes;
  for (const SceneMeshDesc& m : desc.meshes) meshes[m.name] = loadMesh(m.file);
  uint64_t expanded = meshes["terrain"].numTriangles();
  Bounds3f bounds = meshes["terrain"].bounds();
  for (const Placement& p : placements) {
    ASSERT_TRUE(meshes.count(p.name)) << p.name;
    const TriMesh& mesh = meshes[p.name];
    expanded += mesh.numTriangles();
    const Bounds3f b = mesh.bounds();
    bounds.extend(b.lo + p.t);
    bounds.extend(b.hi + p.t);
  }
  const uint64_t plants = expanded - meshes["terrain"].numTriangles();
  EXPECT_GT(plants, 12'150'000u);  // the plants' "12.2 M triangles expanded"
  EXPECT_LT(plants, 12'250'000u);

  const auto scene = loadRenderScene(desc, test::quiet());
  EXPECT_FALSE(scene->instancesFlattened());
  EXPECT_EQ(scene->originalTriangles(), expanded);
  EXPECT_EQ(scene->objects().size(), 4686u);
  const Bounds3f got = scene->originals().bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(got.lo[a], bounds.lo[a], 1e-4f) << "axis " << a;
    EXPECT_NEAR(got.hi[a], bounds.hi[a], 1e-4f) << "axis " << a;
  }
  EXPECT_NEAR(got.hi.x - got.lo.x, 100.0f, 1e-3f);  // the 100 x 100 terrain
}

// Slab test: does the segment org + t*dir, t in [0, 1], pass through box b grown by `grow`?
bool crossesBox(const Vec3f& org, const Vec3f& dir, const Bounds3f& b, float grow) {
  float t0 = 0, t1 = 1;
  for (int a = 0; a < 3; ++a) {
    const float lo = b.lo[a] - grow, hi = b.hi[a] + grow;
    if (dir[a] == 0) {
      if (org[a] < lo || org[a] > hi) return false;
      continue;
    }
    float ta = (lo - org[a]) / dir[a], tb = (hi - org[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

// ecosys restricted to the instances in a 5 x 5 patch of the dense middle, every prototype with
// a box proxy (its bounding box, written to `dir`): real plants, a build small enough to flatten.
SceneDesc patchWithBoxProxies(const ScratchDir& dir) {
  SceneDesc desc = loadSceneDesc(kEcosys);
  std::vector<SceneInstanceDesc> kept;
  for (const SceneInstanceDesc& inst : desc.instances) {
    const Vec3f t(inst.transform.m[0][3], inst.transform.m[1][3], inst.transform.m[2][3]);
    if (t.x >= 30 && t.x < 35 && t.y >= 10 && t.y < 15) kept.push_back(inst);
  }
  desc.instances = kept;
  for (size_t m = 1; m < desc.meshes.size(); ++m) {
    const Bounds3f b = loadMesh(desc.meshes[m].file).bounds();
    const std::string file = desc.meshes[m].name + ".box.obj";
    dir.write(file, test::boxObj(b.lo, b.hi));
    ProxyRef ref;
    ref.kind = "outside";
    ref.method = "box";
    ref.file = dir.path() / file;
    desc.meshes[m].proxies = {ref};
  }
  return desc;
}

TEST(EcosysScene, SelfShadowingIgnoresOnlyTheOwnProxyInBothBuilds) {
  ScratchDir dir;
  const SceneDesc desc = patchWithBoxProxies(dir);
  ASSERT_GT(desc.instances.size(), 50u);
  for (const InstanceBuild build : {InstanceBuild::kInstanced, InstanceBuild::kFlat}) {
    RenderSceneOptions o = test::quiet();
    o.instance_build = build;
    const auto scene = loadRenderScene(desc, o);
    ASSERT_EQ(scene->instancesFlattened(), build == InstanceBuild::kFlat);
    ASSERT_TRUE(scene->usesProxies());
    // World boxes of every instance's proxy (object ids: 0 = terrain, 1 + k = instance k).
    const auto& objects = scene->objects();
    std::vector<Bounds3f> boxes(objects.size());
    std::vector<Vec3f> top(objects.size());  // highest vertex of the plant: a point on it
    std::map<uint32_t, TriMesh> meshes;
    for (uint32_t id = 1; id < objects.size(); ++id) {
      const RenderObject& obj = objects[id];
      if (!meshes.count(obj.mesh)) meshes[obj.mesh] = loadMesh(desc.meshes[obj.mesh].file);
      const TriMesh& mesh = meshes[obj.mesh];
      const Bounds3f b = mesh.bounds();
      boxes[id] = Bounds3f();
      boxes[id].extend(obj.to_world.apply(b.lo));
      boxes[id].extend(obj.to_world.apply(b.hi));
      Vec3f best = mesh.vertices[0];
      for (const Vec3f& v : mesh.vertices)
        if (v.z > best.z) best = v;
      top[id] = obj.to_world.apply(best);
    }
    uint64_t clear = 0, through_other = 0, checked_up = 0;
    for (uint32_t i = 1; i < objects.size(); ++i) {
      // Straight up from the plant's top: blocked by the proxies exactly when it passes through
      // another instance's box (its own box is ignored; the terrain lies below).
      Segment up;
      up.org = top[i];
      up.dir = Vec3f(0, 0, 20);
      up.tnear = 0;
      up.tfar = 1;
      bool near_other = false, in_other = false;
      for (uint32_t j = 1; j < objects.size(); ++j) {
        if (j == i) continue;
        in_other |= crossesBox(up.org, up.dir, boxes[j], -1e-3f);
        near_other |= crossesBox(up.org, up.dir, boxes[j], 1e-3f);
      }
      if (in_other == near_other) {  // not grazing a box face: the answer is certain
        ++checked_up;
        EXPECT_EQ(scene->proxies().occluded(up, i), in_other) << "instance " << i;
        clear += !in_other;
      }
      // Without the ignore, its own box blocks a segment from inside it: the ignore is what
      // lets the segments above through.
      Segment out = up;
      out.org = (boxes[i].lo + boxes[i].hi) * 0.5f;
      EXPECT_TRUE(scene->proxies().occluded(out)) << "instance " << i;
      // Towards the middle of the next instance's box: blocked by that box, with the rule.
      const uint32_t j = i + 1 < objects.size() ? i + 1 : 1;
      Segment across;
      across.org = top[i];
      across.dir = (boxes[j].lo + boxes[j].hi) * 0.5f - top[i];
      across.tnear = 0;
      across.tfar = 1;
      const SceneTracer tracer(*scene, i);
      EXPECT_TRUE(scene->proxies().occluded(across, i)) << i << " -> " << j;
      EXPECT_FALSE(tracer.proxyVisible(across)) << i << " -> " << j;
      ++through_other;
    }
    EXPECT_GT(clear, 10u);  // the check above had segments of both kinds
    EXPECT_GT(checked_up - clear, 0u);
    EXPECT_GT(through_other, 50u);
  }
}

// The framing its description promises: no primary ray misses (a miss is a black, wasted pixel)
// and most pixels see plants (58 % at the scene's 160 x 90).
TEST(EcosysScene, CameraSeesNoSkyAndMostlyPlants) {
  const auto scene = loadRenderScene(kEcosys, test::quiet());
  const Camera& camera = scene->camera();
  uint64_t misses = 0, plants = 0, total = 0;
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      Segment ray;
      ray.org = camera.eye();
      ray.dir = normalize(camera.direction(float(x) + 0.5f, float(y) + 0.5f));
      ray.tnear = 0;
      ray.tfar = std::numeric_limits<float>::infinity();
      const Hit hit = scene->originals().intersect(ray);
      ++total;
      misses += !hit.hit;
      plants += hit.hit && scene->objects()[hit.user_id].instance >= 0;
    }
  EXPECT_EQ(misses, 0u);
  EXPECT_GT(double(plants) / double(total), 0.5) << plants << " of " << total;
}

TEST(EcosysScene, SmallRenderIsTheSameAtOneAndTwoThreads) {
  SceneDesc desc = loadSceneDesc(kEcosys);
  desc.camera.width = 48;
  desc.camera.height = 27;
  const auto scene = loadRenderScene(desc, test::quiet());
  RenderSettings settings;
  settings.spp = 4;
  settings.seed = 3;
  settings.tile_size = 7;
  settings.quiet = true;
  test::ExactTestEstimator exact;
  auto renderIn = [&](int threads) {
    tbb::task_arena arena(threads);
    RenderResult r;
    arena.execute([&] { r = render(*scene, settings, exact); });
    return r;
  };
  const RenderResult one = renderIn(1), two = renderIn(2);
  EXPECT_EQ(one.radiance.pixels, two.radiance.pixels);
  EXPECT_EQ(one.visibility.pixels, two.visibility.pixels);
  // Teeth: the image is not black, some samples are shadowed and some pixels see plants.
  double sum = 0;
  for (float v : one.radiance.pixels) sum += v;
  EXPECT_GT(sum, 0);
  double vis = 0;
  for (float v : one.visibility.pixels) vis += v;
  EXPECT_GT(vis, 0);
  EXPECT_LT(vis, double(one.visibility.pixels.size()));
}

}  // namespace
}  // namespace proxyvis
