#include "mesh/internal/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <iterator>
#include <vector>

namespace proxyvis::detail {

uint64_t countSelfIntersectingPairs(const TriMesh& mesh) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = K::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;

  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3f& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  // vector<vector<size_t>>, not std::array: read/repair of array soups misbehaves in CGAL 5.5.
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});

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
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  return CGAL::collinear(Point(a.x, a.y, a.z), Point(b.x, b.y, b.z), Point(c.x, c.y, c.z));
}

}  // namespace proxyvis::detail
