// independent_double_check ORIGINAL PROXY --expect outside|inside
//
// A second opinion on a written class, sharing nothing with the product's check but CGAL itself:
// both files are read by CGAL's own readers in double precision (a text file's decimals as the
// nearest doubles, as a CAD tool reads them), not by proxyvis's float loaders, and the test uses
// other CGAL machinery than proxies/check/containment.cpp (an AABB tree of the original's
// triangles instead of box_intersection_d, ray parity with several random rays instead of
// Side_of_triangle_mesh).
//   outside: no proxy triangle meets an original triangle, every original vertex is inside the
//            proxy;
//   inside:  no proxy triangle meets an original triangle, every proxy vertex is inside the
//            original.
// Prints one line; exit 0 when the class holds, 1 when it does not, 2 when a file cannot be read.
// Used by the hard-set and clearance tests after proxy-gen wrote a proxy.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Ray = Kernel::Ray_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct Soup {
  std::vector<Point> points;
  std::vector<Triangle> triangles;  // non-degenerate ones (a degenerate one bounds nothing)
  std::vector<Point> used;          // each point a triangle uses, once
};

bool read(const char* file, Soup& soup) {
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(std::string(file), soup.points, polygons,
                                   CGAL::parameters::verbose(false)))
    return false;
  std::vector<bool> used(soup.points.size(), false);
  for (const auto& p : polygons) {
    if (p.size() != 3) return false;
    for (std::size_t i : p)
      if (i >= soup.points.size()) return false;
    const Triangle t(soup.points[p[0]], soup.points[p[1]], soup.points[p[2]]);
    if (t.is_degenerate()) continue;
    soup.triangles.push_back(t);
    for (std::size_t i : p) used[i] = true;
  }
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    if (used[i]) soup.used.push_back(soup.points[i]);
  return !soup.triangles.empty();
}

// Inside by ray parity: the number of triangles a ray from p crosses, odd = inside. A ray that
// grazes an edge or a vertex can count wrong, so three rays in random directions vote.
class ParityInside {
 public:
  explicit ParityInside(const Soup& solid) : tree_(solid.triangles.begin(), solid.triangles.end()) {
    tree_.accelerate_distance_queries();
  }
  bool operator()(const Point& p) {
    int odd = 0;
    for (int k = 0; k < 3; ++k) {
      std::normal_distribution<double> n;
      const Kernel::Vector_3 d(n(rng_), n(rng_), n(rng_));
      odd += tree_.number_of_intersected_primitives(Ray(p, d)) % 2;
    }
    return odd >= 2;
  }

 private:
  Tree tree_;
  std::mt19937_64 rng_{42};
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 || std::strcmp(argv[3], "--expect") != 0 ||
      (std::strcmp(argv[4], "outside") != 0 && std::strcmp(argv[4], "inside") != 0)) {
    std::fprintf(stderr,
                 "usage: independent_double_check ORIGINAL PROXY --expect outside|inside\n");
    return 2;
  }
  const bool outside = std::strcmp(argv[4], "outside") == 0;
  Soup original, proxy;
  if (!read(argv[1], original) || !read(argv[2], proxy)) {
    std::fprintf(stderr, "independent_double_check: cannot read %s or %s as triangles\n", argv[1],
                 argv[2]);
    return 2;
  }
  const Tree original_tree(original.triangles.begin(), original.triangles.end());
  std::size_t crossing = 0;
  for (const Triangle& t : proxy.triangles)
    if (original_tree.do_intersect(t)) ++crossing;
  if (crossing > 0) {
    std::printf("FAIL: %zu proxy triangles meet the original (double reading)\n", crossing);
    return 1;
  }
  // Only the vertices that triangles use (a stray scan point of the original bounds nothing).
  ParityInside inside(outside ? proxy : original);
  const std::vector<Point>& tested = (outside ? original : proxy).used;
  std::size_t wrong = 0;
  for (const Point& p : tested)
    if (!inside(p)) ++wrong;
  if (wrong > 0) {
    std::printf("FAIL: %zu of %zu %s vertices are not inside the %s\n", wrong, tested.size(),
                outside ? "original" : "proxy", outside ? "proxy" : "original");
    return 1;
  }
  std::printf("OK: %s holds in the double reading: no crossing, %zu vertices inside\n", argv[4],
              tested.size());
  return 0;
}
