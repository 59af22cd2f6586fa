#include "scene/internal/value_ranges.h"

#include <fmt/core.h>

#include <cmath>

#include "scene/scene_desc.h"
#include "scene/transform.h"

namespace proxyvis::detail {

namespace {

const std::string kFiniteWhy = "so that the renderer's float arithmetic stays finite";

// The entry of largest magnitude of a 3x3 linear part.
float largestEntry(const Affine3f& t) {
  float m = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m = std::max(m, std::abs(t.m[i][j]));
  return m;
}

}  // namespace

std::string numberText(double v) {
  return fmt::format("{:g}", v);
}

std::optional<RangeProblem> positionProblem(const Vec3f& p, const std::string& what) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(p[i]) <= kMaxSceneCoordinate))
      return RangeProblem{what + " coordinate " + numberText(p[i]) + " out of range",
                          "coordinates must be within [-" + numberText(kMaxSceneCoordinate) + ", " +
                              numberText(kMaxSceneCoordinate) + "] " + kFiniteWhy,
                          "scale the scene down or move it closer to the origin"};
  return std::nullopt;
}

std::optional<RangeProblem> transformProblem(const Affine3f& t) {
  for (const auto& row : t.m)
    for (float x : row)
      if (!std::isfinite(x))
        return RangeProblem{"non-finite transform", "every entry must be a finite number",
                            "check the scale and the matrix"};
  const std::string limit = numberText(kMaxTransformScale);
  if (const float big = largestEntry(t); big > kMaxTransformScale)
    return RangeProblem{
        "transform scales by " + numberText(big) + ", more than " + limit,
        "the linear part's entries must be within [-" + limit + ", " + limit + "] " + kFiniteWhy,
        "change the mesh's units instead of scaling it this much"};
  const std::optional<Affine3f> inv = inverse(t);
  if (!inv)
    return RangeProblem{"singular transform", "a transform must be invertible",
                        "check that no scale is 0 and the matrix rows are independent"};
  if (const float big = largestEntry(*inv); big > kMaxTransformScale)
    return RangeProblem{"transform scales down by " + numberText(big) + ", more than " + limit,
                        "rays are mapped into the mesh's space by the inverse, whose entries "
                        "must be within [-" +
                            limit + ", " + limit + "] " + kFiniteWhy,
                        "change the mesh's units instead of scaling it this much"};
  if (auto p = positionProblem({t.m[0][3], t.m[1][3], t.m[2][3]}, "translation")) return p;
  return std::nullopt;
}

}  // namespace proxyvis::detail
