#include "test_meshes.h"

#include <cmath>
#include <map>
#include <utility>

#include "mesh/primitives.h"
#include "util/rng.h"

namespace proxyvis::test {

TriMesh icosphere(int levels, const Vec3f& center, float radius) {
  const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<Vec3f> v = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0},
                          {0, -1, p}, {0, 1, p}, {0, -1, -p}, {0, 1, -p},
                          {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3f& x : v) x = normalize(x);
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(normalize((v[a] + v[b]) * 0.5f));
      uint32_t id = uint32_t(v.size() - 1);
      mid.emplace(key, id);
      return id;
    };
    std::vector<Triangle> g;
    for (const Triangle& t : f) {
      uint32_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      g.push_back({t[0], a, c});
      g.push_back({t[1], b, a});
      g.push_back({t[2], c, b});
      g.push_back({a, b, c});
    }
    f = std::move(g);
  }
  TriMesh m;
  for (const Vec3f& x : v) m.vertices.push_back(center + x * radius);
  m.triangles = std::move(f);
  m.source = "icosphere";
  return m;
}

TriMesh box(const Vec3f& lo, const Vec3f& hi) {
  return makeBoxMesh(lo, hi);
}

TriMesh triangleSoup(uint32_t n, const Vec3f& lo, const Vec3f& hi, float size, uint64_t seed) {
  TriMesh m;
  Vec3f ext = hi - lo;
  for (uint32_t i = 0; i < n; ++i) {
    Rng rng(seed, i);
    Vec3f c(lo.x + ext.x * rng.uniformFloat(), lo.y + ext.y * rng.uniformFloat(),
            lo.z + ext.z * rng.uniformFloat());
    for (int k = 0; k < 3; ++k)
      m.vertices.push_back(c + Vec3f(rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f,
                                     rng.uniformFloat() - 0.5f) *
                                   size);
    m.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  m.source = "triangle soup";
  return m;
}

TriMesh transformed(const TriMesh& mesh, const Affine3f& xf) {
  TriMesh m = mesh;
  for (Vec3f& v : m.vertices) v = xf.apply(v);
  m.source = mesh.source + " (transformed)";
  return m;
}

Affine3f makeTransform(const Vec3f& axis, float angle, float scale, const Vec3f& translation) {
  // Rodrigues' rotation matrix.
  const float c = std::cos(angle), s = std::sin(angle), C = 1 - c;
  const float x = axis.x, y = axis.y, z = axis.z;
  const float r[3][3] = {{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
                         {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
                         {z * x * C - y * s, z * y * C + x * s, c + z * z * C}};
  Affine3f a;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a.m[i][j] = r[i][j] * scale;
    a.m[i][3] = translation[i];
  }
  return a;
}

Segment randomSegment(const Bounds3f& box, uint64_t seed, uint64_t i) {
  Rng rng(seed, i);
  Vec3f e = box.extent();
  Vec3f a(box.lo.x + e.x * rng.uniformFloat(), box.lo.y + e.y * rng.uniformFloat(),
          box.lo.z + e.z * rng.uniformFloat());
  Vec3f b(box.lo.x + e.x * rng.uniformFloat(), box.lo.y + e.y * rng.uniformFloat(),
          box.lo.z + e.z * rng.uniformFloat());
  return Segment::between(a, b);
}

Bounds3f grown(const Bounds3f& bounds, float fraction) {
  Bounds3f b = bounds;
  Vec3f d = bounds.extent() * fraction;
  b.lo -= d;
  b.hi += d;
  return b;
}

}  // namespace proxyvis::test
