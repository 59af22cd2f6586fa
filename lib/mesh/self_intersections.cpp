#include "mesh/internal/self_intersections.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <iterator>
#include <vector>

#include "mesh/cgal_bridge.h"

namespace proxyvis::detail {

uint64_t countSelfIntersectingPairs(const TriMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Mesh = cgal::SurfaceMesh;

  // vector<vector<size_t>>, not std::array: read/repair of array soups misbehaves in CGAL 5.5.
  auto [points, polygons] = cgal::toSoup<std::vector<std::size_t>>(mesh);

  // Merges exact duplicate points, drops degenerate and duplicate polygons and isolated points.
  PMP::repair_polygon_soup(points, polygons);
  // A Surface_mesh needs a manifold, orientable soup: this splits pinched vertices and edges.
  PMP::orient_polygon_soup(points, polygons);
  Mesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);

  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(faces(sm), sm, std::back_inserter(pairs));
  return pairs.size();
}

bool areCollinear(const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  using cgal::Point3;
  return CGAL::collinear(Point3(a.x, a.y, a.z), Point3(b.x, b.y, b.z), Point3(c.x, c.y, c.z));
}

}  // namespace proxyvis::detail
