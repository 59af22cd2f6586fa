#pragma once
// The shadow segment: the one query the estimators hand to a tracer and Embree answers
// (trace/trace_scene.h). A plain value, so code that only builds segments needs no tracer.
#include "util/vec3.h"

namespace proxyvis {

// A shadow segment: points org + t*dir for t in [tnear, tfar]. dir need not be normalized.
struct Segment {
  Vec3f org;
  float tnear = 0;
  Vec3f dir;
  float tfar = 1;
  // The segment from `a` to `b`: org = a, dir = b - a, t in [0, 1].
  static Segment between(const Vec3f& a, const Vec3f& b) {
    Segment s;
    s.org = a;
    s.dir = b - a;
    return s;
  }
};

}  // namespace proxyvis
