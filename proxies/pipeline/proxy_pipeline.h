#pragma once
// The proxy-gen pipeline for one mesh: build the proxy of the requested kind and method, reduce
// it to a face budget, verify it (closed, manifold, no self-intersection, and for outside /
// inside the exact containment test of proxies/check), and measure it (volume ratio, sampled
// Hausdorff distances both ways, seconds per stage). Used by apps/proxy-gen, the tests and
// bench/proxy_gen.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "proxies/pipeline/proxy_report.h"
#include "util/proxy_class.h"

namespace proxyvis {

// The accepted range of each size and budget (proxy-gen checks them when parsing; generateProxy
// again, for other callers). Sizes are fractions of the bounding-box diagonal. Beyond these a
// wrap or erosion would not finish in reasonable time and memory (an alpha of diag/2000 or an
// offset of 10 diagonals needs gigabytes), or could not be represented in float.
struct ParameterRange {
  double lo, hi;
  bool contains(double v) const { return v >= lo && v <= hi; }
};
inline constexpr ParameterRange kAlphaRange{1e-3, 1};
inline constexpr ParameterRange kOffsetRange{1e-4, 1};
inline constexpr ParameterRange kErosionRange{1e-3, 0.5};
inline constexpr ParameterRange kVoxelRange{2e-3, 0.25};
inline constexpr ParameterRange kRatioRange{1e-6, 1};
inline constexpr ParameterRange kMaxSecondsRange{0.01, 7 * 24 * 3600};

struct ProxyGenOptions {
  ProxyClass kind = ProxyClass::kOutside;
  std::string method;            // empty = the kind's default: wrap, wrap, qem
  std::optional<double> alpha;   // wrap: fraction of the diagonal (default 1/50)
  std::optional<double> offset;  // wrap: fraction of the diagonal (default 1/600)
  size_t max_faces = 0;          // face budget; 0 = none (general: use ratio)
  // Fraction of the input faces: general (default 0.02); outside/inside, a face budget of
  // max(min_faces, ratio x input faces) when max_faces is 0.
  std::optional<double> ratio;
  // The smallest budget --ratio gives a mesh: a scene's small meshes (a flower of 565 faces
  // in ecosys) would otherwise get proxies of a dozen faces, far looser than their wraps.
  size_t min_faces = 12;
  std::optional<double> erosion;  // erode: fraction of the diagonal (default 1/75)
  std::optional<double> voxel;    // erode: voxel edge, fraction of the diagonal (default 1/150)
  bool fill_holes = false;        // inside: fill the holes of an open input first
  std::optional<size_t>
      parts;  // convex-parts: most pieces (default: budget / 12 in [2, 32], or 16)
  // A face budget the caller gave (max_faces, ratio) that no verified proxy meets: true = throw
  // CheckFailed saying what was reached (nothing is written), false = return the proxy with
  // report "budget_reached": false. Budgets not asked for never throw (docs/budgets.md).
  bool hard_budget = true;
  uint64_t seed = 0;  // sampling of the Hausdorff estimates
  uint64_t hausdorff_samples = 20000;
  // Time budget for the whole generation (wrap, seed search, erosion, decimation, face budget
  // poll it); 0 = none.
  double max_seconds = 0;
  // Called as each stage starts, with its key in the report's seconds (validate_input,
  // fill_holes, build, simplify, verify, budget_ladder, metrics); empty = nothing to tell.
  std::function<void(const std::string& stage)> on_stage;
};

// Methods accepted for a kind ("wrap", "hull", "convex-parts" / "wrap", "erode" / "qem",
// "cgal-sms", "meshopt").
const std::vector<std::string>& proxyMethods(ProxyClass kind);

struct ProxyGenResult {
  TriMesh proxy;
  bool verified = false;  // outside/inside: containment proven; general: closed, manifold, no SI
  ProxyReport report;     // its JSON: docs/proxy_reports.md
};

// Builds and checks the proxy of `input` (report key "input.path" = input.source); a face budget
// that the built proxy misses is met by the fallbacks of proxies/pipeline/budget_ladder.h when
// any of them can. Throws Error
// on bad input or options (e.g. an open mesh for --kind inside without fill_holes, naming the
// boundary edges; geometry the generator cannot handle, see proxies/shared/input_geometry.h; an
// option outside its range; a spent max_seconds), CheckFailed when an outside/inside proxy fails
// its guarantee or a hard budget is not met. A general proxy
// that is not closed/manifold/free of self-intersections is returned with verified = false.
ProxyGenResult generateProxy(const TriMesh& input, const ProxyGenOptions& options);

}  // namespace proxyvis
