// Outside proxies from CGAL: convex_hull_3 and alpha_wrap_3 (P. Portaneri, M. Rouxel-Labbé,
// M. Hemmer, D. Cohen-Steiner, P. Alliez, "Alpha wrapping with an offset", ACM TOG 41(4), 2022).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include <fmt/core.h>

#include "mesh/cgal_bridge.h"
#include "proxies/outside/canonical_hull.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/shared/cgal/wrap_budget.h"
#include "proxies/shared/input_geometry.h"
#include "proxies/shared/wrap_size.h"
#include "util/error.h"

namespace proxyvis {

namespace cgal {
// convex_hull_3 (CGAL 5.5's quickhull) keeps the border of each visible region in a std::map
// keyed by vertex handles, i.e. by address, and starts the new cone at its first entry. The
// hull's vertices and faces thus come out in an order that depends on where the allocator put
// the triangulation's blocks (it differed with GLIBC_TUNABLES=glibc.malloc.tcache_count=0), and
// everything after (the centroid sum below, the budget reduction's tie-breaks) inherits it.
// Rebuilds the hull with its vertices sorted by coordinates and its faces, each rotated to start
// at its smallest index, sorted: the same order whatever the heap layout. (Where hull points are
// coplanar, which triangulation of a facet quickhull picks can still follow that order.)
SurfaceMesh canonicalHull(const SurfaceMesh& hull) {
  std::vector<SurfaceMesh::Vertex_index> verts(hull.vertices().begin(), hull.vertices().end());
  std::sort(verts.begin(), verts.end(),
            [&](SurfaceMesh::Vertex_index a, SurfaceMesh::Vertex_index b) {
              const Point3 &p = hull.point(a), &q = hull.point(b);
              return std::make_tuple(p.x(), p.y(), p.z()) < std::make_tuple(q.x(), q.y(), q.z());
            });
  std::vector<uint32_t> rank(hull.number_of_vertices() + hull.number_of_removed_vertices(), 0);
  for (size_t i = 0; i < verts.size(); ++i) rank[verts[i].idx()] = uint32_t(i);
  std::vector<std::array<uint32_t, 3>> faces;
  faces.reserve(hull.number_of_faces());
  for (SurfaceMesh::Face_index f : hull.faces()) {
    std::array<uint32_t, 3> t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull))
      if (k < 3) t[k++] = rank[v.idx()];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  SurfaceMesh out;
  std::vector<SurfaceMesh::Vertex_index> vmap;
  vmap.reserve(verts.size());
  for (SurfaceMesh::Vertex_index v : verts) vmap.push_back(out.add_vertex(hull.point(v)));
  for (const auto& t : faces) out.add_face(vmap[t[0]], vmap[t[1]], vmap[t[2]]);
  return out;
}

using Delaunay = CGAL::Delaunay_triangulation_3<Kernel>;

SurfaceMesh uniqueHull(const std::vector<Point3>& points) {
  const Delaunay dt(points.begin(), points.end());
  SurfaceMesh hull;
  if (dt.dimension() < 3) return hull;
  std::map<Point3, SurfaceMesh::Vertex_index> index;
  auto vertex = [&](Delaunay::Vertex_handle v) {
    auto [it, added] = index.try_emplace(v->point());
    if (added) it->second = hull.add_vertex(v->point());
    return it->second;
  };
  std::vector<Delaunay::Cell_handle> cells;
  dt.incident_cells(dt.infinite_vertex(), std::back_inserter(cells));
  std::vector<std::array<SurfaceMesh::Vertex_index, 3>> faces;
  for (Delaunay::Cell_handle c : cells) {
    const int i = c->index(dt.infinite_vertex());
    std::array<SurfaceMesh::Vertex_index, 3> t;
    for (int j = 0; j < 3; ++j) t[j] = vertex(c->vertex(Delaunay::vertex_triple_index(i, j)));
    faces.push_back(t);
  }
  // The facets all come out with one orientation; outward is the one of positive volume.
  double volume = 0;
  for (const auto& t : faces) {
    const Point3 &a = hull.point(t[0]), &b = hull.point(t[1]), &d = hull.point(t[2]);
    volume += CGAL::scalar_product(a - CGAL::ORIGIN,
                                   CGAL::cross_product(b - CGAL::ORIGIN, d - CGAL::ORIGIN));
  }
  for (const auto& t : faces)
    volume > 0 ? hull.add_face(t[0], t[1], t[2]) : hull.add_face(t[0], t[2], t[1]);
  return cgal::canonicalHull(hull);
}

std::vector<Point3> extremeCorners(const SurfaceMesh& hull) {
  std::vector<Point3> corners;
  for (auto v : hull.vertices()) {
    const Point3& p = hull.point(v);
    std::vector<Point3> ring;
    for (auto h : CGAL::halfedges_around_target(hull.halfedge(v), hull))
      ring.push_back(hull.point(hull.source(h)));
    bool inside_edge = false;
    for (size_t a = 0; a < ring.size() && !inside_edge; ++a)
      for (size_t b = a + 1; b < ring.size() && !inside_edge; ++b)
        inside_edge = CGAL::collinear(ring[a], p, ring[b]) &&
                      CGAL::collinear_are_strictly_ordered_along_line(ring[a], p, ring[b]);
    if (inside_edge) continue;
    bool flat = true;
    for (size_t k = 2; k < ring.size() && flat; ++k)
      flat = CGAL::coplanar(p, ring[0], ring[1], ring[k]);
    if (!flat || CGAL::collinear(p, ring[0], ring[1])) corners.push_back(p);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

}  // namespace cgal

namespace {

using cgal::Point3;
using cgal::SurfaceMesh;
using cgal::Vector3;

// Scales the hull about its vertex centroid c so that every face plane moves outward by at
// least `distance`: a plane at distance h from c moves by s·h, so s = distance / min h.
// Scaling keeps the hull convex and its combinatorics unchanged, which offsetting the planes
// and re-intersecting them would not guarantee.
void pushHullOutward(SurfaceMesh& hull, double distance, const std::string& source) {
  Vector3 sum(0, 0, 0);
  for (auto v : hull.vertices()) sum = sum + (hull.point(v) - CGAL::ORIGIN);
  const Point3 c = CGAL::ORIGIN + sum / double(hull.number_of_vertices());
  double min_h = std::numeric_limits<double>::infinity();
  for (auto f : hull.faces()) {
    auto h = hull.halfedge(f);
    const Point3 &a = hull.point(hull.source(h)), &b = hull.point(hull.target(h)),
                 &d = hull.point(hull.target(hull.next(h)));
    Vector3 n = CGAL::cross_product(b - a, d - a);
    const double len = std::sqrt(n.squared_length());
    if (len > 0) min_h = std::min(min_h, ((a - c) * n) / len);
  }
  if (!(min_h > 0) || !std::isfinite(min_h))
    throw Error(source, "cannot build a convex hull proxy",
                "the input is flat (its hull has no volume)");
  // A hull far thinner than the push would be scaled by a huge factor (float overflow).
  const double s = 1 + distance / min_h;
  if (!(s < 2))
    throw Error(
        source, "cannot build a convex hull proxy",
        fmt::format("the hull is {:.3g} thick, too thin to push out by {:.3g}", min_h, distance),
        "use --method wrap");
  for (auto v : hull.vertices()) hull.point(v) = c + (hull.point(v) - c) * s;
}

}  // namespace

TriMesh makeHullProxy(const TriMesh& input, const HullOptions& options) {
  requireProxyGeometry(input, GeometryNeed::kSolid, "a convex hull proxy");
  std::vector<Point3> points;
  points.reserve(input.numTriangles() * 3);
  for (const Triangle& t : input.triangles)
    for (uint32_t i : t)
      points.emplace_back(input.vertices[i].x, input.vertices[i].y, input.vertices[i].z);
  SurfaceMesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  if (hull.number_of_faces() < 4 || !CGAL::is_triangle_mesh(hull))
    throw Error(input.source, "cannot build a convex hull proxy",
                "the input is flat (its hull has no volume)");
  hull = cgal::canonicalHull(hull);
  pushHullOutward(hull, options.epsilon * input.diagonal(), input.source);
  return cgal::fromSurfaceMesh(hull, "hull of " + input.source);
}

TriMesh makeWrapProxy(const TriMesh& input, const WrapOptions& options) {
  if (!(options.alpha > 0) || !(options.offset > 0))
    throw Error("", "alpha and offset must be positive fractions of the diagonal",
                "alpha_wrap_3 is undefined otherwise");
  requireProxyGeometry(input, GeometryNeed::kSurface, "an outside wrap");
  requireWrapSize(input, options.alpha, options.offset, "the outside wrap");
  const double diag = input.diagonal();
  auto soup = cgal::toSoup(input);
  SurfaceMesh wrap;
  cgal::WrapBudgetVisitor visitor(options.budget, kMaxEstimatedWrapFaces / 4, input.source);
  CGAL::alpha_wrap_3(soup.points, soup.faces, options.alpha * diag, options.offset * diag, wrap,
                     CGAL::parameters::default_values(), CGAL::parameters::visitor(visitor));
  if (wrap.number_of_faces() == 0)
    throw Error(input.source, "alpha wrap produced no surface", "the input may be degenerate");
  return cgal::fromSurfaceMesh(wrap, "wrap of " + input.source);
}

}  // namespace proxyvis
