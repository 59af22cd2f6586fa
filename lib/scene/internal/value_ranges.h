#pragma once
// Range checks the scene file and the instance list share (the limits are in scene_desc.h). Each
// returns the problem as what / why / what to do, for the caller to report with its own location
// (a JSON path, or "file:line").
#include <optional>
#include <string>

#include "util/affine3.h"

namespace proxyvis::detail {

struct RangeProblem {
  std::string what, why, todo;
};

// A position (`what` names it: "eye", "translation"...) with a coordinate beyond
// kMaxSceneCoordinate.
std::optional<RangeProblem> positionProblem(const Vec3f& p, const std::string& what);

// A transform that is not finite, singular, scales up or down by more than kMaxTransformScale
// (an entry of its linear part or of its inverse's) or translates beyond kMaxSceneCoordinate.
std::optional<RangeProblem> transformProblem(const Affine3f& t);

// A number as messages print it: "1e+30", "0.5", "16384".
std::string numberText(double v);

}  // namespace proxyvis::detail
