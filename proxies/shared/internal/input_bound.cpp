// The swept-region test of input_bound.h. Condition (1) is CGAL's exact triangle-triangle test
// on an AABB tree of the input (touching counts, as in the final containment check). Given (1),
// an input component is either entirely between the stars or not at all, so (2) tests one
// vertex per component whose bounding box fits in the stars' box, by the winding number of the
// closed surface old star + reversed new star.
#include "proxies/shared/internal/input_bound.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <cmath>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/internal/touch_cache.h"
#include "util/disjoint_sets.h"

namespace proxyvis::cgal {
namespace {

using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Solid angle of triangle (a, b, c) seen from the origin (A. Van Oosterom, J. Strackee 1983).
double solidAngle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const double la = length(a), lb = length(b), lc = length(c);
  const double num = dot(a, cross(b, c));
  const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  return 2 * std::atan2(num, den);
}

// Tree traversal for "does this triangle touch any input triangle": a node is entered when
// the triangle's box overlaps it and its plane passes within the box (both cheap and
// conservative: a slack makes rounding answer "maybe"); only leaves get CGAL's exact test.
// CGAL's own traversal runs the exact triangle-box test at every node, 3-4 times slower here.
class TouchTraits {
 public:
  // `clearance` > 0: within that distance counts as touching (distances in double: see
  // proxies/check/containment.cpp).
  TouchTraits(const Triangle3& query, double clearance)
      : box_(grownBox(query.bbox(), clearance)), a_(query[0]), clearance_(clearance) {
    const Point3 &a = query[0], &b = query[1], &c = query[2];
    const double l = std::max(l1(b - a), l1(c - a));
    edge_l2_ = l * l;
    const Kernel::Vector_3 n = CGAL::cross_product(b - a, c - a);
    n_[0] = n.x();
    n_[1] = n.y();
    n_[2] = n.z();
    d_ = n_[0] * a.x() + n_[1] * a.y() + n_[2] * a.z();
    slack_ = 1e-9 * (std::abs(n_[0]) + std::abs(n_[1]) + std::abs(n_[2])) *
             (std::abs(a.x()) + std::abs(a.y()) + std::abs(a.z()) + box_.xmax() - box_.xmin() +
              box_.ymax() - box_.ymin() + box_.zmax() - box_.zmin());
    // The plane tests measure n.x - d, |n| times a distance: the clearance in those units.
    reach_ = clearance * std::sqrt(n_[0] * n_[0] + n_[1] * n_[1] + n_[2] * n_[2]);
  }
  bool go_further() const { return !hit_; }
  template <typename Primitive>
  void intersection(const Triangle3& q, const Primitive& p) {
    const Triangle3& t = p.datum();
    if (!CGAL::do_overlap(box_, t.bbox()) || clearlyOneSide(t)) return;
    if (CGAL::do_intersect(q, t) ||
        (clearance_ > 0 && CGAL::squared_distance(q, t) < clearance_ * clearance_))
      hit_ = true;
  }
  template <typename Node>
  bool do_intersect(const Triangle3&, const Node& node) const {
    const CGAL::Bbox_3& b = node.bbox();
    if (!CGAL::do_overlap(box_, b)) return false;
    const double c[3] = {(b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2,
                         (b.zmin() + b.zmax()) / 2};
    const double h[3] = {(b.xmax() - b.xmin()) / 2, (b.ymax() - b.ymin()) / 2,
                         (b.zmax() - b.zmin()) / 2};
    const double r = std::abs(n_[0]) * h[0] + std::abs(n_[1]) * h[1] + std::abs(n_[2]) * h[2];
    const double s = n_[0] * c[0] + n_[1] * c[1] + n_[2] * c[2] - d_;
    return std::abs(s) <= r + reach_ + slack_ + 1e-9 * std::abs(s);
  }
  bool hit() const { return hit_; }

 private:
  // The leaves come in pairs without their own box test, and most lie near the query's plane
  // without crossing it: when all three corners of t are on one side of the query's plane by
  // more than the rounding error can reach, the exact test would say no. The bound is loose on
  // purpose (1e-10 against a rounding error below 1e-14 of L^2 |p - a|, L the query's longest
  // edge from a in the L1 norm).
  bool clearlyOneSide(const Triangle3& t) const {
    int above = 0, below = 0;
    for (int i = 0; i < 3; ++i) {
      const Kernel::Vector_3 d = t[i] - a_;
      const double s = n_[0] * d.x() + n_[1] * d.y() + n_[2] * d.z();
      const double bound = 1e-10 * edge_l2_ * l1(d) + reach_;
      above += s > bound;
      below += s < -bound;
    }
    return above == 3 || below == 3;
  }
  static double l1(const Kernel::Vector_3& v) {
    return std::abs(v.x()) + std::abs(v.y()) + std::abs(v.z());
  }

  CGAL::Bbox_3 box_;
  Point3 a_;
  double n_[3], d_, slack_, edge_l2_, reach_ = 0, clearance_ = 0;
  bool hit_ = false;
};

struct Component {
  Bounds3d box;
  Vec3d vertex;
};

}  // namespace

struct InputBound::Impl {
  double clearance = 0;
  std::vector<Triangle3> triangles;
  TriangleTree tree;
  std::vector<Component> components;  // sorted by box diagonal, smallest first
  std::vector<double> diagonals;
  TouchCache cache;  // touches() is const to its callers; the cache only remembers answers
};

InputBound::InputBound(const TriMesh& input, double clearance) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.clearance = clearance;
  // Components by shared vertex indices (union-find).
  DisjointSets sets(input.vertices.size());
  m.triangles.reserve(input.triangles.size());
  for (const Triangle& t : input.triangles) {
    const Point3 a = toPoint(Vec3d(input.vertices[t[0]])), b = toPoint(Vec3d(input.vertices[t[1]])),
                 c = toPoint(Vec3d(input.vertices[t[2]]));
    if (!CGAL::collinear(a, b, c)) m.triangles.emplace_back(a, b, c);
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  m.tree.insert(m.triangles.begin(), m.triangles.end());
  m.tree.build();
  m.tree.accelerate_distance_queries();
  std::vector<int> slot(input.vertices.size(), -1);
  std::vector<bool> used(input.vertices.size(), false);
  for (const Triangle& t : input.triangles)
    for (uint32_t v : t) used[v] = true;
  for (uint32_t v = 0; v < input.vertices.size(); ++v) {
    if (!used[v]) continue;
    const uint32_t r = sets.find(v);
    if (slot[r] < 0) {
      slot[r] = int(m.components.size());
      m.components.push_back({{}, Vec3d(input.vertices[v])});
    }
    m.components[slot[r]].box.extend(Vec3d(input.vertices[v]));
  }
  std::sort(m.components.begin(), m.components.end(), [](const Component& a, const Component& b) {
    return a.box.diagonal() < b.box.diagonal();
  });
  for (const Component& c : m.components) m.diagonals.push_back(c.box.diagonal());
}

InputBound::~InputBound() = default;

bool InputBound::allows(const std::vector<std::array<Vec3d, 3>>& old_star,
                        const std::vector<std::array<Vec3d, 3>>& new_star,
                        size_t* first_touch) const {
  const Impl& m = *impl_;
  const size_t n_new = new_star.size();
  const size_t start = first_touch && *first_touch < n_new ? *first_touch : 0;
  for (size_t k = 0; k < n_new; ++k) {
    const size_t i = (start + k) % n_new;
    if (touches(new_star[i])) {
      if (first_touch) *first_touch = i;
      return false;
    }
  }
  Bounds3d box;
  for (const auto& t : new_star)
    for (const Vec3d& p : t) box.extend(p);
  for (const auto& t : old_star)
    for (const Vec3d& p : t) box.extend(p);
  // Only a component smaller than the stars' box can fit between them.
  const size_t n = size_t(std::upper_bound(m.diagonals.begin(), m.diagonals.end(), box.diagonal()) -
                          m.diagonals.begin());
  for (size_t i = 0; i < n; ++i) {
    const Component& c = m.components[i];
    bool inside_box = true;
    for (int k = 0; k < 3; ++k) inside_box &= c.box.lo[k] >= box.lo[k] && c.box.hi[k] <= box.hi[k];
    if (!inside_box) continue;
    double w = 0;
    for (const auto& t : old_star)
      w += solidAngle(t[0] - c.vertex, t[1] - c.vertex, t[2] - c.vertex);
    for (const auto& t : new_star)
      w -= solidAngle(t[0] - c.vertex, t[1] - c.vertex, t[2] - c.vertex);
    if (std::abs(w) > 2 * M_PI) return false;  // winding number beyond 1/2
  }
  return true;
}

bool InputBound::touches(const std::array<Vec3d, 3>& t) const {
  const TouchCache::Key key = TouchCache::keyOf(t);
  if (const std::optional<bool> known = impl_->cache.find(key)) return *known;
  const Triangle3 tri(toPoint(t[0]), toPoint(t[1]), toPoint(t[2]));
  bool hit = tri.is_degenerate();
  if (!hit) {
    TouchTraits touch(tri, impl_->clearance);
    impl_->tree.traversal(tri, touch);
    hit = touch.hit();
  }
  impl_->cache.store(key, hit);
  return hit;
}

Vec3d InputBound::closestPoint(const Vec3d& p) const {
  const Point3 q = impl_->tree.closest_point(toPoint(p));
  return {q.x(), q.y(), q.z()};
}

}  // namespace proxyvis::cgal
