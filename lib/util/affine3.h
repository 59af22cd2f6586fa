#pragma once
// The affine transform of instances and scene placements: a value type shared by the scene
// format, the tracer and the renderer (helpers that compose and invert it: scene/transform.h).
#include "util/vec3.h"

namespace proxyvis {

// Row-major 3x4 affine transform (the upper three rows of a 4x4): p' = M * [p, 1].
struct Affine3f {
  float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  Vec3f apply(const Vec3f& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  // The translation (column 3) or the scaling (diagonal) by `v`.
  static Affine3f translation(const Vec3f& v) {
    Affine3f a;
    for (int i = 0; i < 3; ++i) a.m[i][3] = v[i];
    return a;
  }
  static Affine3f scaling(const Vec3f& v) {
    Affine3f a;
    for (int i = 0; i < 3; ++i) a.m[i][i] = v[i];
    return a;
  }
  bool isIdentity() const {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        if (m[i][j] != (i == j ? 1.0f : 0.0f)) return false;
    return true;
  }
};

}  // namespace proxyvis
