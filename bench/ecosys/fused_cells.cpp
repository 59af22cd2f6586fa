#include "fused_cells.h"

#include <embree3/rtcore.h>

#include <limits>

#include "util/error.h"

namespace proxyvis::ecosys {

FusedCellScenes::~FusedCellScenes() {
  for (RTCScene s : cells_)
    if (s) rtcReleaseScene(s);
}

uint32_t FusedCellScenes::addLeaf(const TriMesh& mesh) {
  TraceSceneBuilder builder(device_);
  builder.addMesh(mesh);
  leaves_.push_back(builder.build());
  return uint32_t(leaves_.size() - 1);
}

void FusedCellScenes::buildCell(uint32_t cell, const std::vector<Placement>& placements) {
  if (cell >= cells_.size()) cells_.resize(cell + 1, nullptr);
  RTCScene scene = rtcNewScene(device_.handle());
  for (const Placement& p : placements) {
    RTCGeometry g = rtcNewGeometry(device_.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, leaves_[p.leaf]->handle());
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &p.to_world.m[0][0]);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene);
  device_.throwIfError("fused cell scene");
  cells_[cell] = scene;
}

bool FusedCellScenes::occluded(uint32_t cell, const Segment& s) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray;
  ray.org_x = s.org.x, ray.org_y = s.org.y, ray.org_z = s.org.z;
  ray.dir_x = s.dir.x, ray.dir_y = s.dir.y, ray.dir_z = s.dir.z;
  ray.tnear = s.tnear, ray.tfar = s.tfar;
  ray.time = 0;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
  rtcOccluded1(cells_[cell], &ctx, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

}  // namespace proxyvis::ecosys
