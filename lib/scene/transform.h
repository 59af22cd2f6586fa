#pragma once
// Affine transform helpers the scene format and the renderer share: composing the JSON
// "transform" object, inverting instance transforms (to trace a segment in object space), and
// converting to and from the 12/16-number row-major forms of the files.
#include <cmath>
#include <optional>

#include "util/affine3.h"

namespace proxyvis {

// a * b (apply b first).
inline Affine3f compose(const Affine3f& a, const Affine3f& b) {
  Affine3f r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      float v = (j == 3) ? a.m[i][3] : 0.0f;
      for (int k = 0; k < 3; ++k) v += a.m[i][k] * b.m[k][j];
      r.m[i][j] = v;
    }
  return r;
}

// The linear part applied to a direction (no translation).
inline Vec3f applyLinear(const Affine3f& a, const Vec3f& d) {
  return {a.m[0][0] * d.x + a.m[0][1] * d.y + a.m[0][2] * d.z,
          a.m[1][0] * d.x + a.m[1][1] * d.y + a.m[1][2] * d.z,
          a.m[2][0] * d.x + a.m[2][1] * d.y + a.m[2][2] * d.z};
}

inline double determinant(const Affine3f& a) {
  const auto& m = a.m;
  return double(m[0][0]) * (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) -
         double(m[0][1]) * (double(m[1][0]) * m[2][2] - double(m[1][2]) * m[2][0]) +
         double(m[0][2]) * (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]);
}

// Inverse in double precision; nullopt when the linear part is singular (|det| below 1e-30 or
// not finite), which the scene loader reports as bad input.
inline std::optional<Affine3f> inverse(const Affine3f& a) {
  const double det = determinant(a);
  if (!std::isfinite(det) || std::abs(det) < 1e-30) return std::nullopt;
  const auto& m = a.m;
  double inv[3][3];
  inv[0][0] = (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) / det;
  inv[0][1] = (double(m[0][2]) * m[2][1] - double(m[0][1]) * m[2][2]) / det;
  inv[0][2] = (double(m[0][1]) * m[1][2] - double(m[0][2]) * m[1][1]) / det;
  inv[1][0] = (double(m[1][2]) * m[2][0] - double(m[1][0]) * m[2][2]) / det;
  inv[1][1] = (double(m[0][0]) * m[2][2] - double(m[0][2]) * m[2][0]) / det;
  inv[1][2] = (double(m[0][2]) * m[1][0] - double(m[0][0]) * m[1][2]) / det;
  inv[2][0] = (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]) / det;
  inv[2][1] = (double(m[0][1]) * m[2][0] - double(m[0][0]) * m[2][1]) / det;
  inv[2][2] = (double(m[0][0]) * m[1][1] - double(m[0][1]) * m[1][0]) / det;
  Affine3f r;
  for (int i = 0; i < 3; ++i) {
    double t = 0;
    for (int k = 0; k < 3; ++k) {
      r.m[i][k] = float(inv[i][k]);
      t -= inv[i][k] * m[k][3];
    }
    r.m[i][3] = float(t);
  }
  return r;
}

// Rotation by `degrees` about `axis` (need not be normalized; must be non-zero).
inline Affine3f rotation(Vec3f axis, float degrees) {
  const Vec3d u = normalize(Vec3d(axis));
  const double a = double(degrees) * 3.14159265358979323846 / 180.0;
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  Affine3f r;
  const double rm[3][3] = {{t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y},
                           {t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x},
                           {t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = float(rm[i][j]);
  return r;
}

// The box around `b`'s eight corners under `a` (encloses everything `b` held).
inline Bounds3f transformedBounds(const Bounds3f& b, const Affine3f& a) {
  Bounds3f out;
  for (int i = 0; i < 8; ++i)
    out.extend(
        a.apply({(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z}));
  return out;
}

inline bool operator==(const Affine3f& a, const Affine3f& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (a.m[i][j] != b.m[i][j]) return false;
  return true;
}

}  // namespace proxyvis
