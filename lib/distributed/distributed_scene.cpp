// Loading one rank's share of a data-parallel scene (contract in distributed_scene.h). The steps
// that read files run under MpiComm::collectively(), so that a rank that cannot read its share
// ends the job with one message naming it, before any rendering starts.
#include "distributed/distributed_scene.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

#include "distributed/domain_partition.h"
#include "mesh/io/mesh_io.h"
#include "proxies/check/class_trust.h"
#include "render/scene_assembly.h"
#include "scene/transform.h"
#include "util/error.h"

namespace proxyvis {

namespace {

// The proxy kinds forwarding may rely on under --proxy-kind (DistributedSceneOptions::scene).
void checkForwardingKind(const std::string& kind, bool proxies) {
  if (kind.empty()) return;
  if (!proxies)
    throw Error("", "--proxy-kind " + kind + " does not act without --forwarding proxies",
                "the box policies decide no ray by a proxy",
                "add --forwarding proxies, or leave --proxy-kind out");
  if (kind != "outside")
    throw Error("", "--proxy-kind " + kind + " is not available with --data-parallel",
                "forwarding asks the owners of the outside proxies a ray crosses; inside proxies "
                "only add to them, and a general one proves nothing",
                "use --proxy-kind outside (outside proxies alone), or leave it out (outside and "
                "inside)");
}

}  // namespace

const char* forwardingName(Forwarding f) {
  switch (f) {
    case Forwarding::kDomainBounds:
      return "domain-bounds";
    case Forwarding::kInstanceBoxes:
      return "instance-boxes";
    case Forwarding::kProxies:
      return "proxies";
  }
  return "?";
}

Forwarding parseForwarding(const std::string& name) {
  for (Forwarding f : {Forwarding::kDomainBounds, Forwarding::kInstanceBoxes, Forwarding::kProxies})
    if (name == forwardingName(f)) return f;
  throw Error("", "--forwarding: unknown policy '" + name + "'", {},
              "use domain-bounds, instance-boxes or proxies");
}

DistributedScene::DistributedScene(const SceneDesc& desc)
    : desc_(desc), camera_(desc_.camera), lights_(desc_.lights) {}
DistributedScene::~DistributedScene() = default;

// load()'s steps, in order; the collective ones run under MpiComm::collectively().
class DistributedSceneLoader {
 public:
  DistributedSceneLoader(const SceneDesc& desc, const DistributedSceneOptions& options,
                         const MpiComm& comm)
      : scene_(new DistributedScene(desc)),
        ds_(*scene_),
        desc_(desc),
        options_(options),
        comm_(comm),
        num_meshes_(desc.meshes.size()) {
    ds_.rank_ = comm.rank();
    ds_.ranks_ = comm.size();
  }

  std::unique_ptr<DistributedScene> load() {
    chooseObjects();
    loadProxies();
    assignOwners();
    loadOriginals();
    decideBuild();
    buildTraceScenes();
    measureEpsilon();
    indexBoxes();
    if (options_.proxies) checkLightsOutsideProxies();
    countFacts();
    return std::move(scene_);
  }

 private:
  // Objects in the single-process renderer's order, with the proxy it would request under the
  // same options (narrowed in decideBuild once the triangles are known); the outside and inside
  // proxies forwarding may rely on.
  void chooseObjects() {
    const std::string& kind = options_.scene.proxy_kind;
    outside_.assign(num_meshes_, -1);
    inside_.assign(num_meshes_, -1);
    for (size_t m = 0; m < num_meshes_; ++m) {
      outside_[m] = proxyOfKind(desc_.meshes[m], "outside");
      if (kind.empty() && options_.proxies) inside_[m] = proxyOfKind(desc_.meshes[m], "inside");
    }
    comm_.collectively([&] {
      checkForwardingKind(kind, options_.proxies);
      assembly_ = assembleScene(desc_, options_.scene);
    });
    ds_.objects_ = assembly_.objects;
    used_ = assembly_.used;
  }

  // The proxies of every used mesh that some step needs, on every rank: the outside one (objects
  // are placed by it), the inside one forwarding relies on, the one the single-process renderer
  // would trace (its triangles decide the build); the classes forwarding relies on, proved.
  void loadProxies() {
    proxies_.resize(num_meshes_);
    comm_.collectively([&] {
      for (size_t m = 0; m < num_meshes_; ++m) {
        if (!used_[m]) continue;
        const SceneMeshDesc& mesh = desc_.meshes[m];
        for (size_t i = 0; i < mesh.proxies.size(); ++i) {
          const int p = int(i);
          const bool needed = p == assembly_.proxy[m] || p == outside_[m] || p == inside_[m];
          proxies_[m].push_back(needed ? loadMesh(mesh.proxies[i].file) : TriMesh{});
        }
        if (!options_.proxies) continue;
        if (outside_[m] >= 0)
          requireProvedClass(mesh, mesh.proxies[size_t(outside_[m])], ProxyClass::kOutside,
                             "--forwarding proxies decides rays by it");
        if (inside_[m] >= 0)
          requireProvedClass(mesh, mesh.proxies[size_t(inside_[m])], ProxyClass::kInside,
                             "--forwarding proxies decides rays by it");
      }
    });
  }

  const TriMesh& outsideProxy(const RenderObject& o) const {
    return proxies_[o.mesh][size_t(outside_[o.mesh])];
  }

  // Owners: objects whose mesh has an outside proxy are split into spatial domains, located by
  // that proxy (it contains the original) and weighed by the original file's bytes (a stat, not
  // a read: the file belongs to one rank only).
  void assignOwners() {
    const std::vector<RenderObject>& objects = ds_.objects_;
    ds_.owners_.assign(objects.size(), -1);
    std::vector<uint32_t> distributed;
    std::vector<PartitionItem> items;
    comm_.collectively([&] {
      for (uint32_t id = 0; id < objects.size(); ++id) {
        const RenderObject& o = objects[id];
        if (outside_[o.mesh] < 0) continue;
        PartitionItem item;
        item.bounds = transformedBounds(outsideProxy(o).bounds(), o.to_world);
        std::error_code ec;
        const auto bytes = std::filesystem::file_size(desc_.meshes[o.mesh].file, ec);
        if (ec)
          throw Error(desc_.meshes[o.mesh].file.string(), "cannot read the file's size",
                      ec.message(), "check that every rank sees the scene's files");
        item.weight = double(bytes);
        items.push_back(item);
        distributed.push_back(id);
      }
    });
    const std::vector<int> owner = partitionByDomains(items, ds_.ranks_);
    for (size_t i = 0; i < distributed.size(); ++i) ds_.owners_[distributed[i]] = owner[i];
    mine_.assign(objects.size(), false);
    replicated_.assign(objects.size(), false);
    distributed_.assign(objects.size(), false);
    for (uint32_t id = 0; id < objects.size(); ++id) {
      const int r = ds_.owners_[id];
      mine_[id] = r == ds_.rank_;
      replicated_[id] = r < 0;
      distributed_[id] = r >= 0;
    }
  }

  // This rank's originals: its own meshes and the replicated ones. Then every mesh's triangle
  // count, each counted by a rank that loaded it.
  void loadOriginals() {
    const std::vector<RenderObject>& objects = ds_.objects_;
    load_.assign(num_meshes_, false);
    for (uint32_t id = 0; id < objects.size(); ++id)
      if (mine_[id] || replicated_[id]) load_[objects[id].mesh] = true;
    originals_.resize(num_meshes_);
    comm_.collectively([&] {
      for (size_t m = 0; m < num_meshes_; ++m) {
        if (!load_[m]) continue;
        originals_[m] = loadSceneMesh(desc_.meshes[m]);
        ds_.facts_.originals_opened.push_back(desc_.meshes[m].file);
      }
    });
    triangles_.assign(num_meshes_, 0);
    for (size_t m = 0; m < num_meshes_; ++m)
      if (load_[m]) triangles_[m] = originals_[m].numTriangles();
    comm_.max(triangles_);
  }

  // The single-process renderer's proxy choice and build decision, from every rank's triangle
  // counts (each proxy is on every rank, each original on some).
  void decideBuild() {
    std::vector<uint64_t> proxy_triangles(num_meshes_, 0);
    for (size_t m = 0; m < num_meshes_; ++m) {
      if (!used_[m]) continue;
      const ProxyChoice choice =
          chooseProxy(desc_.meshes[m], options_.scene, triangles_[m],
                      [&](size_t proxy) { return uint64_t(proxies_[m][proxy].numTriangles()); });
      assembly_.setProxy(m, choice.proxy);
      if (choice.proxy >= 0) proxy_triangles[m] = proxies_[m][size_t(choice.proxy)].numTriangles();
    }
    ds_.objects_ = assembly_.objects;
    ds_.build_ = chooseSceneBuild(assembly_, desc_, options_.scene, triangles_, proxy_triangles);
    uint8_t flat = ds_.build_.flat ? 1 : 0;  // rank 0's decision: budgets may differ between nodes
    comm_.broadcast(std::span<uint8_t>(&flat, 1), 0);
    ds_.build_.flat = flat != 0;
  }

  // Embree scenes: own and replicated originals; with proxies, every distributed object's
  // outside proxy (robust tracing) and inside proxy.
  void buildTraceScenes() {
    ds_.device_ = std::make_unique<TraceDevice>();
    TraceSceneBuilder builder(*ds_.device_);
    const std::vector<RenderObject>& objects = ds_.objects_;
    const bool flat = ds_.build_.flat;
    std::vector<const TriMesh*> original_ptrs(num_meshes_, nullptr);
    for (size_t m = 0; m < num_meshes_; ++m)
      if (load_[m]) original_ptrs[m] = &originals_[m];
    comm_.collectively([&] {
      addRenderObjects(builder, objects, original_ptrs, flat, &mine_);
      ds_.own_ = builder.build();
      addRenderObjects(builder, objects, original_ptrs, flat, &replicated_);
      ds_.replicated_ = builder.build();
      if (!options_.proxies) return;
      // Robust (watertight) tracing: a segment that crosses an outside proxy must never slip
      // through between two of its triangles, or its owner would not be asked.
      TraceSceneOptions robust;
      robust.robust = true;
      TraceSceneBuilder robust_builder(*ds_.device_, robust);
      std::vector<const TriMesh*> outside_ptrs(num_meshes_, nullptr),
          inside_ptrs(num_meshes_, nullptr);
      for (size_t m = 0; m < num_meshes_; ++m) {
        if (!used_[m]) continue;
        if (outside_[m] >= 0) outside_ptrs[m] = &proxies_[m][size_t(outside_[m])];
        if (inside_[m] >= 0) inside_ptrs[m] = &proxies_[m][size_t(inside_[m])];
      }
      addRenderObjects(robust_builder, objects, outside_ptrs, flat, &distributed_);
      ds_.outside_ = robust_builder.build();
      addRenderObjects(builder, objects, inside_ptrs, flat, &distributed_);
      ds_.inside_ = builder.build();
    });
  }

  // The single-process epsilon: from the bounds of all originals, the union of every rank's.
  void measureEpsilon() {
    Bounds3f local = ds_.own_->bounds();
    local.extend(ds_.replicated_->bounds());
    std::vector<float> lo = {local.lo.x, local.lo.y, local.lo.z};
    std::vector<float> hi = {local.hi.x, local.hi.y, local.hi.z};
    comm_.min(lo);
    comm_.max(hi);
    Bounds3f all;
    all.lo = {lo[0], lo[1], lo[2]};
    all.hi = {hi[0], hi[1], hi[2]};
    ds_.epsilon_ = rayEpsilon(all);
  }

  // Replicated instance boxes (each owner measures its objects' originals) and the rank
  // domains they make up.
  void indexBoxes() {
    const std::vector<RenderObject>& objects = ds_.objects_;
    const size_t n = objects.size();
    std::vector<float> box_lo(3 * n, std::numeric_limits<float>::max());
    std::vector<float> box_hi(3 * n, std::numeric_limits<float>::lowest());
    for (size_t id = 0; id < n; ++id) {
      if (!mine_[id]) continue;
      const Bounds3f b =
          transformedBounds(originals_[objects[id].mesh].bounds(), objects[id].to_world);
      for (int a = 0; a < 3; ++a)
        box_lo[3 * id + size_t(a)] = b.lo[a], box_hi[3 * id + size_t(a)] = b.hi[a];
    }
    comm_.min(box_lo);
    comm_.max(box_hi);
    std::vector<LabelledBox> boxes;
    std::vector<Bounds3f> domains(size_t(ds_.ranks_));
    for (size_t id = 0; id < n; ++id) {
      if (ds_.owners_[id] < 0) continue;
      LabelledBox lb;
      lb.box.lo = {box_lo[3 * id], box_lo[3 * id + 1], box_lo[3 * id + 2]};
      lb.box.hi = {box_hi[3 * id], box_hi[3 * id + 1], box_hi[3 * id + 2]};
      lb.label = uint32_t(ds_.owners_[id]);
      lb.id = uint32_t(id);
      domains[size_t(lb.label)].extend(lb.box);
      boxes.push_back(lb);
    }
    std::vector<LabelledBox> domain_boxes;
    for (int r = 0; r < ds_.ranks_; ++r)
      if (!domains[size_t(r)].empty()) domain_boxes.push_back({domains[size_t(r)], uint32_t(r)});
    // Boxes grow by the shadow-ray offset: far above float rounding, far below any gap that
    // matters for which ranks are asked.
    ds_.instance_boxes_ = std::make_unique<BoxIndex>(*ds_.device_, std::move(boxes), ds_.epsilon_);
    ds_.domain_boxes_ =
        std::make_unique<BoxIndex>(*ds_.device_, std::move(domain_boxes), ds_.epsilon_);
  }

  // Pitfall 2 of docs/design.md: both guarantees need the light outside the original, the
  // outside one outside the proxy too. Checked against the outside proxy's world box, which
  // holds the original.
  void checkLightsOutsideProxies() {
    comm_.collectively([&] {
      for (size_t l = 0; l < desc_.lights.size(); ++l) {
        const Bounds3f lb = desc_.lights[l].bounds();
        for (size_t id = 0; id < ds_.objects_.size(); ++id) {
          const RenderObject& o = ds_.objects_[id];
          if (ds_.owners_[id] < 0) continue;
          if (transformedBounds(outsideProxy(o).bounds(), o.to_world).overlaps(lb))
            throw Error(
                desc_.path.string(),
                fmt::format("light {} may lie inside the outside proxy of mesh '{}'", l,
                            desc_.meshes[o.mesh].name),
                "a proxy decides rays only for lights outside it (docs/design.md, pitfall 2)",
                "move the light, or use --forwarding instance-boxes");
        }
      }
    });
  }

  void countFacts() {
    DistributedScene::Facts& f = ds_.facts_;
    for (size_t id = 0; id < ds_.objects_.size(); ++id) {
      const uint64_t triangles = triangles_[ds_.objects_[id].mesh];
      if (ds_.owners_[id] < 0) {
        ++f.replicated_objects;
        f.replicated_triangles += triangles;
      } else {
        ++f.distributed_objects;
        if (mine_[id]) {
          ++f.own_objects;
          f.own_triangles += triangles;
        }
      }
    }
    for (size_t m = 0; m < num_meshes_; ++m)
      for (const TriMesh& p : proxies_[m]) f.proxy_triangles += p.numTriangles();
  }

  std::unique_ptr<DistributedScene> scene_;
  DistributedScene& ds_;
  const SceneDesc& desc_;
  const DistributedSceneOptions& options_;
  const MpiComm& comm_;
  const size_t num_meshes_;
  // The objects and, per mesh, the proxy the single-process renderer would trace.
  SceneAssembly assembly_;
  // Per mesh: the outside and inside proxy forwarding relies on (indices into the mesh's
  // proxies, -1: none), whether an object uses it, whether this rank loads it, the loaded
  // proxies and originals, the triangle counts.
  std::vector<int> outside_, inside_;
  std::vector<bool> used_, load_;
  std::vector<std::vector<TriMesh>> proxies_;
  std::vector<TriMesh> originals_;
  std::vector<uint64_t> triangles_;
  // Per object: owned by this rank, replicated on every rank, owned by some rank.
  std::vector<bool> mine_, replicated_, distributed_;
};

std::unique_ptr<DistributedScene> DistributedScene::load(const SceneDesc& desc,
                                                         const DistributedSceneOptions& options,
                                                         const MpiComm& comm) {
  return DistributedSceneLoader(desc, options, comm).load();
}

bool DistributedScene::locallyOccluded(const Segment& s) const {
  return own_->occluded(s) || replicated_->occluded(s);
}

bool DistributedScene::ownOccluded(const Segment& s) const {
  return own_->occluded(s);
}

Hit DistributedScene::intersectLocal(const Segment& ray) const {
  const Hit a = own_->intersect(ray);
  const Hit b = replicated_->intersect(ray);
  if (!b.hit) return a;
  if (!a.hit) return b;
  return a.t <= b.t ? a : b;
}

}  // namespace proxyvis
