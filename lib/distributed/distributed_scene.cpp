// Loading one rank's share of a data-parallel scene (contract in distributed_scene.h). The steps
// that read files run under MpiComm::collectively(), so that a rank that cannot read its share
// ends the job with one message naming it, before any rendering starts.
#include "distributed/distributed_scene.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

#include "distributed/domain_partition.h"
#include "mesh/io/mesh_io.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/sha256.h"

namespace proxyvis {

namespace {

bool overlaps(const Bounds3f& a, const Bounds3f& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

int proxyOfKind(const SceneMeshDesc& mesh, const std::string& kind) {
  for (size_t i = 0; i < mesh.proxies.size(); ++i)
    if (mesh.proxies[i].kind == kind) return int(i);
  return -1;
}

// The recorded class must be the kind's class, for this very file.
void requireProvedClass(const SceneMeshDesc& mesh, const ProxyRef& ref, ProxyClass expected) {
  const std::string file = ref.file.string();
  if (ref.verified_class != expected)
    throw Error(file,
                fmt::format("{} proxy of mesh '{}' has no proved {} class in the scene", ref.kind,
                            mesh.name, proxyClassName(expected)),
                "--forwarding proxies decides rays by it",
                "generate it with proxy-gen, or prove it with proxy-check SCENE --write-scene OUT");
  if (ref.sha256.empty() || ref.sha256 != sha256OfFile(ref.file))
    throw Error(file,
                fmt::format("the {} class of mesh '{}''s proxy was not proved for this file",
                            proxyClassName(expected), mesh.name),
                ref.sha256.empty() ? "the scene records no sha256 for it"
                                   : "the file's sha256 differs from the one recorded",
                "prove it again: proxy-check SCENE --write-scene OUT");
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

std::unique_ptr<DistributedScene> DistributedScene::load(const SceneDesc& desc,
                                                         const DistributedSceneOptions& options,
                                                         const MpiComm& comm) {
  std::unique_ptr<DistributedScene> scene(new DistributedScene(desc));
  DistributedScene& ds = *scene;
  ds.rank_ = comm.rank();
  ds.ranks_ = comm.size();
  const size_t num_meshes = desc.meshes.size();

  // Objects in the single-process renderer's order, with the proxy it would choose.
  std::vector<int> chosen(num_meshes), outside(num_meshes), inside(num_meshes);
  std::vector<bool> used(num_meshes, false);
  for (size_t m = 0; m < num_meshes; ++m) {
    chosen[m] = chooseProxy(desc.meshes[m], RenderSceneOptions{});
    outside[m] = proxyOfKind(desc.meshes[m], "outside");
    inside[m] = proxyOfKind(desc.meshes[m], "inside");
  }
  comm.collectively([&] { ds.objects_ = renderObjects(desc, chosen); });
  for (const RenderObject& o : ds.objects_) used[o.mesh] = true;
  const std::vector<RenderObject>& objects = ds.objects_;

  // Every proxy of every used mesh, on every rank; the classes forwarding relies on, proved.
  std::vector<std::vector<TriMesh>> proxies(num_meshes);
  comm.collectively([&] {
    for (size_t m = 0; m < num_meshes; ++m) {
      if (!used[m]) continue;
      const SceneMeshDesc& mesh = desc.meshes[m];
      for (const ProxyRef& ref : mesh.proxies) proxies[m].push_back(loadMesh(ref.file));
      if (!options.proxies) continue;
      if (outside[m] >= 0)
        requireProvedClass(mesh, mesh.proxies[size_t(outside[m])], ProxyClass::kOutside);
      if (inside[m] >= 0)
        requireProvedClass(mesh, mesh.proxies[size_t(inside[m])], ProxyClass::kInside);
    }
  });

  // Owners: objects whose mesh has an outside proxy are split into spatial domains, located by
  // that proxy (it contains the original) and weighed by the original file's bytes (a stat, not
  // a read: the file belongs to one rank only).
  ds.owners_.assign(objects.size(), -1);
  std::vector<uint32_t> distributed;
  std::vector<PartitionItem> items;
  comm.collectively([&] {
    for (uint32_t id = 0; id < objects.size(); ++id) {
      const RenderObject& o = objects[id];
      if (outside[o.mesh] < 0) continue;
      PartitionItem item;
      item.bounds =
          transformedBounds(proxies[o.mesh][size_t(outside[o.mesh])].bounds(), o.to_world);
      std::error_code ec;
      const auto bytes = std::filesystem::file_size(desc.meshes[o.mesh].file, ec);
      if (ec)
        throw Error(desc.meshes[o.mesh].file.string(), "cannot read the file's size", ec.message(),
                    "check that every rank sees the scene's files");
      item.weight = double(bytes);
      items.push_back(item);
      distributed.push_back(id);
    }
  });
  const std::vector<int> owner = partitionByDomains(items, ds.ranks_);
  for (size_t i = 0; i < distributed.size(); ++i) ds.owners_[distributed[i]] = owner[i];

  // This rank's originals: its own meshes and the replicated ones.
  std::vector<bool> mine(objects.size(), false), replicated(objects.size(), false);
  std::vector<bool> load(num_meshes, false);
  for (uint32_t id = 0; id < objects.size(); ++id) {
    const int r = ds.owners_[id];
    mine[id] = r == ds.rank_;
    replicated[id] = r < 0;
    if (mine[id] || replicated[id]) load[objects[id].mesh] = true;
  }
  std::vector<TriMesh> originals(num_meshes);
  comm.collectively([&] {
    for (size_t m = 0; m < num_meshes; ++m) {
      if (!load[m]) continue;
      originals[m] = loadMesh(desc.meshes[m].file);
      ds.facts_.originals_opened.push_back(desc.meshes[m].file);
    }
  });

  // The single-process build decision, from every mesh's triangle count (each counted by a rank
  // that loaded it) and the proxies it would use.
  std::vector<uint64_t> triangles(num_meshes, 0);
  for (size_t m = 0; m < num_meshes; ++m)
    if (load[m]) triangles[m] = originals[m].numTriangles();
  comm.max(triangles);
  std::vector<int> render_proxy = chosen;
  for (size_t m = 0; m < num_meshes; ++m)
    if (render_proxy[m] >= 0 && proxies[m][size_t(render_proxy[m])].numTriangles() >= triangles[m])
      render_proxy[m] = -1;  // loadRenderScene skips a proxy that is not cheaper
  bool any_proxy = false;
  for (const RenderObject& o : objects) any_proxy |= render_proxy[o.mesh] >= 0;
  uint64_t flat_triangles = 0;
  for (const RenderObject& o : objects)
    flat_triangles +=
        triangles[o.mesh] +
        (any_proxy ? (render_proxy[o.mesh] >= 0
                          ? proxies[o.mesh][size_t(render_proxy[o.mesh])].numTriangles()
                          : triangles[o.mesh])
                   : 0);
  ds.build_ = chooseBuild(options.instance_build, !desc.instances.empty(), flat_triangles,
                          options.memory_budget_bytes);
  uint8_t flat = ds.build_.flat ? 1 : 0;  // rank 0's decision: budgets may differ between nodes
  comm.broadcast(std::span<uint8_t>(&flat, 1), 0);
  ds.build_.flat = flat != 0;

  // Embree scenes.
  ds.device_ = std::make_unique<TraceDevice>();
  TraceSceneBuilder builder(*ds.device_);
  std::vector<const TriMesh*> original_ptrs(num_meshes, nullptr);
  for (size_t m = 0; m < num_meshes; ++m)
    if (load[m]) original_ptrs[m] = &originals[m];
  comm.collectively([&] {
    addRenderObjects(builder, objects, original_ptrs, ds.build_.flat, &mine);
    ds.own_ = builder.build();
    addRenderObjects(builder, objects, original_ptrs, ds.build_.flat, &replicated);
    ds.replicated_ = builder.build();
    std::vector<bool> all_distributed(objects.size());
    for (size_t id = 0; id < objects.size(); ++id) all_distributed[id] = ds.owners_[id] >= 0;
    if (options.proxies) {
      // Robust (watertight) tracing: a segment that crosses an outside proxy must never slip
      // through between two of its triangles, or its owner would not be asked.
      TraceSceneOptions robust;
      robust.robust = true;
      TraceSceneBuilder robust_builder(*ds.device_, robust);
      std::vector<const TriMesh*> outside_ptrs(num_meshes, nullptr),
          inside_ptrs(num_meshes, nullptr);
      for (size_t m = 0; m < num_meshes; ++m) {
        if (!used[m]) continue;
        if (outside[m] >= 0) outside_ptrs[m] = &proxies[m][size_t(outside[m])];
        if (inside[m] >= 0) inside_ptrs[m] = &proxies[m][size_t(inside[m])];
      }
      addRenderObjects(robust_builder, objects, outside_ptrs, ds.build_.flat, &all_distributed);
      ds.outside_ = robust_builder.build();
      addRenderObjects(builder, objects, inside_ptrs, ds.build_.flat, &all_distributed);
      ds.inside_ = builder.build();
    }
  });

  // The single-process epsilon: from the bounds of all originals, the union of every rank's.
  Bounds3f local = ds.own_->bounds();
  local.extend(ds.replicated_->bounds());
  std::vector<float> lo = {local.lo.x, local.lo.y, local.lo.z};
  std::vector<float> hi = {local.hi.x, local.hi.y, local.hi.z};
  comm.min(lo);
  comm.max(hi);
  Bounds3f all;
  all.lo = {lo[0], lo[1], lo[2]};
  all.hi = {hi[0], hi[1], hi[2]};
  ds.epsilon_ = rayEpsilon(all);

  // Replicated instance boxes: each owner measures its objects' originals.
  const size_t n = objects.size();
  std::vector<float> box_lo(3 * n, std::numeric_limits<float>::max());
  std::vector<float> box_hi(3 * n, std::numeric_limits<float>::lowest());
  for (size_t id = 0; id < n; ++id) {
    if (!mine[id]) continue;
    const Bounds3f b =
        transformedBounds(originals[objects[id].mesh].bounds(), objects[id].to_world);
    for (int a = 0; a < 3; ++a)
      box_lo[3 * id + size_t(a)] = b.lo[a], box_hi[3 * id + size_t(a)] = b.hi[a];
  }
  comm.min(box_lo);
  comm.max(box_hi);
  std::vector<LabelledBox> boxes;
  std::vector<Bounds3f> domains(size_t(ds.ranks_));
  for (size_t id = 0; id < n; ++id) {
    if (ds.owners_[id] < 0) continue;
    LabelledBox lb;
    lb.box.lo = {box_lo[3 * id], box_lo[3 * id + 1], box_lo[3 * id + 2]};
    lb.box.hi = {box_hi[3 * id], box_hi[3 * id + 1], box_hi[3 * id + 2]};
    lb.label = uint32_t(ds.owners_[id]);
    domains[size_t(lb.label)].extend(lb.box);
    boxes.push_back(lb);
  }
  std::vector<LabelledBox> domain_boxes;
  for (int r = 0; r < ds.ranks_; ++r)
    if (!domains[size_t(r)].empty()) domain_boxes.push_back({domains[size_t(r)], uint32_t(r)});
  // Boxes grow by the shadow-ray offset: far above float rounding, far below any gap that
  // matters for which ranks are asked.
  ds.instance_boxes_ = std::make_unique<BoxIndex>(*ds.device_, std::move(boxes), ds.epsilon_);
  ds.domain_boxes_ = std::make_unique<BoxIndex>(*ds.device_, std::move(domain_boxes), ds.epsilon_);

  // Pitfall 2 of docs/design.md: both guarantees need the light outside the original, the
  // outside one outside the proxy too. Checked against the outside proxy's world box, which
  // holds the original.
  if (options.proxies) {
    comm.collectively([&] {
      for (size_t l = 0; l < desc.lights.size(); ++l) {
        Bounds3f lb;
        for (const auto& t : desc.lights[l].triangles)
          for (const Vec3f& v : t) lb.extend(v);
        for (size_t id = 0; id < n; ++id) {
          const RenderObject& o = objects[id];
          if (ds.owners_[id] < 0) continue;
          const Bounds3f pb =
              transformedBounds(proxies[o.mesh][size_t(outside[o.mesh])].bounds(), o.to_world);
          if (overlaps(pb, lb))
            throw Error(
                desc.path.string(),
                fmt::format("light {} may lie inside the outside proxy of mesh '{}'", l,
                            desc.meshes[o.mesh].name),
                "a proxy decides rays only for lights outside it (docs/design.md, pitfall 2)",
                "move the light, or use --forwarding instance-boxes");
        }
      }
    });
  }

  Facts& f = ds.facts_;
  for (size_t id = 0; id < n; ++id) {
    if (ds.owners_[id] < 0) {
      ++f.replicated_objects;
      f.replicated_triangles += triangles[objects[id].mesh];
    } else {
      ++f.distributed_objects;
      if (mine[id]) {
        ++f.own_objects;
        f.own_triangles += triangles[objects[id].mesh];
      }
    }
  }
  for (size_t m = 0; m < num_meshes; ++m)
    for (const TriMesh& p : proxies[m]) f.proxy_triangles += p.numTriangles();
  return scene;
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

void DistributedScene::route(Forwarding policy, const Segment& s, std::vector<LabelEntry>& scratch,
                             std::vector<TraceScene::UserHit>& hits, Route& out) const {
  out.blocked_by_inside = false;
  out.ranks.clear();
  scratch.clear();
  if (policy == Forwarding::kProxies) {
    PV_CHECK_MSG(outside_, "route(): the scene was loaded without proxy forwarding");
    if (inside_->occluded(s)) {
      out.blocked_by_inside = true;
      return;
    }
    hits.clear();
    outside_->hitsAlong(s, hits);
    for (const TraceScene::UserHit& h : hits) {
      const int r = owners_[h.user_id];
      if (r == rank_ || r < 0) continue;
      bool found = false;
      for (LabelEntry& e : scratch)
        if (e.label == uint32_t(r)) {
          e.t = std::min(e.t, h.t);
          found = true;
        }
      if (!found) scratch.push_back({uint32_t(r), h.t});
    }
  } else {
    (policy == Forwarding::kDomainBounds ? domain_boxes_ : instance_boxes_)
        ->labelsAlong(s, scratch);
    std::erase_if(scratch, [&](const LabelEntry& e) { return e.label == uint32_t(rank_); });
  }
  std::sort(scratch.begin(), scratch.end(), [](const LabelEntry& a, const LabelEntry& b) {
    return a.t != b.t ? a.t < b.t : a.label < b.label;
  });
  for (const LabelEntry& e : scratch) out.ranks.push_back(uint16_t(e.label));
}

}  // namespace proxyvis
