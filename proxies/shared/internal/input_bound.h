#pragma once
// Private to pv_proxy_shared: the test that lets a bounded collapse move a vertex inward, not
// only outward. A proxy that contains (or is contained in) the input keeps doing so after a local
// change from the old star of faces to a new one when (1) no new face touches an input triangle
// and (2) no input piece lies in the region swept between the old and the new star. Without it
// the collapse must keep each mesh nested in the previous one, which piles up volume at small
// budgets.
#include <array>
#include <memory>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/vec3.h"

namespace proxyvis::cgal {

// What TriMesh stores: candidate positions are rounded to float before any test, so that the
// tests see the geometry that is written. Through a volatile: GCC 12's SLP vectorizer at -O2/-O3
// turns the three double(float(v)) of a Vec3d into a copy, so the rounding did not happen and
// the tests saw points that were rounded, differently, only when written.
inline double roundToFloat(double v) {
  volatile float f = float(v);
  return f;
}
inline Vec3d roundToFloat(const Vec3d& x) {
  return {roundToFloat(x.x), roundToFloat(x.y), roundToFloat(x.z)};
}

// One per thread: touches() remembers its answers (internal/touch_cache.h).
class InputBound {
 public:
  // `clearance` > 0: a triangle within that distance of the input counts as touching it.
  explicit InputBound(const TriMesh& input, double clearance = 0);
  ~InputBound();
  InputBound(const InputBound&) = delete;
  InputBound& operator=(const InputBound&) = delete;

  // `old_star` and `new_star` are triangles (3 corners each) with the same boundary; the
  // union of old_star and reversed new_star is closed. True when no triangle of new_star
  // touches the input and no input component lies between the two stars. `first_touch`, when
  // given, is the new face tested first and is set to the one that touched: a caller trying
  // several positions of one star starts where the last one was refused (same answer, fewer
  // tree traversals).
  bool allows(const std::vector<std::array<Vec3d, 3>>& old_star,
              const std::vector<std::array<Vec3d, 3>>& new_star,
              size_t* first_touch = nullptr) const;

  // True when triangle t touches an input triangle, or comes within the clearance of one (what
  // allows refuses for a new face).
  bool touches(const std::array<Vec3d, 3>& t) const;

  // The input point nearest to p.
  Vec3d closestPoint(const Vec3d& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxyvis::cgal
