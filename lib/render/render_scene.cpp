// Building the renderer's Embree scenes from a scene description (see render_scene.h).
#include "render/render_scene.h"

#include <fmt/core.h>

#include <cstdio>

#include "mesh/io/mesh_io.h"
#include "render/scene_assembly.h"
#include "scene/transform.h"
#include "util/error.h"

namespace proxyvis {

namespace {

// Shadow-ray offset as a fraction of the originals' bounding-box diagonal: above float rounding
// of hit points on every bundled scene (about 1e-7 of the diagonal), below the thinnest gap
// between distinct surfaces; never below kMinRayEpsilon in absolute units.
constexpr float kRayEpsilonOfDiagonal = 2e-5f;
constexpr float kMinRayEpsilon = 1e-6f;

// The class the estimators may rely on, after the light checks of docs/design.md, pitfall 2.
struct ProxyClassDecision {
  bool uses_proxies = false;
  std::optional<ProxyClass> proxy_class;  // when every proxy in use has this class
  std::vector<std::string> warnings;
};

ProxyClassDecision decideProxyClass(const SceneDesc& desc, const std::vector<RenderObject>& objects,
                                    const std::vector<TriMesh>& originals,
                                    const std::vector<TriMesh>& proxies) {
  const size_t num_meshes = desc.meshes.size();
  ProxyClassDecision d;
  std::vector<Bounds3f> light_bounds;
  for (const AreaLightDesc& l : desc.lights) light_bounds.push_back(l.bounds());
  std::optional<ProxyClass> common;
  bool mixed = false;
  std::vector<bool> warned(num_meshes, false);
  for (const RenderObject& o : objects) {
    if (o.proxy < 0) continue;
    d.uses_proxies = true;
    const SceneMeshDesc& mesh = desc.meshes[o.mesh];
    const ProxyRef& ref = mesh.proxies[size_t(o.proxy)];
    ProxyClass c = ref.verified_class.value_or(ProxyClass::kGeneral);
    if (!ref.verified_class && !warned[o.mesh]) {
      d.warnings.push_back(
          fmt::format("mesh '{}': proxy {} has no verified class; treated as general", mesh.name,
                      ref.file.filename().string()));
    }
    if (c != ProxyClass::kGeneral) {
      // Outside: the light must be outside the proxy. Inside: outside the original.
      const TriMesh& guard = c == ProxyClass::kOutside ? proxies[o.mesh] : originals[o.mesh];
      const Bounds3f world = transformedBounds(guard.bounds(), o.to_world);
      for (size_t l = 0; l < light_bounds.size(); ++l) {
        if (!world.overlaps(light_bounds[l])) continue;
        if (!warned[o.mesh])
          d.warnings.push_back(fmt::format(
              "mesh '{}': light {} may reach inside the bounds of its {} {}; the {} guarantee "
              "needs the light outside (docs/design.md, pitfall 2): treated as general",
              mesh.name, l, c == ProxyClass::kOutside ? "proxy" : "original",
              ref.file.filename().string(), proxyClassName(c)));
        c = ProxyClass::kGeneral;
        break;
      }
    }
    warned[o.mesh] = true;
    if (common && *common != c) mixed = true;
    common = c;
  }
  if (common && !mixed) d.proxy_class = *common;
  if (mixed)
    d.warnings.push_back(
        "meshes use proxies of different classes: the estimators treat them as general");
  return d;
}

}  // namespace

std::vector<RenderObject> renderObjects(const SceneDesc& desc, const std::vector<int>& chosen) {
  std::vector<RenderObject> objects;
  auto add = [&](uint32_t mesh, int32_t instance, const Affine3f& t) {
    RenderObject o;
    o.mesh = mesh;
    o.instance = instance;
    o.to_world = t;
    const auto inv = inverse(t);
    if (!inv)
      throw Error(desc.path.string(),
                  "singular transform for mesh '" + desc.meshes[mesh].name + "'");
    o.to_object = *inv;
    o.proxy = chosen[mesh];
    objects.push_back(o);
  };
  for (uint32_t m = 0; m < desc.meshes.size(); ++m)
    if (desc.meshes[m].place) add(m, -1, desc.meshes[m].transform);
  for (size_t i = 0; i < desc.instances.size(); ++i)
    add(desc.instances[i].mesh, int32_t(i), desc.instances[i].transform);
  if (objects.empty())
    throw Error(desc.path.string(), "nothing to render",
                "no mesh is placed and there are no instances");
  return objects;
}

void addRenderObjects(TraceSceneBuilder& builder, const std::vector<RenderObject>& objects,
                      const std::vector<const TriMesh*>& geometry, bool flatten,
                      const std::vector<bool>* include) {
  std::vector<int64_t> prototype(geometry.size(), -1);
  for (uint32_t id = 0; id < objects.size(); ++id) {
    if (include && !(*include)[id]) continue;
    const RenderObject& o = objects[id];
    if (!geometry[o.mesh]) continue;
    const TriMesh& mesh = *geometry[o.mesh];
    if (o.instance < 0 || flatten) {
      builder.addMesh(mesh, o.to_world, id);
    } else {
      if (prototype[o.mesh] < 0) prototype[o.mesh] = builder.addPrototype(mesh);
      builder.addInstance(uint32_t(prototype[o.mesh]), o.to_world, id);
    }
  }
}

float rayEpsilon(const Bounds3f& originals_bounds) {
  return std::max(kMinRayEpsilon, kRayEpsilonOfDiagonal * originals_bounds.diagonal());
}

RenderScene::RenderScene(SceneDesc desc)
    : desc_(std::move(desc)), camera_(desc_.camera), lights_(desc_.lights) {}

RenderScene::~RenderScene() = default;

uint64_t RenderScene::originalTriangles() const {
  return originals_->triangleCount();
}
uint64_t RenderScene::proxyTriangles() const {
  return proxies_->triangleCount();
}

std::unique_ptr<RenderScene> loadRenderScene(const std::filesystem::path& scene_file,
                                             const RenderSceneOptions& options) {
  return loadRenderScene(loadSceneDesc(scene_file), options);
}

std::unique_ptr<RenderScene> loadRenderScene(const SceneDesc& desc,
                                             const RenderSceneOptions& options) {
  std::unique_ptr<RenderScene> scene(new RenderScene(desc));
  const size_t num_meshes = desc.meshes.size();

  SceneAssembly assembly = assembleScene(desc, options);

  // Meshes and proxies, loaded once each.
  std::vector<TriMesh> originals(num_meshes), proxies(num_meshes);
  std::vector<const TriMesh*> original_ptrs(num_meshes), proxy_ptrs(num_meshes);
  std::vector<uint64_t> original_triangles(num_meshes, 0), proxy_triangles(num_meshes, 0);
  for (size_t m = 0; m < num_meshes; ++m) {
    if (!assembly.used[m]) continue;
    originals[m] = loadSceneMesh(desc.meshes[m]);
    original_ptrs[m] = &originals[m];
    original_triangles[m] = originals[m].numTriangles();
    const ProxyChoice choice =
        chooseProxy(desc.meshes[m], options, original_triangles[m], [&](size_t proxy) {
          proxies[m] = loadMesh(desc.meshes[m].proxies[proxy].file);
          return uint64_t(proxies[m].numTriangles());
        });
    assembly.setProxy(m, choice.proxy);
    if (!choice.dropped.empty()) scene->warnings_.push_back(choice.dropped);
    if (choice.proxy < 0) proxies[m] = TriMesh{};  // a dropped proxy's memory back at once
    proxy_ptrs[m] = choice.proxy >= 0 ? &proxies[m] : &originals[m];
    proxy_triangles[m] = proxy_ptrs[m]->numTriangles();
  }
  scene->build_ = chooseSceneBuild(assembly, desc, options, original_triangles, proxy_triangles);
  const bool any_proxy = assembly.anyProxy();
  scene->objects_ = std::move(assembly.objects);
  const std::vector<RenderObject>& objects = scene->objects_;
  const std::vector<int>& chosen = assembly.proxy;
  const std::vector<bool>& used = assembly.used;

  scene->device_ = std::make_unique<TraceDevice>();
  TraceSceneBuilder builder(*scene->device_, options.trace);
  const bool flatten = scene->build_.flat;
  addRenderObjects(builder, objects, original_ptrs, flatten);
  scene->originals_ = builder.build();
  if (any_proxy) {
    addRenderObjects(builder, objects, proxy_ptrs, flatten);
    scene->own_proxies_ = builder.build();
    scene->proxies_ = scene->own_proxies_.get();
  } else {
    scene->proxies_ = scene->originals_.get();
  }
  scene->self_.resize(num_meshes);
  for (size_t m = 0; m < num_meshes; ++m) {
    if (!used[m] || chosen[m] < 0) continue;
    builder.addMesh(originals[m], 0);
    scene->self_[m] = builder.build();
  }
  scene->epsilon_ = rayEpsilon(scene->originals_->bounds());

  ProxyClassDecision decision = decideProxyClass(desc, objects, originals, proxies);
  scene->uses_proxies_ = decision.uses_proxies;
  if (decision.proxy_class) scene->proxy_class_ = *decision.proxy_class;
  for (std::string& w : decision.warnings) scene->warnings_.push_back(std::move(w));
  if (!options.quiet)
    for (const std::string& w : scene->warnings_)
      std::fprintf(stderr, "%s: warning: %s\n", desc.path.filename().string().c_str(), w.c_str());
  return scene;
}

}  // namespace proxyvis
