// InputBound::touches remembers its answers (proxies/shared/internal/touch_cache.h): a
// remembered answer must be the one a fresh test gives, for the same triangle in any corner
// order, and a slot shared by two triangles must never answer for the wrong one.
#include <CGAL/intersections.h>

#include <gtest/gtest.h>

#include <random>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/internal/touch_cache.h"
#include "tests/proxies/check/check_shapes.h"

namespace proxyvis {
namespace {

using Tri = std::array<Vec3d, 3>;

// The answer without the tree or the cache: every input triangle, exactly.
bool touchesBruteForce(const TriMesh& input, const Tri& t) {
  using cgal::Point3;
  auto p = [](const Vec3d& v) { return Point3(v.x, v.y, v.z); };
  const cgal::Kernel::Triangle_3 q(p(t[0]), p(t[1]), p(t[2]));
  if (q.is_degenerate()) return true;
  for (const Triangle& f : input.triangles) {
    const cgal::Kernel::Triangle_3 u(p(Vec3d(input.vertices[f[0]])), p(Vec3d(input.vertices[f[1]])),
                                     p(Vec3d(input.vertices[f[2]])));
    if (!u.is_degenerate() && CGAL::do_intersect(q, u)) return true;
  }
  return false;
}

TEST(InputBoundTouches, RememberedAnswersEqualFreshOnesInAnyCornerOrder) {
  const TriMesh input = test::makeSphere({0, 0, 0}, 1.0f, 16, 8);
  const cgal::InputBound bound(input);
  // Small triangles around the sphere's surface: about a third cross it.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> dir(-1, 1), radius(0.9, 1.1), jitter(-0.08, 0.08);
  std::vector<Tri> queries;
  while (queries.size() < 1500) {
    Vec3d c(dir(rng), dir(rng), dir(rng));
    if (length(c) < 1e-3) continue;
    c = c / length(c) * radius(rng);
    Tri t;
    for (Vec3d& v : t) v = c + Vec3d(jitter(rng), jitter(rng), jitter(rng));
    queries.push_back(t);
  }
  queries.push_back({Vec3d(0, 0, 2), Vec3d(0, 0, 2), Vec3d(1, 0, 2)});  // degenerate: refused
  std::vector<bool> truth;
  size_t touching = 0;
  for (const Tri& t : queries) {
    truth.push_back(touchesBruteForce(input, t));
    touching += truth.back();
  }
  ASSERT_GT(touching, queries.size() / 10);
  ASSERT_LT(touching, queries.size() * 9 / 10);
  for (int pass = 0; pass < 3; ++pass)  // the first asks, the others are answered from memory
    for (size_t i = 0; i < queries.size(); ++i) {
      Tri t = queries[i];
      std::rotate(t.begin(), t.begin() + pass, t.end());
      if (pass == 2) std::swap(t[0], t[1]);
      ASSERT_EQ(bound.touches(t), truth[i]) << "query " << i << ", pass " << pass;
    }
}

TEST(TouchCache, ASharedSlotNeverAnswersForAnotherTriangle) {
  // Four times more triangles than slots: most slots are shared and overwritten.
  cgal::TouchCache cache;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<cgal::TouchCache::Key> keys;
  for (int i = 0; i < 4 * 65536; ++i) {
    const Tri t{Vec3d(u(rng), u(rng), u(rng)), Vec3d(u(rng), u(rng), u(rng)),
                Vec3d(u(rng), u(rng), u(rng))};
    keys.push_back(cgal::TouchCache::keyOf(t));
    EXPECT_EQ(keys.back(), cgal::TouchCache::keyOf({t[2], t[0], t[1]}));
    cache.store(keys.back(), i % 3 == 0);
  }
  size_t remembered = 0;
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::optional<bool> known = cache.find(keys[i]);
    if (!known) continue;
    ++remembered;
    ASSERT_EQ(*known, i % 3 == 0) << "key " << i;
  }
  // The last ones stored are still there; most of the early ones were overwritten.
  EXPECT_TRUE(cache.find(keys.back()).has_value());
  EXPECT_GT(remembered, 65536u / 2);
  EXPECT_LE(remembered, 65536u);
}

}  // namespace
}  // namespace proxyvis
