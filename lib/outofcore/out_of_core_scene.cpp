#include "outofcore/out_of_core_scene.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/io/mesh_io.h"
#include "proxies/check/class_trust.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/page_cache.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

uint64_t fileBytes(const std::filesystem::path& file) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  if (ec) throw Error(file.string(), "cannot read the file's size", ec.message());
  return uint64_t(bytes);
}

}  // namespace

OutOfCoreScene::OutOfCoreScene(const SceneDesc& desc)
    : desc_(desc), camera_(desc_.camera), lights_(desc_.lights) {}
OutOfCoreScene::~OutOfCoreScene() = default;

uint64_t OutOfCoreScene::builtBytes() const {
  uint64_t total = 0;
  for (const OutOfCoreMesh& m : meshes_) total += m.built_bytes;
  return total;
}

uint64_t OutOfCoreScene::inCoreBytes() const {
  uint64_t scratch = 0;
  for (const OutOfCoreMesh& m : meshes_)
    scratch = std::max(scratch, m.load_peak_bytes - std::min(m.load_peak_bytes, m.built_bytes));
  return builtBytes() + scratch;
}

GeometryLoad OutOfCoreScene::loadOriginal(uint32_t mesh, bool cold) const {
  if (cold) dropFromPageCache(desc_.meshes[mesh].file);
  const Stopwatch read;
  const uint64_t file_bytes = fileBytes(desc_.meshes[mesh].file);
  const TriMesh original = loadSceneMesh(desc_.meshes[mesh]);
  GeometryLoad load = buildOriginal(mesh, original);
  load.file_bytes = file_bytes;
  load.read_seconds = read.seconds() - load.build_seconds;
  return load;
}

GeometryLoad OutOfCoreScene::buildOriginal(uint32_t mesh, const TriMesh& original) const {
  GeometryLoad load;
  const Stopwatch build;
  std::vector<const TriMesh*> geometry(desc_.meshes.size(), nullptr);
  geometry[mesh] = &original;
  std::vector<bool> include(objects_.size(), false);
  for (size_t id = 0; id < objects_.size(); ++id) include[id] = objects_[id].mesh == mesh;
  const uint64_t before = device_->bytesInUse();
  TraceSceneBuilder builder(*device_, scene_options_.trace);
  addRenderObjects(builder, objects_, geometry, build_.flat, &include);
  load.scene = builder.build();
  const uint64_t after = device_->bytesInUse();
  load.bytes = after > before ? after - before : 0;
  load.build_seconds = build.seconds();
  return load;
}

// load()'s steps, in order.
class OutOfCoreSceneLoader {
 public:
  OutOfCoreSceneLoader(const SceneDesc& desc, const OutOfCoreSceneOptions& options)
      : scene_(new OutOfCoreScene(desc)), s_(*scene_), desc_(desc), options_(options) {}

  std::unique_ptr<OutOfCoreScene> load() {
    const Stopwatch clock;
    s_.scene_options_ = options_.scene;
    s_.device_ = std::make_unique<TraceDevice>();
    chooseObjects();
    loadProxies();
    scanOriginals();
    buildProxies();
    if (options_.proxies) checkLightsOutsideProxies();
    s_.scan_seconds_ = clock.seconds();
    return std::move(scene_);
  }

 private:
  void chooseObjects() {
    assembly_ = assembleScene(desc_, options_.scene);
    s_.objects_ = assembly_.objects;
    s_.meshes_.resize(desc_.meshes.size());
    for (size_t m = 0; m < desc_.meshes.size(); ++m) {
      OutOfCoreMesh& mesh = s_.meshes_[m];
      mesh.used = assembly_.used[m];
      if (!mesh.used || !options_.proxies) continue;
      mesh.outside = proxyOfKind(desc_.meshes[m], "outside");
      if (options_.scene.proxy_kind.empty() || options_.scene.proxy_kind == "inside")
        mesh.inside = proxyOfKind(desc_.meshes[m], "inside");
      if (options_.scene.proxy_kind == "inside") mesh.outside = -1;
    }
  }

  // The proxies some step needs: the one the single-process renderer would trace (its triangles
  // decide the build), the outside and inside ones the proxy policies rely on, proved.
  void loadProxies() {
    proxies_.resize(desc_.meshes.size());
    for (size_t m = 0; m < desc_.meshes.size(); ++m) {
      const OutOfCoreMesh& om = s_.meshes_[m];
      if (!om.used) continue;
      const SceneMeshDesc& mesh = desc_.meshes[m];
      for (size_t i = 0; i < mesh.proxies.size(); ++i) {
        const int p = int(i);
        const bool needed = p == assembly_.proxy[m] || p == om.outside || p == om.inside;
        proxies_[m].push_back(needed ? loadMesh(mesh.proxies[i].file) : TriMesh{});
      }
      const std::string relies = "the out-of-core renderer skips loads by it";
      if (om.outside >= 0)
        requireProvedClass(mesh, mesh.proxies[size_t(om.outside)], ProxyClass::kOutside, relies);
      if (om.inside >= 0)
        requireProvedClass(mesh, mesh.proxies[size_t(om.inside)], ProxyClass::kInside, relies);
    }
  }

  // Every original once: its triangles and bounds, then (once the build is decided) its built
  // bytes and scene bounds. A scene without instances is flat whatever the triangles, so each
  // original is read once and built from that reading; with instances the decision needs every
  // mesh's triangles first, and each original is read twice.
  void scanOriginals() {
    const size_t n = desc_.meshes.size();
    std::vector<uint64_t> original_triangles(n, 0), proxy_triangles(n, 0);
    bool has_instances = false;
    for (const RenderObject& o : s_.objects_) has_instances |= o.instance >= 0;
    mesh_bounds_.resize(n);
    auto measure = [&](size_t m, const TriMesh& original) {
      s_.meshes_[m].triangles = original_triangles[m] = original.numTriangles();
      s_.meshes_[m].file_bytes = fileBytes(desc_.meshes[m].file);
      mesh_bounds_[m] = original.bounds();
      const ProxyChoice choice =
          chooseProxy(desc_.meshes[m], options_.scene, original_triangles[m],
                      [&](size_t proxy) { return uint64_t(proxies_[m][proxy].numTriangles()); });
      assembly_.setProxy(m, choice.proxy);
      if (choice.proxy >= 0) proxy_triangles[m] = proxies_[m][size_t(choice.proxy)].numTriangles();
    };
    if (has_instances) {
      for (size_t m = 0; m < n; ++m)
        if (s_.meshes_[m].used) measure(m, loadSceneMesh(desc_.meshes[m]));
    }
    s_.build_ = has_instances ? chooseSceneBuild(assembly_, desc_, options_.scene,
                                                 original_triangles, proxy_triangles)
                              : chooseBuild(options_.scene.instance_build, false, 0, 0);
    Bounds3f all;
    for (size_t m = 0; m < n; ++m) {
      if (!s_.meshes_[m].used) continue;
      GeometryLoad load;
      if (has_instances) {
        load = s_.loadOriginal(uint32_t(m));
      } else {
        const TriMesh original = loadSceneMesh(desc_.meshes[m]);
        measure(m, original);
        load = s_.buildOriginal(uint32_t(m), original);
      }
      s_.meshes_[m].built_bytes = load.bytes;
      s_.meshes_[m].load_peak_bytes = uint64_t(std::ceil(kLoadPeakOverBuilt * double(load.bytes)));
      all.extend(load.scene->bounds());
    }
    // With each mesh's proxy settled (the objects' proxy fields follow it).
    s_.objects_ = assembly_.objects;
    if (!has_instances) {
      // The build description with the real triangle count, as the in-core renderer reports it.
      uint64_t flat = 0;
      for (const RenderObject& o : s_.objects_) flat += original_triangles[o.mesh];
      s_.build_ = chooseBuild(options_.scene.instance_build, false, flat, 0);
    }
    // The single-process epsilon: from the bounds of all originals.
    s_.epsilon_ = rayEpsilon(all);
    std::vector<LabelledBox> boxes;
    for (uint32_t id = 0; id < s_.objects_.size(); ++id) {
      const RenderObject& o = s_.objects_[id];
      boxes.push_back({transformedBounds(mesh_bounds_[o.mesh], o.to_world), o.mesh, id});
    }
    s_.boxes_ = std::make_unique<BoxIndex>(*s_.device_, std::move(boxes), s_.epsilon_);
  }

  void buildProxies() {
    if (!options_.proxies) return;
    const size_t n = desc_.meshes.size();
    std::vector<const TriMesh*> outside(n, nullptr), inside(n, nullptr);
    bool any_outside = false, any_inside = false;
    for (size_t m = 0; m < n; ++m) {
      const OutOfCoreMesh& om = s_.meshes_[m];
      if (om.outside >= 0) outside[m] = &proxies_[m][size_t(om.outside)], any_outside = true;
      if (om.inside >= 0) inside[m] = &proxies_[m][size_t(om.inside)], any_inside = true;
    }
    const uint64_t before = s_.device_->bytesInUse();
    // Robust (watertight) tracing: a segment that crosses an outside proxy must never slip
    // through between two of its triangles, or its object would not be loaded.
    TraceSceneOptions robust = options_.scene.trace;
    robust.robust = true;
    if (any_outside) {
      TraceSceneBuilder builder(*s_.device_, robust);
      addRenderObjects(builder, s_.objects_, outside, s_.build_.flat);
      s_.outside_ = builder.build();
    }
    if (any_inside) {
      TraceSceneBuilder builder(*s_.device_, options_.scene.trace);
      addRenderObjects(builder, s_.objects_, inside, s_.build_.flat);
      s_.inside_ = builder.build();
    }
    s_.proxy_bytes_ = s_.device_->bytesInUse() - before;
  }

  // Pitfall 2 of docs/design.md: an outside proxy decides rays only for lights outside it (its
  // world box, which holds the original, is checked); an inside one for lights outside the
  // original.
  void checkLightsOutsideProxies() {
    for (size_t l = 0; l < desc_.lights.size(); ++l) {
      const Bounds3f lb = desc_.lights[l].bounds();
      for (const RenderObject& o : s_.objects_) {
        const OutOfCoreMesh& om = s_.meshes_[o.mesh];
        if (om.outside < 0 && om.inside < 0) continue;
        const Bounds3f guard =
            om.outside >= 0 ? proxies_[o.mesh][size_t(om.outside)].bounds() : mesh_bounds_[o.mesh];
        if (transformedBounds(guard, o.to_world).overlaps(lb))
          throw Error(desc_.path.string(),
                      fmt::format("light {} may lie inside the bounds of mesh '{}' or its proxy", l,
                                  desc_.meshes[o.mesh].name),
                      "a proxy decides rays only for lights outside it (docs/design.md, "
                      "pitfall 2)",
                      "move the light, or render with --ooc-policy exact-batched");
      }
    }
  }

  std::unique_ptr<OutOfCoreScene> scene_;
  OutOfCoreScene& s_;
  const SceneDesc& desc_;
  const OutOfCoreSceneOptions& options_;
  SceneAssembly assembly_;
  std::vector<std::vector<TriMesh>> proxies_;
  std::vector<Bounds3f> mesh_bounds_;
};

std::unique_ptr<OutOfCoreScene> OutOfCoreScene::load(const SceneDesc& desc,
                                                     const OutOfCoreSceneOptions& options) {
  return OutOfCoreSceneLoader(desc, options).load();
}

}  // namespace proxyvis
