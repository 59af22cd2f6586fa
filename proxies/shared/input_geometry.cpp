#include "proxies/shared/input_geometry.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/core.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "util/error.h"

namespace proxyvis {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The referenced vertices in double, or none if a coordinate is not finite.
std::vector<Vec3d> referencedPoints(const TriMesh& mesh, bool& finite) {
  std::vector<uint8_t> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (uint32_t i : t) used[i] = 1;
  std::vector<Vec3d> points;
  finite = true;
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i]) continue;
    const Vec3d p(mesh.vertices[i]);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      finite = false;
      return {};
    }
    points.push_back(p);
  }
  return points;
}

double distanceToLine(const Vec3d& p, const Vec3d& a, const Vec3d& unit_dir) {
  const Vec3d d = p - a;
  return length(d - unit_dir * dot(d, unit_dir));
}

}  // namespace

double GeometryMeasure::flat_tolerance() const {
  return std::max(1e-6 * diagonal, 8.0 * double(FLT_EPSILON) * max_abs);
}

GeometryMeasure measureGeometry(const TriMesh& mesh) {
  GeometryMeasure m;
  m.triangles = mesh.numTriangles();
  const std::vector<Vec3d> points = referencedPoints(mesh, m.finite);
  if (!m.finite || points.empty()) return m;

  Bounds3d box;
  for (const Vec3d& p : points) {
    box.extend(p);
    m.max_abs = std::max({m.max_abs, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  m.diagonal = box.diagonal();
  if (!(m.diagonal > 0)) return m;

  // Two far-apart vertices: the lowest along the longest box side, and the farthest from it.
  const Vec3d extent = box.extent();
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const Vec3d a =
      *std::min_element(points.begin(), points.end(),
                        [&](const Vec3d& p, const Vec3d& q) { return p[axis] < q[axis]; });
  const Vec3d b = *std::max_element(
      points.begin(), points.end(),
      [&](const Vec3d& p, const Vec3d& q) { return length(p - a) < length(q - a); });
  const Vec3d dir = normalize(b - a);
  Vec3d c = a;
  for (const Vec3d& p : points) {
    const double w = distanceToLine(p, a, dir);
    if (w > m.width) {
      m.width = w;
      c = p;
    }
  }
  if (m.width > 0) {
    const Vec3d n = normalize(cross(b - a, c - a));
    for (const Vec3d& p : points) m.thickness = std::max(m.thickness, std::abs(dot(p - a, n)));
  }

  for (const Triangle& t : mesh.triangles) {
    const Vec3f &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
    if (!CGAL::collinear(Kernel::Point_3(p.x, p.y, p.z), Kernel::Point_3(q.x, q.y, q.z),
                         Kernel::Point_3(r.x, r.y, r.z)))
      ++m.non_degenerate_triangles;
  }
  return m;
}

void requireProxyGeometry(const TriMesh& mesh, GeometryNeed need, const std::string& generator) {
  const std::string& file = mesh.source;
  const std::string cannot = "cannot build " + generator;
  if (mesh.empty())
    throw Error(file, "the mesh has no triangles", "there is nothing to build a proxy of");
  for (const Triangle& t : mesh.triangles)
    for (uint32_t i : t)
      if (i >= mesh.vertices.size())
        throw Error(file,
                    fmt::format("a triangle refers to vertex {} of {}", i, mesh.vertices.size()),
                    "the mesh is inconsistent");
  const GeometryMeasure m = measureGeometry(mesh);
  if (!m.finite)
    throw Error(file, "a vertex coordinate is not finite", cannot + " from infinite or NaN points",
                "repair the mesh");
  if (m.max_abs > kMaxProxyCoordinate)
    throw Error(
        file,
        fmt::format("coordinates reach {:.3g}, beyond +-{:g}", m.max_abs, kMaxProxyCoordinate),
        cannot + ": offsets and squared distances of such numbers overflow float",
        "scale the mesh down (other units) and translate it near the origin");
  if (m.diagonal == 0)
    throw Error(file, "all vertices are at one point", cannot + " of a mesh without extent",
                "check the mesh (a scale of 0?)");
  if (m.diagonal < kMinProxyDiagonal)
    throw Error(file,
                fmt::format("the bounding-box diagonal is {:.3g}, below {:g}", m.diagonal,
                            kMinProxyDiagonal),
                cannot + ": squared distances this small underflow float",
                "scale the mesh up (other units)");
  if (m.diagonal < kMinProxyRelativeExtent * m.max_abs)
    throw Error(
        file,
        fmt::format("the mesh spans {:.3g} at coordinates up to {:.3g}", m.diagonal, m.max_abs),
        cannot +
            ": float coordinates this far from the origin leave too few steps across "
            "the mesh to place a proxy around it",
        "translate the mesh near the origin");
  const double flat = m.flat_tolerance();
  if (m.width <= flat)
    throw Error(file, "all vertices lie on one line (within float rounding)",
                cannot + ": the mesh has no area", "check the mesh");
  if (need == GeometryNeed::kSurface && m.non_degenerate_triangles == 0)
    throw Error(file, fmt::format("all {} triangles are degenerate (zero area)", m.triangles),
                cannot + ": the mesh has no surface", "check the mesh");
  if (need == GeometryNeed::kSolid && m.thickness <= flat)
    throw Error(file, "all vertices lie in one plane (within float rounding)",
                cannot + ": the mesh encloses no volume",
                "use --kind outside --method wrap for a flat mesh");
}

}  // namespace proxyvis
