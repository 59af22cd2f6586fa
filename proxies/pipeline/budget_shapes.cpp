// Boxes and tetrahedra for the face-budget ladder. An enclosing shape contains the input's
// vertices, hence their convex hull, hence the input; an inscribed one lies in a ball of the
// interior, hence inside. Both are verified exactly by the caller anyway.
#include "proxies/pipeline/budget_shapes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/optimal_bounding_box.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "proxies/shared/cgal/weld.h"

namespace proxyvis {
namespace {

using cgal::Kernel;
using cgal::Point3;
using cgal::SurfaceMesh;
using Transform = Kernel::Aff_transformation_3;

// A rotation as three orthonormal rows: frame coordinates = rows · world point.
struct Frame {
  std::array<Vec3d, 3> axis{Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  Vec3d toFrame(const Vec3d& p) const {
    return {dot(axis[0], p), dot(axis[1], p), dot(axis[2], p)};
  }
  Vec3d toWorld(const Vec3d& q) const { return axis[0] * q.x + axis[1] * q.y + axis[2] * q.z; }
};

// The frame of CGAL's optimal oriented bounding box (deterministic seed).
Frame boxFrame(const TriMesh& input) {
  // CGAL needs 4 points (and says so on stderr otherwise): a smaller input keeps the axes.
  if (input.vertices.size() < 4) return Frame();
  std::vector<Point3> points;
  points.reserve(input.vertices.size());
  for (const Vec3f& v : input.vertices) points.emplace_back(v.x, v.y, v.z);
  Transform t;
  CGAL::oriented_bounding_box(points, t, CGAL::parameters::random_seed(1));
  Frame f;
  for (int r = 0; r < 3; ++r) {
    Vec3d row(t.m(r, 0), t.m(r, 1), t.m(r, 2));
    f.axis[r] = normalize(row);
  }
  // Re-orthonormalise (the transformation is a rotation up to rounding).
  f.axis[1] = normalize(f.axis[1] - f.axis[0] * dot(f.axis[0], f.axis[1]));
  f.axis[2] = cross(f.axis[0], f.axis[1]);
  return f;
}

// Outward margin in world units: the requested fraction of the diagonal, and at least a few
// float ulps of the largest coordinate (the corners are rounded to float).
// The input's bounding box in the frame's coordinates.
std::pair<Vec3d, Vec3d> extentInFrame(const TriMesh& input, const Frame& f) {
  const double inf = std::numeric_limits<double>::infinity();
  Vec3d lo(inf, inf, inf), hi(-inf, -inf, -inf);
  for (const Vec3f& v : input.vertices) {
    const Vec3d q = f.toFrame(Vec3d(v));
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], q[a]);
      hi[a] = std::max(hi[a], q[a]);
    }
  }
  return {lo, hi};
}

double worldMargin(const TriMesh& input, double margin) {
  double max_abs = 0;
  for (const Vec3f& v : input.vertices)
    max_abs =
        std::max({max_abs, double(std::fabs(v.x)), double(std::fabs(v.y)), double(std::fabs(v.z))});
  return std::max(margin * input.diagonal(), 1e-6 * max_abs);
}

// Turns every face of a convex polytope away from the point `inner`.
void orientAway(TriMesh& mesh, const Vec3d& inner) {
  for (Triangle& t : mesh.triangles) {
    const Vec3d a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
    if (dot(cross(b - a, c - a), a - inner) < 0) std::swap(t[1], t[2]);
  }
}

TriMesh boxMesh(const Frame& f, const Vec3d& lo, const Vec3d& hi, const std::string& source) {
  TriMesh box;
  box.source = source;
  for (int c = 0; c < 8; ++c) {
    const Vec3d q((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const Vec3d p = f.toWorld(q);
    box.vertices.emplace_back(float(p.x), float(p.y), float(p.z));
  }
  // Two triangles per side; corner bit `axis` fixed to `side`.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      std::array<uint32_t, 4> q{};
      int m = 0;
      for (uint32_t c = 0; c < 8; ++c)
        if (((c >> axis) & 1) == uint32_t(side)) q[m++] = c;
      // q[0], q[3] are diagonal: (q0, q1, q3) and (q0, q3, q2) cover the square.
      box.triangles.push_back({q[0], q[1], q[3]});
      box.triangles.push_back({q[0], q[3], q[2]});
    }
  orientAway(box, f.toWorld((lo + hi) * 0.5));
  return box;
}

TriMesh tetMesh(const std::array<Vec3d, 4>& p, const std::string& source) {
  TriMesh tet;
  tet.source = source;
  Vec3d centre(0, 0, 0);
  for (const Vec3d& v : p) {
    tet.vertices.emplace_back(float(v.x), float(v.y), float(v.z));
    centre += v * 0.25;
  }
  tet.triangles = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  orientAway(tet, centre);
  return tet;
}

// The point on the three planes n_i · x = d_i (Cramer's rule); nullopt when they meet in no
// single point.
std::optional<Vec3d> meet(const Vec3d& n0, double d0, const Vec3d& n1, double d1, const Vec3d& n2,
                          double d2) {
  const double det = dot(n0, cross(n1, n2));
  if (!(std::fabs(det) > 1e-300)) return std::nullopt;
  return (cross(n1, n2) * d0 + cross(n2, n0) * d1 + cross(n0, n1) * d2) / det;
}

double tetVolume(const std::array<Vec3d, 4>& p) {
  return std::fabs(dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]))) / 6;
}

}  // namespace

TriMesh enclosingBox(const TriMesh& input, double margin) {
  const Frame f = boxFrame(input);
  const double m = worldMargin(input, margin);
  auto [lo, hi] = extentInFrame(input, f);
  for (int a = 0; a < 3; ++a) {
    lo[a] -= m;
    hi[a] += m;
  }
  return boxMesh(f, lo, hi, "box around " + input.source);
}

TriMesh enclosingTetrahedron(const TriMesh& input, double margin) {
  const double m = worldMargin(input, margin);
  std::optional<std::array<Vec3d, 4>> best;
  double best_volume = std::numeric_limits<double>::infinity();
  for (const Frame& f : {boxFrame(input), Frame()}) {
    // Extents in the frame: the regular tetrahedron's normals, and the same stretched to the
    // box's proportions (an affine image of the regular one, for elongated inputs).
    const auto [lo, hi] = extentInFrame(input, f);
    const Vec3d extent = hi - lo;
    const double emax = std::max({extent.x, extent.y, extent.z});
    for (bool stretched : {false, true})
      for (double flip : {1.0, -1.0}) {
        std::array<Vec3d, 4> n{Vec3d(1, 1, 1), Vec3d(1, -1, -1), Vec3d(-1, 1, -1),
                               Vec3d(-1, -1, 1)};
        for (Vec3d& k : n) {
          if (stretched)
            for (int a = 0; a < 3; ++a) k[a] /= std::max(extent[a], 1e-3 * emax);
          k = normalize(f.toWorld(k * flip));
        }
        std::array<double, 4> d;
        d.fill(-std::numeric_limits<double>::infinity());
        for (const Vec3f& v : input.vertices)
          for (int i = 0; i < 4; ++i) d[i] = std::max(d[i], dot(n[i], Vec3d(v)));
        for (double& di : d) di += m;
        std::array<Vec3d, 4> p;
        bool ok = true;
        for (int i = 0; i < 4 && ok; ++i) {
          const int a = (i + 1) % 4, b = (i + 2) % 4, c = (i + 3) % 4;
          const std::optional<Vec3d> x = meet(n[a], d[a], n[b], d[b], n[c], d[c]);
          ok = x.has_value();
          if (ok) p[i] = *x;
        }
        if (!ok) continue;
        const double volume = tetVolume(p);
        if (std::isfinite(volume) && volume < best_volume) {
          best_volume = volume;
          best = p;
        }
      }
  }
  if (!best) return {};
  return tetMesh(*best, "tetrahedron around " + input.source);
}

std::optional<InteriorBall> deepestInteriorPoint(const TriMesh& input) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  const SurfaceMesh sm = cgal::toWeldedMesh(input);
  if (sm.number_of_faces() == 0 || !CGAL::is_closed(sm)) return std::nullopt;
  Tree tree(faces(sm).first, faces(sm).second, sm);
  tree.accelerate_distance_queries();
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel> side(tree);
  auto depth = [&](const Vec3d& p) {
    const Point3 q(p.x, p.y, p.z);
    if (side(q) != CGAL::ON_BOUNDED_SIDE) return -1.0;
    return std::sqrt(tree.squared_distance(q));
  };
  // A grid of about 20 points along the longest side, then a local search around the best.
  const Bounds3f b = input.bounds();
  const Vec3d lo(b.lo), size = Vec3d(b.hi) - Vec3d(b.lo);
  const double step = std::max({size.x, size.y, size.z}) / 20;
  if (!(step > 0)) return std::nullopt;
  InteriorBall best;
  best.radius = -1;
  for (double z = lo.z + step / 2; z < lo.z + size.z; z += step)
    for (double y = lo.y + step / 2; y < lo.y + size.y; y += step)
      for (double x = lo.x + step / 2; x < lo.x + size.x; x += step) {
        const double d = depth({x, y, z});
        if (d > best.radius) best = {{x, y, z}, d};
      }
  if (!(best.radius > 0)) return std::nullopt;
  for (double s = step / 2; s > step / 64; s /= 2) {
    InteriorBall round = best;
    for (int c = 0; c < 27; ++c) {
      const Vec3d p = best.center + Vec3d(c % 3 - 1, c / 3 % 3 - 1, c / 9 - 1) * s;
      const double d = depth(p);
      if (d > round.radius) round = {p, d};
    }
    best = round;
  }
  return best;
}

TriMesh inscribedBox(const InteriorBall& ball, const std::string& source) {
  const double h = 0.98 * ball.radius / std::sqrt(3.0);
  Frame f;
  const Vec3d c = f.toFrame(ball.center), e(h, h, h);
  return boxMesh(f, c - e, c + e, "box inside " + source);
}

TriMesh inscribedTetrahedron(const InteriorBall& ball, const std::string& source) {
  const double r = 0.98 * ball.radius / std::sqrt(3.0);
  std::array<Vec3d, 4> p{Vec3d(1, 1, 1), Vec3d(1, -1, -1), Vec3d(-1, 1, -1), Vec3d(-1, -1, 1)};
  for (Vec3d& v : p) v = ball.center + v * r;
  return tetMesh(p, "tetrahedron inside " + source);
}

}  // namespace proxyvis
