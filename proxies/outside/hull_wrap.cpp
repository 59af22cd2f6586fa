// Outside proxies from CGAL: convex_hull_3 and alpha_wrap_3 (P. Portaneri, M. Rouxel-Labbé,
// M. Hemmer, D. Cohen-Steiner, P. Alliez, "Alpha wrapping with an offset", ACM TOG 41(4), 2022).
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "proxies/limits/input_geometry.h"
#include "proxies/outside/internal/cgal_mesh.h"
#include "proxies/outside/internal/wrap_budget.h"
#include "proxies/outside/outside_proxy.h"
#include "util/error.h"

namespace proxyvis {
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
  pushHullOutward(hull, options.epsilon * input.diagonal(), input.source);
  return cgal::fromSurfaceMesh(hull, "hull of " + input.source);
}

double estimateWrapFaces(const TriMesh& input, double alpha, double offset) {
  Bounds3d box;
  double area = 0;
  for (const Triangle& t : input.triangles) {
    const Vec3d a(input.vertices[t[0]]), b(input.vertices[t[1]]), c(input.vertices[t[2]]);
    box.extend(a);
    box.extend(b);
    box.extend(c);
    area += 0.5 * length(cross(b - a, c - a));
  }
  const double diag = box.diagonal();
  const Vec3d e = box.extent() + Vec3d(2, 2, 2) * (offset * diag);
  const double box_area = 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  const double edge = alpha * diag;
  // An equilateral triangle of edge `edge` covers 0.433 edge^2; count both sides of the input.
  return (box_area + 2 * area) / (0.433 * edge * edge);
}

void requireWrapSize(const TriMesh& input, double alpha, double offset, const char* what) {
  const double faces = estimateWrapFaces(input, alpha, offset);
  if (!(faces <= kMaxEstimatedWrapFaces))
    throw Error(input.source,
                fmt::format("{} with alpha {:g} and offset {:g} would have about {:.3g} faces, "
                            "more than {:g}",
                            what, alpha, offset, faces, kMaxEstimatedWrapFaces),
                "it would take too much memory and time",
                "use a larger --alpha or a smaller --offset");
}

TriMesh makeWrapProxy(const TriMesh& input, const WrapOptions& options) {
  if (!(options.alpha > 0) || !(options.offset > 0))
    throw Error("", "alpha and offset must be positive fractions of the diagonal",
                "alpha_wrap_3 is undefined otherwise");
  requireProxyGeometry(input, GeometryNeed::kSurface, "an outside wrap");
  requireWrapSize(input, options.alpha, options.offset, "the outside wrap");
  const double diag = input.diagonal();
  cgal::Soup soup = cgal::toSoup(input);
  SurfaceMesh wrap;
  cgal::WrapBudgetVisitor visitor(options.budget, kMaxEstimatedWrapFaces / 4, input.source);
  CGAL::alpha_wrap_3(soup.points, soup.faces, options.alpha * diag, options.offset * diag, wrap,
                     CGAL::parameters::default_values(), CGAL::parameters::visitor(visitor));
  if (wrap.number_of_faces() == 0)
    throw Error(input.source, "alpha wrap produced no surface", "the input may be degenerate");
  return cgal::fromSurfaceMesh(wrap, "wrap of " + input.source);
}

}  // namespace proxyvis
