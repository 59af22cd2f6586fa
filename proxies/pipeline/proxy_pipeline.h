#pragma once
// The proxy-gen pipeline for one mesh: build the proxy of the requested kind and method, reduce
// it to a face budget, verify it (closed, manifold, no self-intersection, and for outside /
// inside the exact containment test of proxies/check), and measure it (volume ratio, sampled
// Hausdorff distances both ways, seconds per stage). Used by apps/proxy-gen, the tests and
// bench/proxy_gen.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "proxies/pipeline/proxy_report.h"
#include "util/affine3.h"
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
// --clearance-ulps (ulps of float at the input's largest coordinate) and --clearance (scene
// units, up to the float limit; a clearance larger than the proxy fails its checks).
inline constexpr ParameterRange kClearanceUlpsRange{0, 1 << 20};
inline constexpr ParameterRange kClearanceRange{0, 3.4e38};

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
  // Outside/inside: the least distance the proxy keeps from the input (proxies/pipeline/
  // clearance.h): `clearance` in scene units, else `clearance_ulps` ulps of float at the input's
  // largest coordinate (default kDefaultClearanceUlps); a clearance of 0 keeps none.
  std::optional<double> clearance, clearance_ulps;
  // Outside/inside: the input's vertices read in double (mesh/io/double_reading.h); the chosen
  // proxy is then proved against that reading too ("checks.containment_double"), and its class
  // is written only when it holds in both. Null: the float reading alone.
  const std::vector<Vec3d>* input_double = nullptr;
  // Why there is no double reading of a text input (its second parser refused the file): the
  // report says so, and the clearance alone covers that reading (docs/clearance.md).
  std::string input_double_missing;
  // Outside/inside without `clearance`: the transforms the proxy will be placed with (a scene's
  // placement of the mesh and its instances). The clearance grows to what keeps the class on
  // each placed float copy (placementClearance in clearance.h).
  std::vector<Affine3f> placements;
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

// For an outside/inside proxy of a text file (OFF, OBJ, ASCII PLY): reads `file` again in double
// into `storage` and points options.input_double at it, so that generateProxy proves the class
// in both readings; when the second reading fails, options.input_double_missing says why.
void addDoubleReading(ProxyGenOptions& options, const std::filesystem::path& file,
                      const TriMesh& input, std::vector<Vec3d>& storage);

}  // namespace proxyvis
