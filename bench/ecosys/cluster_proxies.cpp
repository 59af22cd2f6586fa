#include "cluster_proxies.h"

#include <algorithm>
#include <cmath>

#include "mesh/io/mesh_io.h"
#include "proxies/outside/outside_proxy.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace proxyvis::ecosys {

namespace {

void append(TriMesh& into, const TriMesh& mesh, const Affine3f& to_world) {
  const uint32_t base = uint32_t(into.vertices.size());
  for (const Vec3f& v : mesh.vertices) into.vertices.push_back(to_world.apply(v));
  for (const Triangle& t : mesh.triangles)
    into.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

}  // namespace

ClusterTracer::~ClusterTracer() = default;

uint32_t ClusterTracer::cellAt(const Vec3f& p) const {
  const int ix = std::clamp(int(std::floor((p.x - x0_) / options_.cell)), 0, nx_ - 1);
  const int iy = std::clamp(int(std::floor((p.y - y0_) / options_.cell)), 0, ny_ - 1);
  return uint32_t(iy * nx_ + ix);
}

uint32_t ClusterTracer::cellOf(uint32_t object, const Vec3f& p) const {
  const uint32_t c = cell_of_object_[object];
  return c != ~0u ? c : cellAt(p);
}

ClusterTracer::ClusterTracer(const RenderScene& scene, const ClusterOptions& options,
                             const std::vector<Vec3f>& focus)
    : scene_(scene), options_(options), device_(std::make_unique<TraceDevice>()) {
  const Stopwatch watch;
  const SceneDesc& desc = scene.desc();
  const Bounds3f box = scene.originals().bounds();
  x0_ = box.lo.x, y0_ = box.lo.y;
  nx_ = std::max(1, int(std::ceil((box.hi.x - box.lo.x) / options.cell)));
  ny_ = std::max(1, int(std::ceil((box.hi.y - box.lo.y) / options.cell)));
  const int cells = nx_ * ny_;
  summary_.cells = cells;

  // Meshes: originals of every instanced mesh; the input of the cell proxies per mesh.
  originals_.resize(desc.meshes.size());
  std::vector<TriMesh> inputs(desc.meshes.size());
  std::vector<Vec3f> centre(desc.meshes.size());
  for (size_t m = 0; m < desc.meshes.size(); ++m) {
    if (desc.meshes[m].place) continue;
    originals_[m] = loadMesh(desc.meshes[m].file);
    const Bounds3f b = originals_[m].bounds();
    centre[m] = (b.lo + b.hi) * 0.5f;
  }
  // Which cell each object belongs to, and the cells' members.
  const auto& objects = scene.objects();
  cell_of_object_.assign(objects.size(), ~0u);
  std::vector<std::vector<uint32_t>> members;
  members.resize(size_t(cells));
  for (uint32_t i = 0; i < objects.size(); ++i) {
    if (objects[i].instance < 0) continue;
    const Vec3f c = objects[i].to_world.apply(centre[objects[i].mesh]);
    cell_of_object_[i] = cellAt(c);
    members[cell_of_object_[i]].push_back(i);
  }
  // Cells near a shading point get a proxy.
  std::vector<uint8_t> wanted(size_t(cells), 0);
  const int reach = int(std::ceil(options.margin / options.cell));
  for (const Vec3f& p : focus) {
    const uint32_t c = cellAt(p);
    const int cx = int(c) % nx_, cy = int(c) / nx_;
    for (int y = std::max(0, cy - reach); y <= std::min(ny_ - 1, cy + reach); ++y)
      for (int x = std::max(0, cx - reach); x <= std::min(nx_ - 1, cx + reach); ++x)
        wanted[size_t(y * nx_ + x)] = 1;
  }
  for (size_t m = 0; m < desc.meshes.size(); ++m) {
    if (desc.meshes[m].place) continue;
    int p = -1;
    for (const RenderObject& o : objects)
      if (o.mesh == m) {
        p = o.proxy;
        break;
      }
    inputs[m] = options.from_proxies && p >= 0 ? loadMesh(desc.meshes[m].proxies[size_t(p)].file)
                                               : originals_[m];
  }

  // The cell proxies are small flattened meshes: a context filter skips the own cell's proxy at
  // little cost, where mask-then-filter would trace every segment that escapes twice.
  TraceSceneOptions trace_options;
  trace_options.ignore = IgnoreStrategy::kFilter;
  TraceSceneBuilder builder(*device_, trace_options);
  // Placed meshes (the terrain) stay exact in the proxy scene, with a user id no cell has.
  for (uint32_t i = 0; i < objects.size(); ++i)
    if (objects[i].instance < 0)
      append(terrain_, loadMesh(desc.meshes[objects[i].mesh].file), objects[i].to_world);
  if (!terrain_.empty()) builder.addMesh(terrain_, uint32_t(cells));
  cell_proxy_.resize(size_t(cells));
  std::vector<int64_t> prototype(desc.meshes.size(), -1);
  for (int c = 0; c < cells; ++c) {
    if (members[size_t(c)].empty()) continue;
    if (wanted[size_t(c)]) {
      TriMesh input;
      for (uint32_t i : members[size_t(c)])
        append(input, inputs[objects[i].mesh], objects[i].to_world);
      try {
        TriMesh proxy;
        if (options.method == "wrap") {
          WrapOptions wo;
          wo.alpha = options.alpha / input.diagonal();
          wo.offset = options.offset / input.diagonal();
          proxy = makeWrapProxy(input, wo);
        } else {
          proxy = makeHullProxy(input);
        }
        summary_.proxy_triangles += proxy.numTriangles();
        builder.addMesh(proxy, uint32_t(c));
        cell_proxy_[size_t(c)] = std::move(proxy);
        ++summary_.built;
        continue;
      } catch (const Error& e) {
        ++summary_.failed;
        if (summary_.first_failure.empty()) summary_.first_failure = e.what();
      }
    }
    for (uint32_t i : members[size_t(c)]) {
      const uint32_t m = objects[i].mesh;
      if (prototype[m] < 0) prototype[m] = builder.addPrototype(originals_[m]);
      builder.addInstance(uint32_t(prototype[m]), objects[i].to_world, uint32_t(c));
    }
  }
  proxies_ = builder.build();
  own_.resize(size_t(cells));
  if (options.fused) fused_ = std::make_unique<FusedCellScenes>(*device_);
  // Members are needed again for the own-cell scenes.
  members_ = std::move(members);
  summary_.build_seconds = watch.seconds();
}

void ClusterTracer::prepare(uint32_t cell) {
  if (options_.fused) {
    if (!fused_->built(cell)) fused_->buildCell(cell, fusedPlacements(cell));
    return;
  }
  if (own_[cell] || members_[cell].empty()) return;
  TraceSceneBuilder builder(*device_);
  std::vector<int64_t> prototype(originals_.size(), -1);
  for (uint32_t i : members_[cell]) {
    const RenderObject& o = scene_.objects()[i];
    if (prototype[o.mesh] < 0) prototype[o.mesh] = builder.addPrototype(originals_[o.mesh]);
    builder.addInstance(uint32_t(prototype[o.mesh]), o.to_world, i);
  }
  own_[cell] = builder.build();
}

std::vector<FusedCellScenes::Placement> ClusterTracer::fusedPlacements(uint32_t cell) {
  if (fused_leaf_mesh_.empty()) {  // leaves once: terrain, every plant mesh, every cell proxy
    fused_leaf_mesh_.assign(originals_.size(), ~0u);
    fused_leaf_cell_.assign(cell_proxy_.size(), ~0u);
    if (!terrain_.empty()) fused_terrain_ = fused_->addLeaf(terrain_);
    for (size_t m = 0; m < originals_.size(); ++m)
      if (!originals_[m].empty()) fused_leaf_mesh_[m] = fused_->addLeaf(originals_[m]);
    for (size_t c = 0; c < cell_proxy_.size(); ++c)
      if (!cell_proxy_[c].empty()) fused_leaf_cell_[c] = fused_->addLeaf(cell_proxy_[c]);
  }
  std::vector<FusedCellScenes::Placement> out;
  if (!terrain_.empty()) out.push_back({fused_terrain_, Affine3f{}});
  for (uint32_t c = 0; c < cell_proxy_.size(); ++c) {
    if (c != cell && fused_leaf_cell_[c] != ~0u) {
      out.push_back({fused_leaf_cell_[c], Affine3f{}});
      continue;
    }
    for (uint32_t i : members_[c]) {
      const RenderObject& o = scene_.objects()[i];
      out.push_back({fused_leaf_mesh_[o.mesh], o.to_world});
    }
  }
  return out;
}

bool ClusterTracer::proxyVisible(const Segment& s, uint32_t cell) const {
  if (options_.fused) return !fused_->occluded(cell, s);
  if (proxies_->occluded(s, cell)) return false;
  return !(own_[cell] && own_[cell]->occluded(s));
}

}  // namespace proxyvis::ecosys
