#pragma once
// The one conversion between TriMesh and CGAL: a triangle soup in CGAL's point type (what
// alpha_wrap_3 and the Polygon_mesh_processing soup functions take) and a Surface_mesh, and back.
// Everything that hands a TriMesh to CGAL goes through here (mesh-info's self-intersection test,
// the proxy generators, the exact containment check); the repairs each needs are built on it.
// Including this header pulls in CGAL (15-37 s per translation unit): include it only from the
// .cpp files that use CGAL, never from another header that is not CGAL-only itself.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/error.h"

namespace proxyvis::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
using SoupTriangle = std::array<std::size_t, 3>;

inline Point3 toPoint(const Vec3d& v) {
  return {v.x, v.y, v.z};
}

// `box` grown by `margin` on every side (what lies within `margin` of it overlaps the result).
inline CGAL::Bbox_3 grownBox(const CGAL::Bbox_3& box, double margin) {
  return {box.xmin() - margin, box.ymin() - margin, box.zmin() - margin,
          box.xmax() + margin, box.ymax() + margin, box.zmax() + margin};
}

// A triangle soup in CGAL's types. Polygon is SoupTriangle, or std::vector<std::size_t> for
// repair_polygon_soup (which misbehaves on std::array soups in CGAL 5.5).
template <typename Polygon = SoupTriangle>
struct Soup {
  std::vector<Point3> points;
  std::vector<Polygon> faces;
};

// The mesh's vertices and triangles as they are: nothing welded, dropped or checked (indices
// must be in range; non-finite coordinates are the caller's to refuse).
template <typename Polygon = SoupTriangle>
Soup<Polygon> toSoup(const TriMesh& mesh) {
  Soup<Polygon> soup;
  soup.points.reserve(mesh.vertices.size());
  for (const Vec3f& v : mesh.vertices) soup.points.emplace_back(v.x, v.y, v.z);
  soup.faces.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) soup.faces.push_back(Polygon{t[0], t[1], t[2]});
  return soup;
}

// Builds a Surface_mesh from a mesh whose faces form a valid oriented polygon mesh (e.g. a
// closed manifold proxy). Returns false when Surface_mesh rejects a face (non-manifold input).
inline bool toSurfaceMesh(const TriMesh& mesh, SurfaceMesh& out) {
  out.clear();
  std::vector<SurfaceMesh::Vertex_index> vmap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3f& v = mesh.vertices[i];
    vmap[i] = out.add_vertex(Point3(v.x, v.y, v.z));
  }
  for (const Triangle& t : mesh.triangles) {
    if (out.add_face(vmap[t[0]], vmap[t[1]], vmap[t[2]]) == SurfaceMesh::null_face()) return false;
  }
  // Drop vertices no face references (e.g. bun_zipper's 1,113 stray scan points).
  for (SurfaceMesh::Vertex_index v : out.vertices())
    if (out.is_isolated(v)) out.remove_vertex(v);
  out.collect_garbage();
  return true;
}

// Converts back, rounding coordinates to float (what TriMesh stores); vertex indices compacted.
inline TriMesh fromSurfaceMesh(const SurfaceMesh& sm, std::string source) {
  TriMesh mesh;
  mesh.source = std::move(source);
  std::vector<uint32_t> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), 0);
  for (SurfaceMesh::Vertex_index v : sm.vertices()) {
    index[v.idx()] = uint32_t(mesh.vertices.size());
    const Point3& p = sm.point(v);
    mesh.vertices.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  }
  for (SurfaceMesh::Face_index f : sm.faces()) {
    Triangle t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) t[k] = index[v.idx()];
      ++k;
    }
    PV_CHECK_MSG(k == 3, "fromSurfaceMesh expects triangles");
    mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace proxyvis::cgal
