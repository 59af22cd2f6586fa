#pragma once
// Tiny synthetic meshes for the proxy-check tests: closed shapes whose containment relations are
// known by construction, so the tests do not depend on the proxy generators.
#include <cmath>
#include <numbers>

#include "mesh/tri_mesh.h"

namespace proxyvis::test {

// Closed, outward-oriented axis-aligned box [lo, hi] (12 triangles).
inline TriMesh makeBox(Vec3f lo, Vec3f hi, const char* source = "box") {
  TriMesh m;
  m.source = source;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  // Faces as quads (a, b, c, d) counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])});
    m.triangles.push_back({uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])});
  }
  return m;
}

// Closed UV sphere (slices x stacks quads, poles as fans), outward-oriented.
inline TriMesh makeSphere(Vec3f center, float radius, int slices = 24, int stacks = 12,
                          const char* source = "sphere") {
  TriMesh m;
  m.source = source;
  const float pi = std::numbers::pi_v<float>;
  m.vertices.push_back(center + Vec3f(0, 0, radius));  // north pole
  for (int i = 1; i < stacks; ++i) {
    const float theta = pi * float(i) / float(stacks);
    for (int j = 0; j < slices; ++j) {
      const float phi = 2 * pi * float(j) / float(slices);
      m.vertices.push_back(center + radius * Vec3f(std::sin(theta) * std::cos(phi),
                                                   std::sin(theta) * std::sin(phi),
                                                   std::cos(theta)));
    }
  }
  const uint32_t south = uint32_t(m.vertices.size());
  m.vertices.push_back(center + Vec3f(0, 0, -radius));
  auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * slices + (j % slices)); };
  for (int j = 0; j < slices; ++j) m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < slices; ++j)
    m.triangles.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  return m;
}

// A copy of `m` scaled by `s` about `center` and then moved by `shift`.
inline TriMesh transformed(const TriMesh& m, Vec3f center, float s, Vec3f shift,
                           const char* source) {
  TriMesh r = m;
  r.source = source;
  for (Vec3f& v : r.vertices) v = center + s * (v - center) + shift;
  return r;
}

// `m` with its last triangle removed: an open surface with a 3-edge hole.
inline TriMesh withHole(const TriMesh& m, const char* source) {
  TriMesh r = m;
  r.source = source;
  r.triangles.pop_back();
  return r;
}

}  // namespace proxyvis::test
