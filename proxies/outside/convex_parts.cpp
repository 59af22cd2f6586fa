// Outside proxy as a union of convex pieces (the collision-proxy form of V-HACD and CoACD), built
// so that it contains the input by construction: the space is cut by planes into convex cells,
// each cell gets the convex hull of the input surface clipped to it, grown outward, and the
// pieces are joined by an exact union (CGAL corefinement on an exact kernel). Each piece is
// the hull of float points, so it is exactly convex in the coordinates it is written in: nothing
// is rounded before the union, whose inputs must not cross themselves.
//
// Why the result contains the input: the cells partition space, so the hulls of the surface's
// clipped parts cover the whole surface ∂S, each part strictly inside its grown hull. A point of
// S that no hull covers (near a cell's edge deep inside S, where no surface point pulls the hull)
// cannot reach the outside without crossing ∂S, which lies inside the union: it is in a cavity of
// the union, and the cavities' shells (the components of negative volume) are dropped. Clipping
// is done in double; the growth (ConvexPartsOptions::epsilon, far above that rounding) keeps
// every piece strictly away from the input, as the exact containment check (which counts
// touching as crossing) requires, and the grown corners are rounded to float outward. That
// check still runs on the result: nothing here is trusted.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include "mesh/cgal_bridge.h"
#include "mesh/validation.h"
#include "proxies/outside/canonical_hull.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/shared/bounded_simplify.h"
#include "proxies/shared/input_geometry.h"
#include "util/disjoint_sets.h"
#include "util/error.h"

namespace proxyvis {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal::Point3;
using cgal::SurfaceMesh;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<ExactKernel::Point_3>;

using Polygon = std::vector<Vec3d>;

// The closed half-space dot(normal, x) <= offset is "below".
struct Plane {
  Vec3d normal;
  double offset = 0;
  double side(const Vec3d& p) const { return dot(normal, p) - offset; }
};

// Sutherland-Hodgman against one plane, keeping both sides. A crossing point is computed once and
// given to both sides, so the two pieces agree on the cut.
void clipPolygon(const Polygon& p, const Plane& plane, Polygon& below, Polygon& above) {
  below.clear();
  above.clear();
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3d& a = p[i];
    const Vec3d& b = p[(i + 1) % n];
    const double da = plane.side(a), db = plane.side(b);
    if (da <= 0) below.push_back(a);
    if (da >= 0) above.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const Vec3d x = a + (b - a) * (da / (da - db));
      below.push_back(x);
      above.push_back(x);
    }
  }
}

// The input surface clipped to one convex cell of the partition.
struct Cell {
  std::vector<Polygon> polygons;
};

void splitCell(const Cell& cell, const Plane& plane, Cell& below, Cell& above) {
  Polygon b, a;
  for (const Polygon& p : cell.polygons) {
    clipPolygon(p, plane, b, a);
    // A polygon that only touches the plane from one side lies wholly on that side.
    if (b.size() >= 3) below.polygons.push_back(b);
    if (a.size() >= 3) above.polygons.push_back(a);
  }
}

// Every corner of the cell's polygons: what its piece is the hull of.
std::vector<Point3> cellPoints(const Cell& cell) {
  std::vector<Point3> points;
  for (const Polygon& p : cell.polygons)
    for (const Vec3d& v : p) points.emplace_back(v.x, v.y, v.z);
  return points;
}

// Points for comparing cuts by hull volume: at most max_points of the corners, each moved by a
// fixed pseudo-random 1e-7 of the cell's size. Corners on a cut plane or on a flat part of the
// input are coplanar, which sends every hull predicate to exact arithmetic (most of the run);
// the estimate does not need them exact.
std::vector<Point3> estimatePoints(const Cell& cell, size_t max_points) {
  size_t total = 0;
  Bounds3d box;
  for (const Polygon& p : cell.polygons) {
    total += p.size();
    for (const Vec3d& v : p) box.extend(v);
  }
  const double jitter = 1e-7 * length(box.hi - box.lo);
  const size_t stride = std::max<size_t>(1, total / max_points);
  std::vector<Point3> points;
  points.reserve(total / stride + 1);
  uint64_t state = 0x9E3779B97F4A7C15ull, k = 0;
  auto next = [&] {  // splitmix64, as a number in [-1, 1)
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1p-52 - 1;
  };
  for (const Polygon& p : cell.polygons)
    for (const Vec3d& v : p)
      if (k++ % stride == 0)
        points.emplace_back(v.x + jitter * next(), v.y + jitter * next(), v.z + jitter * next());
  return points;
}

double meshVolume(const SurfaceMesh& m) {
  double v = 0;
  for (auto f : m.faces()) {
    auto h = m.halfedge(f);
    const Point3 &a = m.point(m.source(h)), &b = m.point(m.target(h)),
                 &c = m.point(m.target(m.next(h)));
    v += CGAL::scalar_product(a - CGAL::ORIGIN,
                              CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN));
  }
  return v / 6;
}

// Volume of the convex hull; 0 when the points span no volume (a flat patch of the surface).
// Summed over the canonical hull: in quickhull's own order the sum's rounding, and with it the
// choice between two nearly equal cuts, would follow the heap layout.
double hullVolume(const std::vector<Point3>& points) {
  if (points.size() < 4) return 0;
  SurfaceMesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  if (!CGAL::is_triangle_mesh(hull) || hull.number_of_faces() < 4) return 0;
  return meshVolume(cgal::canonicalHull(hull));
}

constexpr size_t kSearchPoints = 1500;
constexpr size_t kSearchPolygons = 600;
constexpr size_t kPieceFaces = 96;
// A cell's candidate cuts: each axis at 1/8 ... 7/8 of the cell's extent.
constexpr int kCutsPerAxis = 7;
constexpr int kCuts = 3 * kCutsPerAxis;

struct SplitChoice {
  Plane plane;
  double gain = -1;  // hull volume removed by the cut
};

// The best of the cell's axis-aligned cuts at 1/8 ... 7/8 of its extent, by hull volume removed.
SplitChoice bestSplit(const Cell& cell) {
  Bounds3d box;
  for (const Polygon& p : cell.polygons)
    for (const Vec3d& v : p) box.extend(v);
  // The cuts are compared on a regular sample of the cell's polygons: clipping all of them for
  // each of the 21 candidates made the search most of the run on meshes of 50 k faces.
  Cell sample;
  const size_t stride = std::max<size_t>(1, cell.polygons.size() / kSearchPolygons);
  for (size_t i = 0; i < cell.polygons.size(); i += stride)
    sample.polygons.push_back(cell.polygons[i]);
  const double sample_volume = hullVolume(estimatePoints(sample, kSearchPoints));
  // The candidates are independent: evaluated in parallel, compared in their fixed order.
  std::array<SplitChoice, kCuts> candidates;
  tbb::parallel_for(0, kCuts, [&](int c) {
    const int axis = c / kCutsPerAxis, k = 1 + c % kCutsPerAxis;
    const double lo = box.lo[axis], hi = box.hi[axis];
    if (!(hi > lo)) return;
    Plane plane;
    plane.normal[axis] = 1;
    plane.offset = lo + (hi - lo) * k / (kCutsPerAxis + 1);
    Cell below, above;
    splitCell(sample, plane, below, above);
    if (below.polygons.empty() || above.polygons.empty()) return;
    candidates[c] = {plane, sample_volume - hullVolume(estimatePoints(below, kSearchPoints)) -
                                hullVolume(estimatePoints(above, kSearchPoints))};
  });
  SplitChoice best;
  for (const SplitChoice& c : candidates)
    if (c.gain > best.gain) best = c;
  return best;
}

// The partition: greedily cut the cell whose best cut removes the most hull volume, until
// max_parts cells or no cut removes min_gain of the whole hull.
std::vector<Cell> partition(const TriMesh& input, const ConvexPartsOptions& options) {
  Cell root;
  root.polygons.reserve(input.numTriangles());
  for (const Triangle& t : input.triangles)
    root.polygons.push_back(
        {Vec3d(input.vertices[t[0]]), Vec3d(input.vertices[t[1]]), Vec3d(input.vertices[t[2]])});
  const double min_gain = options.min_gain * hullVolume(estimatePoints(root, kSearchPoints));

  std::vector<Cell> cells;
  std::vector<SplitChoice> choices;
  cells.push_back(std::move(root));
  choices.push_back(bestSplit(cells[0]));
  while (cells.size() < options.max_parts) {
    checkBudget(options.budget, "the convex parts' partition");
    size_t pick = 0;
    for (size_t i = 1; i < cells.size(); ++i)
      if (choices[i].gain > choices[pick].gain) pick = i;
    if (!(choices[pick].gain > min_gain)) break;
    Cell below, above;
    splitCell(cells[pick], choices[pick].plane, below, above);
    cells[pick] = std::move(below);
    choices[pick] = bestSplit(cells[pick]);
    cells.push_back(std::move(above));
    choices.push_back(bestSplit(cells.back()));
  }
  return cells;
}

// x rounded to a float on the side of x that `up` names: the grown hull then contains the exact
// Minkowski sum whatever the coordinates' magnitude.
float roundOutward(double x, bool up) {
  float f = float(x);
  if (up && double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  if (!up && double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

// hull(cell) with every face plane moved outward by at least e. A hull thick enough is scaled
// about its corners' centroid c (a face plane at distance h from c moves by (s - 1) · h, so
// s = 1 + e / min h), which keeps its face count; the scaled corners are rounded to float away
// from c, and e is far above that rounding. A flat or thin part is grown by the cube [-e, e]^3
// instead (its support exceeds the hull's by e in every direction), corners rounded outward.
// The piece is the hull of those floats: exactly convex in the coordinates it is written in.
TriMesh grownHull(const Cell& cell, double e, const std::string& source) {
  std::vector<Point3> points = cellPoints(cell);
  SurfaceMesh quick;
  CGAL::convex_hull_3(points.begin(), points.end(), quick);
  const bool solid = quick.number_of_faces() >= 4 && CGAL::is_triangle_mesh(quick);
  std::vector<Point3> grown;
  if (solid) {
    points = cgal::extremeCorners(quick);
    const SurfaceMesh hull = cgal::uniqueHull(points);
    double cx = 0, cy = 0, cz = 0;
    for (const Point3& p : points) cx += p.x(), cy += p.y(), cz += p.z();
    const Point3 c(cx / points.size(), cy / points.size(), cz / points.size());
    double min_h = std::numeric_limits<double>::infinity();
    for (auto f : hull.faces()) {
      auto h = hull.halfedge(f);
      const Point3 &a = hull.point(hull.source(h)), &b = hull.point(hull.target(h)),
                   &d = hull.point(hull.target(hull.next(h)));
      const cgal::Vector3 n = CGAL::cross_product(b - a, d - a);
      const double len = std::sqrt(n.squared_length());
      if (len > 0) min_h = std::min(min_h, ((a - c) * n) / len);
    }
    const double s = 1 + e / min_h;
    if (!hull.is_empty() && min_h > 0 && s < 1.5) {
      for (const Point3& p : points)
        grown.emplace_back(roundOutward(c.x() + (p.x() - c.x()) * s, p.x() > c.x()),
                           roundOutward(c.y() + (p.y() - c.y()) * s, p.y() > c.y()),
                           roundOutward(c.z() + (p.z() - c.z()) * s, p.z() > c.z()));
      return cgal::fromSurfaceMesh(cgal::uniqueHull(grown), source);
    }
  } else if (quick.number_of_vertices() >= 3) {
    points.assign(quick.points().begin(), quick.points().end());
    std::sort(points.begin(), points.end());
  }
  grown.reserve(points.size() * 8);
  for (const Point3& p : points)
    for (int k = 0; k < 8; ++k)
      grown.emplace_back(roundOutward(p.x() + (k & 1 ? e : -e), k & 1),
                         roundOutward(p.y() + (k & 2 ? e : -e), k & 2),
                         roundOutward(p.z() + (k & 4 ? e : -e), k & 4));
  return cgal::fromSurfaceMesh(cgal::uniqueHull(grown), source);
}

ExactMesh toExact(const TriMesh& m) {
  ExactMesh out;
  std::vector<ExactMesh::Vertex_index> index;
  index.reserve(m.vertices.size());
  for (const Vec3f& v : m.vertices) index.push_back(out.add_vertex({v.x, v.y, v.z}));
  for (const Triangle& t : m.triangles) out.add_face(index[t[0]], index[t[1]], index[t[2]]);
  return out;
}

TriMesh fromExact(const ExactMesh& m, const std::string& source) {
  SurfaceMesh rounded;
  std::vector<SurfaceMesh::Vertex_index> index(m.number_of_vertices() +
                                               m.number_of_removed_vertices());
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    index[v.idx()] = rounded.add_vertex(
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  for (auto f : m.faces()) {
    std::vector<SurfaceMesh::Vertex_index> corners;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(index[v.idx()]);
    rounded.add_face(corners);
  }
  // Corefinement finds the intersecting faces by box addresses: the union's order follows the
  // heap layout, and the budget's collapses after it follow that order.
  return cgal::fromSurfaceMesh(cgal::canonicalHull(rounded), source);
}

// The mesh without its components of negative volume: the shells of cavities, which filled
// make the union contain every point of the input that no piece covered.
TriMesh withoutCavities(const TriMesh& m) {
  DisjointSets sets(m.vertices.size());
  for (const Triangle& t : m.triangles)
    for (int k = 1; k < 3; ++k) sets.unite(t[0], t[k]);
  std::vector<double> volume(m.vertices.size(), 0);
  for (const Triangle& t : m.triangles)
    volume[sets.find(t[0])] +=
        dot(Vec3d(m.vertices[t[0]]), cross(Vec3d(m.vertices[t[1]]), Vec3d(m.vertices[t[2]])));
  TriMesh out;
  out.source = m.source;
  out.vertices = m.vertices;
  for (const Triangle& t : m.triangles)
    if (volume[sets.find(t[0])] > 0) out.triangles.push_back(t);
  // Compact the vertices the dropped shells used (a proxy has no stray vertices).
  std::vector<uint32_t> index(m.vertices.size(), ~0u);
  out.vertices.clear();
  for (Triangle& t : out.triangles)
    for (uint32_t& v : t) {
      if (index[v] == ~0u) {
        index[v] = uint32_t(out.vertices.size());
        out.vertices.push_back(m.vertices[v]);
      }
      v = index[v];
    }
  return out;
}

// Piece i's grown hull, and that hull reduced to `share` faces by nested collapses when it has
// more (each collapse keeps the piece around the previous one, so around its cell's part of the
// input). The pieces do not depend on each other: they are built in parallel, and are the same
// whatever the thread count.
struct Piece {
  TriMesh hull;
  std::optional<TriMesh> reduced;
};
std::vector<Piece> buildPieces(const std::vector<Cell>& cells, const ConvexPartsOptions& options,
                               double e, size_t share, const std::string& source) {
  std::vector<Piece> pieces(cells.size());
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    checkBudget(options.budget, "the convex parts");
    Piece& piece = pieces[i];
    piece.hull = grownHull(cells[i], e * double(1 + i), source);
    if (piece.hull.numTriangles() <= share) return;
    BoundedSimplifyOptions s;
    s.max_faces = share;
    s.side = BoundSide::kOutside;
    s.budget = options.budget;
    piece.reduced = simplifyBounded(piece.hull, s);
  });
  return pieces;
}

// The exact union of the pieces, rounded to float. Piece i is grown by (1 + i) · e: where two
// pieces overlap, the later one's surface then stays a clear distance outside the earlier one's
// instead of crossing it at a grazing angle (both hug the same input near their common cut),
// which is where rounding the exact intersection curves to float made faces cross.
TriMesh unitePieces(const TriMesh& input, const std::vector<Cell>& cells,
                    const ConvexPartsOptions& options, double e, ConvexPartsStats& stats) {
  const std::string source = "convex parts of " + input.source;
  // Each piece is reduced to its share of the face budget; the pipeline then reduces the union
  // to the budget itself. Without a budget each piece keeps kPieceFaces: the union stays small
  // enough to unite exactly and to check, and a convex piece of that many faces is close to its
  // hull.
  const size_t share = options.face_budget == 0
                           ? kPieceFaces
                           : std::max<size_t>(16, 3 * options.face_budget / cells.size());
  std::vector<Piece> pieces = buildPieces(cells, options, e, share, source);
  ExactMesh united;
  stats.piece_faces = 0;
  for (size_t i = 0; i < cells.size(); ++i) {
    checkBudget(options.budget, "the convex parts");
    TriMesh piece = std::move(pieces[i].hull);
    // Nested collapses keep containment but not convexity; a piece that crosses itself could not
    // be united, so it stays unreduced. (Tested here, one piece at a time: CGAL's lazy exact
    // numbers are not shared across threads.)
    if (pieces[i].reduced && !PMP::does_self_intersect(toExact(*pieces[i].reduced)))
      piece = std::move(*pieces[i].reduced);
    stats.piece_faces += piece.numTriangles();
    if (i == 0) {
      united = toExact(piece);
      continue;
    }
    // A union is refused when it would not be manifold (two pieces meeting at exactly an edge
    // or a corner): the piece grown a little more then meets the union elsewhere.
    ExactMesh out;
    for (int attempt = 0;; ++attempt) {
      ExactMesh exact = toExact(piece);
      if (PMP::corefine_and_compute_union(united, exact, out)) break;
      if (attempt == 2)
        throw Error(input.source, "cannot build a convex parts proxy",
                    fmt::format("the union of {} convex pieces is not manifold", i + 1),
                    "try another --parts, or --method wrap");
      out.clear();
      piece = grownHull(cells[i], e * (double(1 + i) + 0.5 * (attempt + 1)), source);
    }
    // The new corners are intersections of planes through earlier corners: computing them now
    // keeps CGAL's lazy numbers from carrying every earlier construction along.
    for (auto v : out.vertices()) CGAL::exact(out.point(v));
    united = std::move(out);
  }
  return withoutCavities(fromExact(united, source));
}

}  // namespace

TriMesh makeConvexPartsProxy(const TriMesh& input, const ConvexPartsOptions& options,
                             ConvexPartsStats* stats) {
  if (options.max_parts < 1 || options.max_parts > kMaxConvexParts)
    throw Error(
        "", fmt::format("--parts must be in [1, {}], got {}", kMaxConvexParts, options.max_parts));
  requireProxyGeometry(input, GeometryNeed::kSolid, "a convex parts proxy");
  const std::vector<Cell> cells = partition(input, options);
  ConvexPartsStats local;
  ConvexPartsStats& st = stats ? *stats : local;
  st.parts = cells.size();
  // Rounding can still leave crossing faces where pieces meet; larger growth separates them.
  // At least 64 float steps of the largest coordinate, so that rounding the pieces' corners and
  // the union's to float stays far inside the growth wherever the mesh lies.
  const GeometryMeasure measure = measureGeometry(input);
  double e = std::max(options.epsilon * input.diagonal() / double(cells.size()),
                      64 * double(std::numeric_limits<float>::epsilon()) * measure.max_abs);
  for (int attempt = 0;; ++attempt) {
    TriMesh united = unitePieces(input, cells, options, e, st);
    // The pipeline's own count (equal positions merged first): corners that rounding made equal
    // are not a crossing, and counting them as one made fandisk and camelhead unite three times.
    ValidationOptions check;
    check.self_intersections = true;
    if (attempt == 2 || validateMesh(united, check).self_intersecting_pairs.value_or(1) == 0)
      return united;
    e *= 4;
  }
}

}  // namespace proxyvis
