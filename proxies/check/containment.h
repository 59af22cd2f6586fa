#pragma once
// Exact containment of two triangle meshes (CGAL, exact predicates): does the proxy contain the
// original (an outside proxy), is it contained in it (an inside proxy), or neither? "Closed" means
// bounds a volume by ray parity: every edge, after welding equal positions, has an even number of
// faces (a closed manifold, or a watertight surface with non-manifold edges;
// docs/proxy_classes.md). Both meshes are tested as given: no repaired or hole-filled copy stands
// in for either. Owned by the proxy-check work; proxy-gen calls it to verify a proxy before writing
// it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/proxy_class.h"
#include "util/vec3.h"

namespace proxyvis {

enum class ContainmentVerdict {
  kContains,      // proxy closed; surfaces do not intersect; original lies inside the proxy
  kContained,     // both closed; surfaces do not intersect; proxy lies inside the original
  kIntersecting,  // the two surfaces intersect (or touch)
  kDisjoint,      // closed, not intersecting, neither inside the other (mismatched pair)
  kUndecidable    // the proxy is open (or the original is open and the proxy is not outside)
};

const char* containmentName(ContainmentVerdict v);  // "contains", "contained", ...

// The verdict that proves `kind` (outside or inside): contains, or contained.
inline ContainmentVerdict expectedVerdict(ProxyClass kind) {
  return kind == ProxyClass::kOutside ? ContainmentVerdict::kContains
                                      : ContainmentVerdict::kContained;
}

struct ContainmentResult {
  ContainmentVerdict verdict = ContainmentVerdict::kUndecidable;
  bool proxy_closed = false, original_closed = false;
  uint64_t intersecting_face_pairs = 0;  // 0 unless kIntersecting (may stop counting early)
  // The volume each closed mesh bounds by ray parity (proxies/shared/parity_solid.h).
  std::optional<double> original_volume, proxy_volume;
  // The least distance between the two surfaces when they do not intersect, measured up to
  // ContainmentOptions::separation_cap (equal to the cap: at least that far apart); empty when
  // not asked for or when they intersect.
  std::optional<double> separation;
  std::string detail;  // human-readable reason, e.g. where they intersect
};

struct ContainmentOptions {
  // The original's vertex positions in another reading of its file (same order as
  // original.vertices, e.g. its decimal text read in double): the check runs on these instead
  // of the float vertices. Null: the float vertices, as the programs read them.
  const std::vector<Vec3d>* original_positions = nullptr;
  // > 0: also measure ContainmentResult::separation, up to this distance.
  double separation_cap = 0;
};

// For an open original, "contains" means: no surface intersection and every original vertex
// strictly inside the closed proxy.
ContainmentResult checkContainment(const TriMesh& original, const TriMesh& proxy,
                                   const ContainmentOptions& options = {});

}  // namespace proxyvis
