// Closest-point queries on a CGAL AABB tree of triangles (Alliez, Tayeb, Wormser, "3D Fast
// Intersection and Distance Computation", CGAL manual).
#include "proxies/check/mesh_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Sphere3 = Kernel::Sphere_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

std::vector<Triangle3> trianglesOf(const TriMesh& m) {
  std::vector<Triangle3> t;
  t.reserve(m.triangles.size());
  auto p = [&](uint32_t i) {
    const Vec3f& v = m.vertices[i];
    return Point(v.x, v.y, v.z);
  };
  for (const Triangle& f : m.triangles) {
    Triangle3 tri(p(f[0]), p(f[1]), p(f[2]));
    if (!tri.is_degenerate()) t.push_back(tri);
  }
  return t;
}

// `samples` points uniform by area (Rng(seed, i)), then the first vertex of every triangle;
// the samples ordered by their triangle, so that consecutive queries visit the same part of the
// tree.
std::vector<Point> queryPoints(const std::vector<Triangle3>& src, uint64_t samples, uint64_t seed) {
  std::vector<double> cdf(src.size());
  double total = 0;
  for (size_t i = 0; i < src.size(); ++i) cdf[i] = total += std::sqrt(src[i].squared_area());
  std::vector<std::pair<size_t, Point>> sampled(samples);
  tbb::parallel_for(
      tbb::blocked_range<uint64_t>(0, samples), [&](const tbb::blocked_range<uint64_t>& r) {
        for (uint64_t i = r.begin(); i < r.end(); ++i) {
          Rng rng(seed, i);
          const double u = rng.uniformDouble() * total;
          const size_t t = std::min<size_t>(
              std::lower_bound(cdf.begin(), cdf.end(), u) - cdf.begin(), src.size() - 1);
          double a = rng.uniformDouble(), b = rng.uniformDouble();
          if (a + b > 1) a = 1 - a, b = 1 - b;
          const Triangle3& tri = src[t];
          sampled[i] = {t, tri[0] + a * (tri[1] - tri[0]) + b * (tri[2] - tri[0])};
        }
      });
  std::stable_sort(sampled.begin(), sampled.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Point> points;
  points.reserve(samples + src.size());
  for (const auto& s : sampled) points.push_back(s.second);
  for (const Triangle3& t : src) points.push_back(t[0]);  // every vertex of a non-degenerate one
  return points;
}

}  // namespace

double sampledOneSidedDistance(const TriMesh& from, const TriMesh& to, uint64_t samples,
                               uint64_t seed, MeshDistanceStats* stats) {
  const std::vector<Triangle3> src = trianglesOf(from), dst = trianglesOf(to);
  if (src.empty() || dst.empty())
    throw Error(src.empty() ? from.source : to.source, "no non-degenerate triangles",
                "a surface distance needs a surface");
  Tree tree(dst.begin(), dst.end());
  tree.accelerate_distance_queries();
  const std::vector<Point> points = queryPoints(src, samples, seed);

  // Only the largest distance matters: a point with some triangle of `to` within the running
  // maximum cannot raise it, and a sphere test on the tree (stops at the first triangle it
  // finds) says so far faster than a closest-point query. On a proxy near its original nearly
  // every point is settled that way (dragon to 2 %: 37 closest-point queries for 142 k points).
  // The result is the maximum of the closest-point distances over all points whatever the
  // threads do: a point is skipped only when a triangle is provably nearer than a maximum
  // already found (the sphere is shrunk by more than the rounding of its test).
  std::atomic<double> best2{0};
  std::atomic<uint64_t> tree_queries{0};
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
        uint64_t queried = 0;
        for (size_t i = r.begin(); i < r.end(); ++i) {
          const Point& q = points[i];
          double m = best2.load(std::memory_order_relaxed);
          const double r2 = m * (1 - 1e-9) - 1e-12 * (q - CGAL::ORIGIN).squared_length();
          if (r2 > 0 && tree.do_intersect(Sphere3(q, r2))) continue;
          ++queried;
          const double d2 = tree.squared_distance(q);
          while (d2 > m && !best2.compare_exchange_weak(m, d2)) {
          }
        }
        tree_queries += queried;
      });
  if (stats) *stats = {points.size(), tree_queries.load()};
  return std::sqrt(best2.load());
}

}  // namespace proxyvis
