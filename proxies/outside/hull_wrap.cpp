// Outside proxies from CGAL: convex_hull_3 and alpha_wrap_3 (P. Portaneri, M. Rouxel-Labbé,
// M. Hemmer, D. Cohen-Steiner, P. Alliez, "Alpha wrapping with an offset", ACM TOG 41(4), 2022).
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "mesh/cgal_bridge.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/shared/cgal/wrap_budget.h"
#include "proxies/shared/input_geometry.h"
#include "proxies/shared/wrap_size.h"
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
