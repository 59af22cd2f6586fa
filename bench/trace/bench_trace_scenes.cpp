// The scenes of bench_trace (bench_trace_scenes.h): the flattened and the instanced dragon, each
// built through lib/trace and again through the bare Embree API, and the random segments.
#include "bench_trace_scenes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "trace/internal/embree_ray.h"
#include "util/rng.h"

namespace proxyvis::trace_bench {
namespace {

// The mesh as a bare Embree triangle geometry.
RTCGeometry bareTriangles(RTCDevice device, const TriMesh& mesh) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.numVertices()));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.numTriangles()));
  for (size_t i = 0; i < mesh.numVertices(); ++i) {
    vb[3 * i] = mesh.vertices[i].x;
    vb[3 * i + 1] = mesh.vertices[i].y;
    vb[3 * i + 2] = mesh.vertices[i].z;
  }
  for (size_t i = 0; i < mesh.numTriangles(); ++i)
    for (int k = 0; k < 3; ++k) ib[3 * i + k] = mesh.triangles[i][k];
  rtcCommitGeometry(geom);
  return geom;
}

}  // namespace

std::vector<Segment> makeSegments(const Bounds3f& scene_box, uint64_t n, uint64_t seed) {
  // The box around the scene: its bounds grown by 10 % of the extent on every side.
  Bounds3f box = scene_box;
  Vec3f grow = box.extent() * 0.1f;
  box.lo -= grow;
  box.hi += grow;
  const Vec3f e = box.extent();
  std::vector<Segment> segs(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 14), [&](const auto& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      Rng rng(seed, i);
      Vec3f a(box.lo.x + e.x * rng.uniformFloat(), box.lo.y + e.y * rng.uniformFloat(),
              box.lo.z + e.z * rng.uniformFloat());
      Vec3f b(box.lo.x + e.x * rng.uniformFloat(), box.lo.y + e.y * rng.uniformFloat(),
              box.lo.z + e.z * rng.uniformFloat());
      segs[i] = {a, 0.0f, b - a, 1.0f};
    }
  });
  return segs;
}

void bareOccluded(RTCScene scene, const std::vector<Segment>& segs, std::vector<uint8_t>& out) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, segs.size(), kChunk), [&](const auto& r) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (size_t i = r.begin(); i != r.end(); ++i) {
      RTCRay ray = detail::toRtcRay(segs[i]);
      rtcOccluded1(scene, &ctx, &ray);
      out[i] = ray.tfar < 0.0f;
    }
  });
}

std::vector<Affine3f> gridTransforms(const TriMesh& mesh, uint32_t k) {
  const Bounds3f b = mesh.bounds();
  const Vec3f e = b.extent();
  const float spacing = 1.2f * std::max({e.x, e.y, e.z});
  const uint32_t side = uint32_t(std::ceil(std::cbrt(double(k))));
  std::vector<Affine3f> xfs;
  for (uint32_t i = 0; i < k; ++i) {
    Rng rng(7, i);
    float a = 6.2831853f * rng.uniformFloat();
    Affine3f xf;
    xf.m[0][0] = std::cos(a);
    xf.m[0][1] = -std::sin(a);
    xf.m[1][0] = std::sin(a);
    xf.m[1][1] = std::cos(a);
    Vec3f c = b.center();
    Vec3f t(spacing * float(i % side), spacing * float((i / side) % side),
            spacing * float(i / (side * side)));
    // rotate about the mesh centre, then move to the grid cell
    Vec3f rc = Vec3f(xf.m[0][0] * c.x + xf.m[0][1] * c.y, xf.m[1][0] * c.x + xf.m[1][1] * c.y, c.z);
    xf.m[0][3] = t.x + c.x - rc.x;
    xf.m[1][3] = t.y + c.y - rc.y;
    xf.m[2][3] = t.z;
    xfs.push_back(xf);
  }
  return xfs;
}

BenchScene flatScene(TraceDevice& device, const TriMesh& mesh, const Options& o) {
  BenchScene s;
  s.name = "dragon " + std::to_string(mesh.numTriangles() / 1000) + "k tris";
  TraceSceneOptions to;
  to.robust = o.robust;
  to.high_quality = o.high_quality;
  TraceSceneBuilder builder(device, to);
  builder.addMesh(mesh, 1);
  s.wrapped = builder.build();
  s.bare = rtcNewScene(device.handle());
  RTCGeometry g = bareTriangles(device.handle(), mesh);
  rtcAttachGeometry(s.bare, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(s.bare);
  return s;
}

BenchScene instanceScene(TraceDevice& device, const TriMesh& mesh, const Options& o) {
  BenchScene s;
  s.name = "dragon x" + std::to_string(o.instances) + " instances";
  auto xfs = gridTransforms(mesh, o.instances);
  TraceSceneOptions to;
  to.robust = o.robust;
  to.high_quality = o.high_quality;
  TraceSceneBuilder builder(device, to);
  uint32_t proto = builder.addPrototype(mesh);
  for (uint32_t i = 0; i < xfs.size(); ++i) builder.addInstance(proto, xfs[i], i);
  s.wrapped = builder.build();

  RTCScene bare_proto = rtcNewScene(device.handle());
  RTCGeometry g = bareTriangles(device.handle(), mesh);
  rtcAttachGeometry(bare_proto, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(bare_proto);
  s.bare_prototypes.push_back(bare_proto);
  s.bare = rtcNewScene(device.handle());
  for (size_t i = 0; i < xfs.size(); ++i) {
    const Affine3f& xf = xfs[i];
    RTCGeometry inst = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(inst, bare_proto);
    // For the self-shadowing comparison: instance i answers rays whose mask has bit i % 32.
    rtcSetGeometryMask(inst, 1u << (i % 32));
    rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &xf.m[0][0]);
    rtcCommitGeometry(inst);
    rtcAttachGeometry(s.bare, inst);
    rtcReleaseGeometry(inst);
  }
  rtcCommitScene(s.bare);
  return s;
}

}  // namespace proxyvis::trace_bench
