#pragma once
// The ranges scene_desc.h promises for what the scene loaders accept, checked independently of
// the loaders' own code: a violation is a finding.
#include <cmath>
#include <optional>
#include <string>

#include "fuzz_support.h"
#include "scene/scene_desc.h"
#include "scene/transform.h"

namespace proxyvis::fuzz {

inline void checkPosition(const Vec3f& p, const char* what) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(p[i]) <= kMaxSceneCoordinate))
      finding(std::string("accepted a ") + what + " out of range");
}

inline void checkTransform(const Affine3f& t) {
  const std::optional<Affine3f> inv = inverse(t);
  if (!inv) finding("accepted a singular transform");
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      if (!(std::abs(t.m[i][j]) <= kMaxTransformScale) ||
          !(std::abs(inv->m[i][j]) <= kMaxTransformScale))
        finding("accepted a transform that scales out of range");
  }
  checkPosition({t.m[0][3], t.m[1][3], t.m[2][3]}, "translation");
}

}  // namespace proxyvis::fuzz
