#pragma once
// Closed, outward-oriented meshes from a few parameters: axis-aligned boxes and UV spheres. Tests
// and benchmarks use them as originals and as synthetic proxies whose containment is known by
// construction.
#include <cmath>
#include <numbers>
#include <string>

#include "mesh/tri_mesh.h"

namespace proxyvis {

// The box [lo, hi]: 8 vertices (corner i takes hi on axis k when bit k of i is set) and 12
// triangles, counter-clockwise seen from outside.
inline TriMesh makeBoxMesh(const Vec3f& lo, const Vec3f& hi, std::string source = "box") {
  TriMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  m.source = std::move(source);
  return m;
}

// UV sphere with vertices on the sphere: `slices` (>= 3) around the z axis, `stacks` (>= 2) from
// pole to pole, the poles as triangle fans; 2 * slices * (stacks - 1) triangles. Its faces lie
// within radius * cos(pi / slices) * cos(pi / stacks) of the center at the closest.
inline TriMesh makeUvSphere(const Vec3f& center, float radius, int slices, int stacks,
                            std::string source = "sphere") {
  TriMesh m;
  m.source = std::move(source);
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

}  // namespace proxyvis
