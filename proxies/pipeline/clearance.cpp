#include "proxies/pipeline/clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "proxies/shared/plane_lp.h"

namespace proxyvis {

double floatUlp(double magnitude) {
  const float m = float(std::min(std::abs(magnitude), double(std::numeric_limits<float>::max())));
  if (m < std::numeric_limits<float>::min()) return std::numeric_limits<float>::denorm_min();
  int exponent = 0;
  std::frexp(m, &exponent);  // m = f * 2^exponent, f in [0.5, 1)
  return std::ldexp(1.0, exponent - std::numeric_limits<float>::digits);
}

double largestCoordinate(const TriMesh& mesh) {
  double m = 0;
  for (const Vec3f& v : mesh.vertices)
    m = std::max({m, std::abs(double(v.x)), std::abs(double(v.y)), std::abs(double(v.z))});
  return m;
}

double clearanceDistance(const TriMesh& input, std::optional<double> distance,
                         std::optional<double> ulps, const std::vector<Affine3f>& placements) {
  if (distance) return *distance;
  const double k = ulps.value_or(kDefaultClearanceUlps);
  double clearance = k * floatUlp(largestCoordinate(input));
  for (const Affine3f& t : placements)
    clearance = std::max(clearance, placementClearance(input, t, k));
  return clearance;
}

namespace {

// The smallest singular value of the transform's linear part: the square root of the smallest
// eigenvalue of A^T A, by the closed form for symmetric 3x3 matrices (O. K. Smith, "Eigenvalues
// of a symmetric 3x3 matrix", CACM 4(4), 1961).
double smallestSingularValue(const Affine3f& t) {
  double b[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      b[i][j] = 0;
      for (int k = 0; k < 3; ++k) b[i][j] += double(t.m[k][i]) * double(t.m[k][j]);
    }
  const double off = b[0][1] * b[0][1] + b[0][2] * b[0][2] + b[1][2] * b[1][2];
  double least;
  if (off == 0) {
    least = std::min({b[0][0], b[1][1], b[2][2]});
  } else {
    const double q = (b[0][0] + b[1][1] + b[2][2]) / 3;
    const double p2 = (b[0][0] - q) * (b[0][0] - q) + (b[1][1] - q) * (b[1][1] - q) +
                      (b[2][2] - q) * (b[2][2] - q) + 2 * off;
    const double p = std::sqrt(p2 / 6);
    double c[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i][j] = (b[i][j] - (i == j ? q : 0)) / p;
    const double r = (c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                      c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                      c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])) /
                     2;
    const double phi = std::acos(std::clamp(r, -1.0, 1.0)) / 3;
    least = q + 2 * p * std::cos(phi + 2 * M_PI / 3);
  }
  return std::sqrt(std::max(least, 0.0));
}

}  // namespace

double placementClearance(const TriMesh& mesh, const Affine3f& to_world, double ulps) {
  if (mesh.vertices.empty()) return 0;
  Vec3d extent;  // the largest |coordinate| on each axis
  for (const Vec3f& v : mesh.vertices)
    extent =
        max(extent, Vec3d(std::abs(double(v.x)), std::abs(double(v.y)), std::abs(double(v.z))));
  double magnitude = 0;
  for (int i = 0; i < 3; ++i) {
    double row = std::abs(double(to_world.m[i][3]));
    for (int j = 0; j < 3; ++j) row += std::abs(double(to_world.m[i][j])) * extent[j];
    magnitude = std::max(magnitude, row);
  }
  // Slightly less than the computed smallest scale: its own rounding must not shrink the bound.
  const double smallest_scale = smallestSingularValue(to_world) * (1 - 1e-9);
  if (!(smallest_scale > 0)) return 0;
  return ulps * floatUlp(magnitude) / smallest_scale;
}

namespace {

Vec3d at(const TriMesh& m, uint32_t i) {
  return Vec3d(m.vertices[i]);
}

// Twice the area-weighted normal of a triangle (its cross product).
Vec3d areaNormal(const TriMesh& m, const Triangle& t) {
  return cross(at(m, t[1]) - at(m, t[0]), at(m, t[2]) - at(m, t[0]));
}

double signedVolume(const TriMesh& m) {
  double v = 0;
  for (const Triangle& t : m.triangles) v += dot(at(m, t[0]), cross(at(m, t[1]), at(m, t[2])));
  return v / 6;
}

}  // namespace

TriMesh pushedAway(const TriMesh& proxy, ProxyClass kind, double distance) {
  const double outward = signedVolume(proxy) >= 0 ? 1.0 : -1.0;
  const double side = kind == ProxyClass::kInside ? -outward : outward;
  const size_t n = proxy.vertices.size();
  std::vector<Vec3d> normal(n);
  std::vector<std::vector<Vec3d>> faces_of(n);
  for (const Triangle& t : proxy.triangles) {
    const Vec3d a = areaNormal(proxy, t);
    const double l = length(a);
    if (!(l > 0)) continue;
    for (uint32_t i : t) {
      normal[i] += a;
      faces_of[i].push_back(a / l);
    }
  }
  const double step = distance + 2 * floatUlp(largestCoordinate(proxy));
  TriMesh out = proxy;
  for (size_t i = 0; i < n; ++i) {
    const double l = length(normal[i]);
    if (!(l > 0)) continue;
    const Vec3d dir = normal[i] * (side / l);
    double least = 1;  // the smallest cosine between the push and the vertex's faces' normals
    for (const Vec3d& f : faces_of[i]) least = std::min(least, side * dot(dir, f));
    std::optional<Vec3d> move;
    if (least >= 0.5) {
      move = dir * (step / least);
    } else {
      // A sharp or folded vertex (a face's normal far from the average; along it, that face
      // would move the wrong way): the least move along the average that moves every face's
      // plane by `step`, a 3-variable LP. None exists when the faces' normals fill more than a
      // half-space: the vertex stays, and the separation measured afterwards decides.
      lp::PlaneLpProblem problem;
      for (const Vec3d& f : faces_of[i]) problem.constraints.push_back({f * side, step});
      problem.objective = dir;
      problem.half_size = 20 * step;
      move = lp::solvePlaneLp(problem);
    }
    if (move) out.vertices[i] = Vec3f(at(proxy, uint32_t(i)) + *move);
  }
  return out;
}

}  // namespace proxyvis
