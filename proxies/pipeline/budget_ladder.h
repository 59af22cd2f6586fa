#pragma once
// The face budget of proxy-gen (docs/budgets.md): reduce a built proxy to the budget and verify
// it, and when that fails, climb a ladder of fallbacks that keep the guarantee (coarser wraps or
// voxels, the convex hull, a box, a tetrahedron; for general proxies meshoptimizer), each
// verified with the same exact checks, and keep the tightest that meets the budget.
#include <functional>
#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/proxy_report.h"
#include "proxies/pipeline/stage_timer.h"
#include "proxies/shared/bounded_simplify.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis {

// A proxy and what the checks found.
struct VerifiedCandidate {
  std::string source;  // "wrap", "wrap alpha 0.04", "hull", "box", "tetrahedron", ...
  TriMesh mesh;
  MeshReport report;
  std::optional<ContainmentResult> containment;  // outside/inside only (with the separation)
  BoundedSimplifyStats stats;                    // of the bounded simplification, if any
  bool ok = false;  // closed, manifold, no self-intersection, and for outside/inside the
                    // expected containment
  size_t faces() const { return mesh.numTriangles(); }
};

// What one run needs to build, reduce and check candidates.
struct BudgetContext {
  const TriMesh& input;
  const TriMesh& reference;  // what the guarantee refers to (the input, or its holes filled)
  const ProxyGenOptions& options;
  std::string method;
  size_t max_faces = 0;  // 0 = no budget
  const TimeBudget& budget;
  StageTimer& timer;
  ProxyReport& report;
  // Builds the proxy of `options.method` with other options (a coarser alpha or voxel).
  std::function<TriMesh(const ProxyGenOptions&)> rebuild;
  // Outside/inside: the least distance a verified proxy keeps from the reference (clearance.h).
  double clearance = 0;
};

// The face budget the caller gave for an outside/inside proxy, known before it is built:
// max_faces, else max(min_faces (default 12), ratio x input faces); 0 = none.
size_t requestedFaces(const ProxyGenOptions& options, const TriMesh& input);

// Checks `mesh` as a proxy of the context's kind (validation with self-intersections; for
// outside/inside the exact containment test against the reference and the clearance: a proxy
// closer to the reference than ctx.clearance is moved away from it (pushedAway) and checked
// again, and fails when it still is).
VerifiedCandidate verifyCandidate(const BudgetContext& ctx, TriMesh mesh, std::string source);

// Reduces `built` to the budget with the containment-preserving collapse (outside/inside) and
// verifies it. A collapse can still let faces cut through a distant part of the surface; then
// the budget is retried with collapses kept closer to their edges, and, when `allow_unreduced`,
// the unreduced proxy is returned (inside, it is checked first: when it is 'disjoint' from the
// reference, no collapse can help and it is returned at once). Each attempt
// goes to report.budget_attempts.
VerifiedCandidate reduceAndVerify(const BudgetContext& ctx, const TriMesh& built,
                                  std::string source, bool allow_unreduced);

// What the ladder found: the tightest verified candidate within the budget (smallest volume
// outside, largest inside; general: clean ones first, then fewest faces), and the verified
// candidate with the fewest faces (general: any), e.g. to write with --budget soft.
struct LadderResult {
  std::optional<VerifiedCandidate> within, smallest;
};

// When `primary` is not a verified proxy within the budget, the fallbacks; when it is, a box
// that is tighter (outside, budgets of 12 to 48 faces). Records every candidate
// in report.budget_ladder.
LadderResult climbBudgetLadder(const BudgetContext& ctx, const VerifiedCandidate& primary);

// A failure no reduction or fallback can fix: the closed proxy is neither inside nor around the
// reference ('disjoint': the reference bounds no consistent volume).
bool inputIsTheProblem(const VerifiedCandidate& c);

// The Error (exit 1) of a budget that was asked for and not met: one line saying what was
// reached and why. `smallest` is the fewest faces of any verified candidate (0 = none).
[[noreturn]] void throwBudgetNotMet(const BudgetContext& ctx, size_t smallest);

// A hard budget below 4 faces (outside/inside): no closed surface meets it. Verifies the
// tetrahedron, the smallest proxy there is, without building the method's proxy, and throws
// what throwBudgetNotMet throws.
[[noreturn]] void failBelowClosedMinimum(const BudgetContext& ctx);

// The flags that tune `method` of `kind`, for the advice of a failure message ("--alpha/--offset"
// for the wraps, "--erosion/--voxel" for erode; empty for the hull).
std::string tuningFlags(ProxyClass kind, const std::string& method);

}  // namespace proxyvis
