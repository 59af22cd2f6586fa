#pragma once
// Procedural meshes for the trace tests, each with a reason to exist.
#include <cstdint>

#include "mesh/tri_mesh.h"
#include "trace/trace_scene.h"

namespace proxyvis::test {

// Closed sphere: an icosahedron subdivided `levels` times and pushed onto the sphere
// (20 * 4^levels triangles). Shared vertices, so rays near edges hit neighbouring triangles.
TriMesh icosphere(int levels, const Vec3f& center = {}, float radius = 1);
// Axis-aligned closed box, 12 triangles: large triangles with long shared diagonals.
TriMesh box(const Vec3f& lo, const Vec3f& hi);
// `n` random triangles in [lo, hi]^3, sizes up to `size`: open, overlapping and intersecting,
// every orientation (what a closed mesh never tests).
TriMesh triangleSoup(uint32_t n, const Vec3f& lo, const Vec3f& hi, float size, uint64_t seed);

// The mesh with `xf` applied to every vertex (what an instance should be equivalent to).
TriMesh transformed(const TriMesh& mesh, const Affine3f& xf);
// Rotation by `angle` radians about the unit `axis`, then uniform `scale` (negative mirrors),
// then translation.
Affine3f makeTransform(const Vec3f& axis, float angle, float scale, const Vec3f& translation);

// Segment i of `seed` with both endpoints uniform in `box` (tnear 0, tfar 1, dir = end - start),
// the distribution of the throughput numbers.
Segment randomSegment(const Bounds3f& box, uint64_t seed, uint64_t i);
// `bounds` grown by `fraction` of its extent on every side.
Bounds3f grown(const Bounds3f& bounds, float fraction);

}  // namespace proxyvis::test
