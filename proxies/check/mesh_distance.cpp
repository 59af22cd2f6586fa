// Closest-point queries on a CGAL AABB tree of triangles (Alliez, Tayeb, Wormser, "3D Fast
// Intersection and Distance Computation", CGAL manual).
#include "proxies/check/mesh_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
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

}  // namespace

double sampledOneSidedDistance(const TriMesh& from, const TriMesh& to, uint64_t samples,
                               uint64_t seed) {
  const std::vector<Triangle3> src = trianglesOf(from), dst = trianglesOf(to);
  if (src.empty() || dst.empty())
    throw Error(src.empty() ? from.source : to.source, "no non-degenerate triangles",
                "a surface distance needs a surface");
  Tree tree(dst.begin(), dst.end());
  tree.accelerate_distance_queries();
  // Cumulative areas for area-uniform sampling.
  std::vector<double> cdf(src.size());
  double total = 0;
  for (size_t i = 0; i < src.size(); ++i) cdf[i] = total += std::sqrt(src[i].squared_area());
  auto distance2 = [&](const Point& q) { return tree.squared_distance(q); };
  double max2 = tbb::parallel_reduce(
      tbb::blocked_range<uint64_t>(0, samples + src.size()), 0.0,
      [&](const tbb::blocked_range<uint64_t>& r, double m) {
        for (uint64_t i = r.begin(); i < r.end(); ++i) {
          Point q;
          if (i < samples) {
            Rng rng(seed, i);
            const double u = rng.uniformDouble() * total;
            const size_t t = std::min<size_t>(
                std::lower_bound(cdf.begin(), cdf.end(), u) - cdf.begin(), src.size() - 1);
            double a = rng.uniformDouble(), b = rng.uniformDouble();
            if (a + b > 1) a = 1 - a, b = 1 - b;
            const Triangle3& tri = src[t];
            q = tri[0] + a * (tri[1] - tri[0]) + b * (tri[2] - tri[0]);
          } else {
            q = src[i - samples][0];  // every vertex (of a non-degenerate triangle)
          }
          m = std::max(m, distance2(q));
        }
        return m;
      },
      [](double a, double b) { return std::max(a, b); });
  return std::sqrt(max2);
}

}  // namespace proxyvis
