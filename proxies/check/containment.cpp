// Exact containment of two triangle meshes.
//
// Method (all predicates exact: CGAL Exact_predicates_inexact_constructions_kernel):
//  1. Each mesh becomes a repaired polygon soup (exactly equal positions welded, faces with a
//     repeated corner and duplicated faces dropped: the same point set) for the intersection test,
//     and a ray-parity solid (proxies/shared/parity_solid.h) for point location. A surface is
//     closed when every welded edge has an even number of faces: a closed manifold, or a
//     watertight surface with non-manifold edges (four faces meeting at an edge), whose inside is
//     the set of points a ray leaves after an odd number of crossings. Point location counts
//     crossings with the input's own triangles, so no repaired or re-meshed copy stands in for
//     the input.
//  2. Surface intersection: box_intersection_d (Zomorodian & Edelsbrunner, "Fast software for
//     box intersections", SoCG 2000) pairs faces whose boxes overlap, then an exact
//     triangle-triangle test. Touching counts as intersecting.
//  3. Without a surface intersection every connected piece of one surface lies entirely inside or
//     entirely outside the other solid, so point location of every vertex (Side_of_triangle_mesh:
//     ray parity on an AABB tree of the input's triangles) settles contains / contained /
//     disjoint. Testing every vertex,
//     not one, also handles several components and cavities.
#include "proxies/check/containment.h"

#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/box_intersection_d.h>
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/cgal/parity_solid_mesh.h"
#include "util/error.h"

namespace proxyvis {

namespace {

using cgal::Kernel;
using Point = cgal::Point3;
using Segment3 = Kernel::Segment_3;
using Triangle3 = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
namespace PMP = CGAL::Polygon_mesh_processing;

// A mesh prepared for the exact tests.
struct ExactMesh {
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> faces;
  bool closed = false;      // every welded edge has an even number of faces
  cgal::ParitySolid solid;  // the same triangles, for point location by ray parity
};

// `positions`, when given, replaces the mesh's float vertices (another reading of its file).
ExactMesh prepare(const TriMesh& mesh, const char* role,
                  const std::vector<Vec3d>* positions = nullptr) {
  if (mesh.empty())
    throw Error(mesh.source, fmt::format("the {} has no triangles", role),
                "containment needs two non-empty surfaces");
  if (positions && positions->size() != mesh.vertices.size())
    throw Error(
        mesh.source, fmt::format("the {}'s second reading has another vertex count", role),
        fmt::format("{} positions for {} vertices", positions->size(), mesh.vertices.size()));
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!isFinite(mesh.vertices[i]) || (positions && !isFinite((*positions)[i])))
      throw Error(mesh.source, fmt::format("the {} has a non-finite vertex", role),
                  "exact predicates need finite coordinates");
  for (const Triangle& t : mesh.triangles)
    for (uint32_t i : t)
      if (i >= mesh.vertices.size())
        throw Error(mesh.source, fmt::format("the {} has a vertex index out of range", role));
  auto [points, polygons] = cgal::toSoup<std::vector<std::size_t>>(mesh);
  if (positions)
    for (size_t i = 0; i < points.size(); ++i) points[i] = cgal::toPoint((*positions)[i]);
  // Closed = bounds a volume by ray parity. Built from the unrepaired triangles: duplicated faces
  // count modulo 2 there, which repair_polygon_soup's merge would not respect.
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(polygons.size());
  for (const auto& p : polygons) triangles.push_back({p[0], p[1], p[2]});
  ExactMesh m;
  m.solid = cgal::makeParitySolid(points, std::move(triangles));
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty())
    throw Error(mesh.source, fmt::format("the {} has only degenerate triangles", role),
                "containment needs a surface");
  m.points = std::move(points);
  m.closed = m.solid.watertight();
  m.faces.reserve(polygons.size());
  for (const auto& p : polygons) m.faces.push_back({p[0], p[1], p[2]});
  return m;
}

Triangle3 triangleOf(const ExactMesh& m, std::size_t f) {
  const auto& t = m.faces[f];
  return {m.points[t[0]], m.points[t[1]], m.points[t[2]]};
}

// Exact intersection of two (possibly degenerate, i.e. collinear) triangles. A degenerate
// triangle is the union of its edges; edges have positive length after welding.
bool trianglesIntersect(const Triangle3& a, const Triangle3& b) {
  const bool da = a.is_degenerate(), db = b.is_degenerate();
  if (!da && !db) return CGAL::do_intersect(a, b);
  auto edges = [](const Triangle3& t) {
    return std::array<Segment3, 3>{Segment3(t[0], t[1]), Segment3(t[1], t[2]),
                                   Segment3(t[2], t[0])};
  };
  if (da && db) {
    for (const Segment3& s : edges(a))
      for (const Segment3& r : edges(b))
        if (CGAL::do_intersect(s, r)) return true;
    return false;
  }
  const Triangle3& degenerate = da ? a : b;
  const Triangle3& proper = da ? b : a;
  for (const Segment3& s : edges(degenerate))
    if (CGAL::do_intersect(s, proper)) return true;
  return false;
}

// Each face's box, grown by `margin` on every side.
std::vector<Box> faceBoxes(const ExactMesh& m, double margin = 0) {
  std::vector<Box> boxes;
  boxes.reserve(m.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    boxes.emplace_back(cgal::grownBox(triangleOf(m, f).bbox(), margin), f);
  return boxes;
}

// Squared distance between two triangles that do not intersect, either possibly degenerate (a
// degenerate one is the union of its edges). Double arithmetic (CGAL's distance functions on
// Epick): relative error of a few ulps of the coordinates, far below any clearance it is
// compared with.
double triangleDistance2(const Triangle3& a, const Triangle3& b) {
  auto edges = [](const Triangle3& t) {
    return std::array<Segment3, 3>{Segment3(t[0], t[1]), Segment3(t[1], t[2]),
                                   Segment3(t[2], t[0])};
  };
  const bool da = a.is_degenerate(), db = b.is_degenerate();
  if (!da && !db) return CGAL::to_double(CGAL::squared_distance(a, b));
  double best = std::numeric_limits<double>::infinity();
  if (da && db) {
    for (const Segment3& s : edges(a))
      for (const Segment3& r : edges(b))
        best = std::min(best, CGAL::to_double(CGAL::squared_distance(s, r)));
    return best;
  }
  const Triangle3& proper = da ? b : a;
  for (const Segment3& s : edges(da ? a : b)) {
    best = std::min(best, CGAL::to_double(CGAL::squared_distance(s.source(), proper)));
    for (const Segment3& r : edges(proper))
      best = std::min(best, CGAL::to_double(CGAL::squared_distance(s, r)));
  }
  return best;
}

// The least distance between two surfaces that do not intersect, or `cap` when no two faces
// come closer than that: box_intersection_d pairs the faces whose boxes, grown by `cap`,
// overlap, and only those pairs are measured.
double surfaceSeparation(const ExactMesh& original, const ExactMesh& proxy, double cap) {
  std::vector<Box> a = faceBoxes(original, cap), b = faceBoxes(proxy);
  double best2 = cap * cap;
  auto callback = [&](const Box& ba, const Box& bb) {
    best2 = std::min(
        best2, triangleDistance2(triangleOf(original, ba.info()), triangleOf(proxy, bb.info())));
  };
  CGAL::box_intersection_d(a.begin(), a.end(), b.begin(), b.end(), callback);
  return std::sqrt(best2);
}

struct IntersectionSummary {
  uint64_t pairs = 0;
  // The lexicographically first intersecting (original face, proxy face): deterministic.
  std::size_t first_original = std::numeric_limits<std::size_t>::max(), first_proxy = 0;
};

IntersectionSummary intersectSurfaces(const ExactMesh& original, const ExactMesh& proxy) {
  std::vector<Box> a = faceBoxes(original), b = faceBoxes(proxy);
  IntersectionSummary s;
  auto callback = [&](const Box& ba, const Box& bb) {
    const std::size_t fa = ba.info(), fb = bb.info();
    if (!trianglesIntersect(triangleOf(original, fa), triangleOf(proxy, fb))) return;
    ++s.pairs;
    if (std::pair(fa, fb) < std::pair(s.first_original, s.first_proxy)) {
      s.first_original = fa;
      s.first_proxy = fb;
    }
  };
  // Closed boxes: touching boxes are reported, so touching triangles are found.
  CGAL::box_intersection_d(a.begin(), a.end(), b.begin(), b.end(), callback);
  return s;
}

// How many points of `m` lie strictly inside the closed `solid`, and one that does not
// (or does) for the report.
struct InsideCount {
  std::size_t inside = 0, total = 0;
  std::optional<Point> example_outside, example_inside;
};

InsideCount countInside(const ExactMesh& m, const ExactMesh& solid) {
  const cgal::ParityLocator side(solid.solid.mesh);
  InsideCount c;
  c.total = m.points.size();
  for (const Point& p : m.points) {
    if (side(p) == CGAL::ON_BOUNDED_SIDE) {
      ++c.inside;
      if (!c.example_inside) c.example_inside = p;
    } else if (!c.example_outside) {
      c.example_outside = p;
    }
  }
  return c;
}

std::string str(const Point& p) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z());
}

}  // namespace

const char* containmentName(ContainmentVerdict v) {
  switch (v) {
    case ContainmentVerdict::kContains:
      return "contains";
    case ContainmentVerdict::kContained:
      return "contained";
    case ContainmentVerdict::kIntersecting:
      return "intersecting";
    case ContainmentVerdict::kDisjoint:
      return "disjoint";
    case ContainmentVerdict::kUndecidable:
      return "undecidable";
  }
  return "undecidable";
}

ContainmentResult checkContainment(const TriMesh& original, const TriMesh& proxy,
                                   const ContainmentOptions& options) {
  ContainmentResult r;
  ExactMesh o = prepare(original, "original", options.original_positions);
  ExactMesh p = prepare(proxy, "proxy");
  r.original_closed = o.closed;
  r.proxy_closed = p.closed;
  if (o.closed) r.original_volume = cgal::signedVolume(o.solid.mesh);
  if (p.closed) r.proxy_volume = cgal::signedVolume(p.solid.mesh);
  if (!p.closed) {
    r.verdict = ContainmentVerdict::kUndecidable;
    r.detail =
        "the proxy is not closed (a boundary edge, or an edge with an odd number of faces): it "
        "has no inside, so containment is undefined";
    return r;
  }
  IntersectionSummary s = intersectSurfaces(o, p);
  if (s.pairs > 0) {
    r.verdict = ContainmentVerdict::kIntersecting;
    r.intersecting_face_pairs = s.pairs;
    const Triangle3 t = triangleOf(o, s.first_original);
    r.detail = fmt::format(
        "{} intersecting (or touching) face pairs; e.g. original face near {} meets proxy face "
        "near {}",
        s.pairs, str(CGAL::centroid(t)), str(CGAL::centroid(triangleOf(p, s.first_proxy))));
    return r;
  }
  if (options.separation_cap > 0) r.separation = surfaceSeparation(o, p, options.separation_cap);
  const InsideCount o_in_p = countInside(o, p);
  const bool all_inside = o_in_p.inside == o_in_p.total;
  if (!o.closed) {
    if (all_inside) {
      r.verdict = ContainmentVerdict::kContains;
      r.detail = "no surface intersection; every vertex of the open original is inside the proxy";
    } else if (o_in_p.inside == 0) {
      r.verdict = ContainmentVerdict::kDisjoint;
      r.detail = fmt::format(
          "no surface intersection and no original vertex inside the proxy "
          "(e.g. {}): mismatched pair?",
          str(*o_in_p.example_outside));
    } else {
      r.verdict = ContainmentVerdict::kUndecidable;
      r.detail = fmt::format(
          "the original is open and only {} of its {} vertices are inside the proxy (outside: "
          "e.g. {}); an open original cannot contain the proxy",
          o_in_p.inside, o_in_p.total, str(*o_in_p.example_outside));
    }
    return r;
  }
  const InsideCount p_in_o = countInside(p, o);
  if (all_inside && p_in_o.inside == 0) {
    r.verdict = ContainmentVerdict::kContains;
    r.detail = "no surface intersection; the original lies inside the proxy";
  } else if (p_in_o.inside == p_in_o.total && o_in_p.inside == 0) {
    r.verdict = ContainmentVerdict::kContained;
    r.detail = "no surface intersection; the proxy lies inside the original";
  } else {
    r.verdict = ContainmentVerdict::kDisjoint;
    r.detail = fmt::format(
        "no surface intersection, but neither lies inside the other: {} of {} original vertices "
        "inside the proxy, {} of {} proxy vertices inside the original{}",
        o_in_p.inside, o_in_p.total, p_in_o.inside, p_in_o.total,
        o_in_p.inside == 0 && p_in_o.inside == 0 ? " (mismatched pair?)" : "");
  }
  return r;
}

}  // namespace proxyvis
