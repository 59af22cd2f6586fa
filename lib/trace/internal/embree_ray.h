#pragma once
// A Segment as Embree's RTCRay. Private to lib/trace (and bench_trace, whose bare Embree loops
// must trace exactly the rays the wrapper traces).
#include <embree3/rtcore.h>

#include <cstdint>

#include "trace/trace_scene.h"

namespace proxyvis::detail {

// The ray of `s` for rtcOccluded1 / rtcIntersect1: time 0, id 0, flags 0, the given ray mask.
inline RTCRay toRtcRay(const Segment& s, uint32_t mask = ~0u) {
  RTCRay r;
  r.org_x = s.org.x;
  r.org_y = s.org.y;
  r.org_z = s.org.z;
  r.tnear = s.tnear;
  r.dir_x = s.dir.x;
  r.dir_y = s.dir.y;
  r.dir_z = s.dir.z;
  r.time = 0;
  r.tfar = s.tfar;
  r.mask = mask;
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace proxyvis::detail
