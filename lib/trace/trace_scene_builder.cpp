// Builds Embree scenes: flattened meshes go straight into the top-level scene; prototypes are
// committed scenes of their own, placed by RTC_GEOMETRY_TYPE_INSTANCE geometries, so N instances
// cost the memory of one mesh plus N transforms.
#include <embree3/rtcore.h>

#include <cmath>
#include <cstring>
#include <string>

#include "trace/internal/trace_scene_impl.h"
#include "util/error.h"

namespace proxyvis {

namespace {

struct Prototype {
  RTCScene scene = nullptr;
  Bounds3f bounds;
  uint64_t triangles = 0;
};

// Every scene gets the context-filter flag (also each instanced scene, as Embree requires) so
// that queries can ignore a user id; without a filter in the context it costs nothing.
RTCSceneFlags sceneFlags(const TraceSceneOptions& options) {
  int flags = RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;
  if (options.robust) flags |= RTC_SCENE_FLAG_ROBUST;
  return RTCSceneFlags(flags);
}

RTCScene newScene(TraceDevice& device, const TraceSceneOptions& options) {
  RTCScene scene = rtcNewScene(device.handle());
  device.throwIfError("creating a scene");
  rtcSetSceneFlags(scene, sceneFlags(options));
  rtcSetSceneBuildQuality(scene,
                          options.high_quality ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
  return scene;
}

// Bad meshes are the user's problem: check before Embree sees them, since Embree does not check
// indices and gives undefined results for NaN vertices.
void validateMesh(const TriMesh& mesh) {
  const size_t nv = mesh.vertices.size();
  for (size_t i = 0; i < nv; ++i)
    if (!isFinite(mesh.vertices[i]))
      throw Error(mesh.source, "vertex " + std::to_string(i) + " has a NaN or infinite coordinate",
                  "it cannot be traced", "repair or re-export the mesh");
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (uint32_t idx : mesh.triangles[f])
      if (idx >= nv)
        throw Error(mesh.source,
                    "triangle " + std::to_string(f) + " refers to vertex " + std::to_string(idx) +
                        " of " + std::to_string(nv),
                    "index out of range", "repair or re-export the mesh");
}

// A committed triangle geometry with the mesh copied into Embree-owned buffers, its vertices
// mapped by `to_world` when given (written straight into Embree's buffer, no copy of the mesh).
// `placed_bounds` (with to_world) is extended by every placed vertex.
RTCGeometry newTriangleGeometry(TraceDevice& device, const TriMesh& mesh,
                                const Affine3f* to_world = nullptr,
                                Bounds3f* placed_bounds = nullptr) {
  validateMesh(mesh);
  RTCGeometry geom = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree over-allocates buffers made by rtcSetNewGeometryBuffer, so 16-byte loads past the last
  // vertex are safe without our own padding. A zero-size buffer still gets a valid pointer slot.
  const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  void* vb = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                     sizeof(Vec3f), nv);
  void* ib = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                     sizeof(Triangle), nt);
  if (std::string errors = device.takeErrors(); !errors.empty()) {
    rtcReleaseGeometry(geom);
    throw Error(mesh.source, "Embree cannot allocate the mesh buffers", errors);
  }
  static_assert(sizeof(Vec3f) == 12 && sizeof(Triangle) == 12);
  if (to_world) {
    auto* out = static_cast<Vec3f*>(vb);
    for (size_t i = 0; i < nv; ++i) {
      out[i] = to_world->apply(mesh.vertices[i]);
      if (!isFinite(out[i])) {
        rtcReleaseGeometry(geom);
        throw Error(mesh.source,
                    "vertex " + std::to_string(i) + " is not finite once placed in the scene",
                    "its transform overflows", "scale the instance down");
      }
      if (placed_bounds) placed_bounds->extend(out[i]);
    }
  } else if (nv) {
    std::memcpy(vb, mesh.vertices.data(), nv * sizeof(Vec3f));
  }
  if (nt) std::memcpy(ib, mesh.triangles.data(), nt * sizeof(Triangle));
  rtcCommitGeometry(geom);
  if (std::string errors = device.takeErrors(); !errors.empty()) {
    rtcReleaseGeometry(geom);
    throw Error(mesh.source, "Embree rejected the mesh", errors);
  }
  return geom;
}

bool isFinite(const Affine3f& a) {
  for (const auto& row : a.m)
    for (float x : row)
      if (!std::isfinite(x)) return false;
  return true;
}

// Cofactor matrix of the linear part: maps object-space normals (edge cross products) to world
// space exactly as the flattened mesh's cross products would be, including mirrored transforms.
void cofactor(const Affine3f& a, float out[3][3]) {
  const auto& m = a.m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      out[r][c] = m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1];
    }
}

}  // namespace

struct TraceSceneBuilder::Impl {
  TraceDevice& device;
  TraceSceneOptions options;
  std::vector<Prototype> prototypes;
  std::unique_ptr<TraceScene::Impl> scene;

  Impl(TraceDevice& d, const TraceSceneOptions& o) : device(d), options(o) { reset(); }
  ~Impl() {
    for (Prototype& p : prototypes) rtcReleaseScene(p.scene);
  }

  void reset() {
    for (Prototype& p : prototypes) rtcReleaseScene(p.scene);
    prototypes.clear();
    scene = std::make_unique<TraceScene::Impl>();
    scene->device = device.handle();
    rtcRetainDevice(scene->device);
    scene->scene = newScene(device, options);
    scene->ignore = options.ignore;
  }

  uint32_t attach(RTCGeometry geom, const TopGeometry& top) {
    rtcSetGeometryMask(geom, maskBit(top.user_id));
    rtcCommitGeometry(geom);  // a geometry changed after its commit must be committed again
    uint32_t id = rtcAttachGeometry(scene->scene, geom);
    rtcReleaseGeometry(geom);  // the scene holds the reference now
    device.throwIfError("attaching a geometry");
    PV_CHECK(id == scene->geometries.size());  // fresh scenes number geometries densely from 0
    scene->geometries.push_back(top);
    scene->user_ids.push_back(top.user_id);
    return id;
  }
};

TraceSceneBuilder::TraceSceneBuilder(TraceDevice& device, const TraceSceneOptions& options)
    : impl_(std::make_unique<Impl>(device, options)) {}

TraceSceneBuilder::~TraceSceneBuilder() = default;

uint32_t TraceSceneBuilder::addMesh(const TriMesh& mesh, uint32_t user_id) {
  RTCGeometry geom = newTriangleGeometry(impl_->device, mesh);
  TopGeometry top;
  top.user_id = user_id;
  uint32_t id = impl_->attach(geom, top);
  impl_->scene->bounds.extend(mesh.bounds());
  impl_->scene->triangles += mesh.numTriangles();
  return id;
}

uint32_t TraceSceneBuilder::addMesh(const TriMesh& mesh, const Affine3f& to_world,
                                    uint32_t user_id) {
  // The placed vertices' box (the mapped corners of the mesh's box may be much larger).
  Bounds3f bounds;
  RTCGeometry geom = newTriangleGeometry(impl_->device, mesh, &to_world, &bounds);
  TopGeometry top;
  top.user_id = user_id;
  uint32_t id = impl_->attach(geom, top);
  impl_->scene->bounds.extend(bounds);
  impl_->scene->triangles += mesh.numTriangles();
  return id;
}

uint32_t TraceSceneBuilder::addPrototype(const TriMesh& mesh) {
  Prototype proto;
  proto.scene = newScene(impl_->device, impl_->options);
  RTCGeometry geom = nullptr;
  try {
    geom = newTriangleGeometry(impl_->device, mesh);
  } catch (...) {
    rtcReleaseScene(proto.scene);
    throw;
  }
  rtcAttachGeometry(proto.scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(proto.scene);
  proto.bounds = mesh.bounds();
  proto.triangles = mesh.numTriangles();
  impl_->prototypes.push_back(proto);
  impl_->device.throwIfError("building the BVH of " + mesh.source);
  return uint32_t(impl_->prototypes.size() - 1);
}

uint32_t TraceSceneBuilder::addInstance(uint32_t prototype, const Affine3f& transform,
                                        uint32_t user_id) {
  if (prototype >= impl_->prototypes.size())
    throw Error("", "instance of unknown prototype " + std::to_string(prototype),
                std::to_string(impl_->prototypes.size()) + " prototypes were added",
                "call addPrototype first");
  if (!isFinite(transform))
    throw Error("", "instance transform has a NaN or infinite entry", "it cannot be traced");
  const Prototype& proto = impl_->prototypes[prototype];
  RTCGeometry geom = rtcNewGeometry(impl_->device.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geom, proto.scene);
  rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &transform.m[0][0]);
  rtcCommitGeometry(geom);
  TopGeometry top;
  top.user_id = user_id;
  top.prototype = prototype;
  cofactor(transform, top.normal_xf);
  uint32_t id = impl_->attach(geom, top);
  if (!proto.bounds.empty())
    for (int corner = 0; corner < 8; ++corner) {
      Vec3f p((corner & 1) ? proto.bounds.hi.x : proto.bounds.lo.x,
              (corner & 2) ? proto.bounds.hi.y : proto.bounds.lo.y,
              (corner & 4) ? proto.bounds.hi.z : proto.bounds.lo.z);
      impl_->scene->bounds.extend(transform.apply(p));
    }
  impl_->scene->triangles += proto.triangles;
  return id;
}

std::unique_ptr<TraceScene> TraceSceneBuilder::build() {
  TraceScene::Impl& scene = *impl_->scene;
  if (scene.ignore == IgnoreStrategy::kAuto) {
    size_t instances = 0;
    for (const TopGeometry& g : scene.geometries) instances += g.prototype != kInvalidId;
    scene.ignore = 2 * instances >= scene.geometries.size() ? IgnoreStrategy::kMaskThenFilter
                                                            : IgnoreStrategy::kFilter;
  }
  rtcCommitScene(impl_->scene->scene);
  impl_->device.throwIfError("building the top-level BVH");
  // The top-level scene retains the prototype scenes its instances use; hand ours over.
  impl_->scene->prototypes.reserve(impl_->prototypes.size());
  for (Prototype& p : impl_->prototypes) impl_->scene->prototypes.push_back(p.scene);
  impl_->prototypes.clear();
  std::unique_ptr<TraceScene> result(new TraceScene(std::move(impl_->scene)));
  impl_->reset();
  return result;
}

}  // namespace proxyvis
