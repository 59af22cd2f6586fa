#pragma once
// Tiny synthetic meshes for the proxy-check tests: closed shapes whose containment relations are
// known by construction, so the tests do not depend on the proxy generators.
#include "mesh/primitives.h"
#include "mesh/tri_mesh.h"

namespace proxyvis::test {

// Closed, outward-oriented axis-aligned box [lo, hi] (12 triangles).
inline TriMesh makeBox(Vec3f lo, Vec3f hi, const char* source = "box") {
  return makeBoxMesh(lo, hi, source);
}

// Closed UV sphere (slices x stacks quads, poles as fans), outward-oriented.
inline TriMesh makeSphere(Vec3f center, float radius, int slices = 24, int stacks = 12,
                          const char* source = "sphere") {
  return makeUvSphere(center, radius, slices, stacks, source);
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
