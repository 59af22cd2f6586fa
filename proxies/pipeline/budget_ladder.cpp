#include "proxies/pipeline/budget_ladder.h"

#include "proxies/pipeline/clearance.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "proxies/general/general_proxy.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/pipeline/budget_shapes.h"
#include "util/error.h"

namespace proxyvis {
namespace {

bool withinBudget(const BudgetContext& ctx, const VerifiedCandidate& c) {
  return ctx.max_faces == 0 || c.faces() <= ctx.max_faces;
}

// Larger is tighter: the volume for inside proxies, minus the volume outside, minus the face
// count for general proxies (closed and clean ones first).
double tightness(const BudgetContext& ctx, const VerifiedCandidate& c) {
  switch (ctx.options.kind) {
    case ProxyClass::kOutside:
      return -c.mesh.signedVolume();
    case ProxyClass::kInside:
      return c.mesh.signedVolume();
    default:
      return (c.ok ? 1e18 : 0) - double(c.faces());
  }
}

void record(const BudgetContext& ctx, const VerifiedCandidate& c) {
  LadderEntry entry{std::nullopt, c.source, c.faces(), c.ok, std::nullopt};
  const double ref_volume = ctx.reference.signedVolume();
  if (c.ok && c.report.closed && ref_volume > 0)
    entry.volume_ratio = c.mesh.signedVolume() / ref_volume;
  ctx.report.budget_ladder.push_back(std::move(entry));
}

// Coarser versions of the size the method's proxy was built with (the report's parameters): 2, 4
// and 8 times, within its range.
std::vector<ProxyGenOptions> coarserOptions(const BudgetContext& ctx) {
  std::vector<ProxyGenOptions> out;
  const ProxyParameters& used = ctx.report.parameters;
  for (double factor : {2.0, 4.0, 8.0}) {
    ProxyGenOptions c = ctx.options;
    if (ctx.method == "wrap" && used.alpha) {
      const double alpha = *used.alpha * factor;
      if (!kAlphaRange.contains(alpha)) break;
      c.alpha = alpha;
    } else if (ctx.method == "erode" && used.voxel) {
      const double voxel = *used.voxel * factor;
      if (voxel > 1.0 / 20) break;  // coarser grids erode away most of the volume
      c.voxel = voxel;
      c.erosion = used.erosion;
    } else {
      break;
    }
    out.push_back(c);
  }
  return out;
}

std::string coarserName(const BudgetContext& ctx, const ProxyGenOptions& c) {
  return ctx.method == "wrap" ? fmt::format("wrap alpha {:.4g}", *c.alpha)
                              : fmt::format("erode voxel {:.4g}", *c.voxel);
}

}  // namespace

size_t requestedFaces(const ProxyGenOptions& options, const TriMesh& input) {
  if (options.max_faces > 0) return options.max_faces;
  if (options.ratio)
    return std::max(options.min_faces, size_t(*options.ratio * input.numTriangles()));
  return 0;
}

namespace {

// The checks of verifyCandidate, without the clearance's repair.
VerifiedCandidate checkCandidate(const BudgetContext& ctx, TriMesh mesh, std::string source) {
  VerifiedCandidate c;
  c.source = std::move(source);
  c.mesh = std::move(mesh);
  c.stats.faces_before = c.stats.faces_after = c.faces();
  c.stats.budget_reached = withinBudget(ctx, c);
  c.report = ctx.timer.run("verify", [&] {
    ValidationOptions v;
    v.self_intersections = true;
    return validateMesh(c.mesh, v);
  });
  ctx.budget.check("verifying the proxy");
  c.ok = c.report.closed && c.report.manifold && c.report.self_intersecting_pairs.value_or(1) == 0;
  if (ctx.options.kind != ProxyClass::kGeneral) {
    ContainmentOptions options;
    options.separation_cap = 2 * ctx.clearance;
    c.containment =
        ctx.timer.run("verify", [&] { return checkContainment(ctx.reference, c.mesh, options); });
    c.ok = c.ok && c.containment->verdict == expectedVerdict(ctx.options.kind);
  }
  return c;
}

bool keepsClearance(const BudgetContext& ctx, const VerifiedCandidate& c) {
  return ctx.clearance <= 0 || (c.containment && c.containment->separation &&
                                *c.containment->separation >= ctx.clearance);
}

}  // namespace

VerifiedCandidate verifyCandidate(const BudgetContext& ctx, TriMesh mesh, std::string source) {
  VerifiedCandidate c = checkCandidate(ctx, std::move(mesh), source);
  if (!c.ok || keepsClearance(ctx, c)) return c;
  // Closer than the clearance (relaxed vertices sit within an ulp of the input; a hull's are
  // input vertices): moved away by what is missing, then by more, each time checked again.
  const double missing = ctx.clearance - c.containment->separation.value_or(0);
  for (const double factor : {1.0, 2.0, 4.0}) {
    VerifiedCandidate pushed =
        checkCandidate(ctx, pushedAway(c.mesh, ctx.options.kind, missing * factor), source);
    if (pushed.ok && keepsClearance(ctx, pushed)) {
      pushed.stats = c.stats;
      return pushed;
    }
  }
  c.ok = false;
  c.containment->detail = fmt::format(
      "{}; but the surfaces are only {:.3g} apart, less than the clearance {:.3g}, and moving the "
      "proxy away did not keep its checks",
      c.containment->detail, c.containment->separation.value_or(0), ctx.clearance);
  return c;
}

bool inputIsTheProblem(const VerifiedCandidate& c) {
  // 'disjoint': both closed, no intersection, neither inside the other. ('undecidable' means an
  // open proxy: the proxy's fault, which a fallback may not share.)
  return !c.ok && c.containment && c.containment->verdict == ContainmentVerdict::kDisjoint;
}

VerifiedCandidate reduceAndVerify(const BudgetContext& ctx, const TriMesh& built,
                                  std::string source, bool allow_unreduced) {
  const bool reduce = ctx.max_faces > 0 && built.numTriangles() > ctx.max_faces;
  auto attempt = [&](double move) {
    TriMesh proxy = built;
    BoundedSimplifyStats stats;
    stats.faces_before = stats.faces_after = built.numTriangles();
    if (move > 0) {
      BoundedSimplifyOptions s;
      s.max_faces = ctx.max_faces;
      s.side = ctx.options.kind == ProxyClass::kOutside ? BoundSide::kOutside : BoundSide::kInside;
      s.max_move_edges = move;
      s.budget = &ctx.budget;
      s.bound = &ctx.reference;  // lets collapses move toward the input: tighter at small budgets
      s.clearance = ctx.clearance;  // but no closer than the clearance
      proxy = ctx.timer.run("simplify", [&] { return simplifyBounded(built, s, &stats); });
    }
    VerifiedCandidate c = verifyCandidate(ctx, std::move(proxy), source);
    c.stats = stats;
    c.stats.budget_reached = withinBudget(ctx, c);
    if (reduce)
      ctx.report.budget_attempts.push_back(
          {source, move, c.faces(), c.report.closed, c.report.manifold,
           c.report.self_intersecting_pairs.value_or(0),
           c.containment ? containmentName(c.containment->verdict) : "n/a"});
    ctx.budget.check("the face budget's retries");
    return c;
  };
  if (!reduce) return attempt(0);
  // Inside, the unreduced proxy first (a check costs a fraction of a collapse): an input that
  // bounds no consistent volume gives a proxy that is not inside it at all, no collapse can fix
  // that, and the run fails at once. (An outside wrap or hull contains its input by
  // construction; it is checked unreduced only when every reduction failed.)
  std::optional<VerifiedCandidate> unreduced;
  if (allow_unreduced && ctx.options.kind == ProxyClass::kInside) {
    unreduced = attempt(0);
    if (inputIsTheProblem(*unreduced)) return std::move(*unreduced);
  }
  std::optional<VerifiedCandidate> last;
  for (double move : {1.0, 0.5}) {
    last = attempt(move);
    if (last->ok || inputIsTheProblem(*last)) return std::move(*last);
  }
  if (unreduced) return std::move(*unreduced);
  return allow_unreduced ? attempt(0) : std::move(*last);
}

namespace {

// The 4-face proxy of the kind: around the reference (outside) or in its deepest interior ball
// (inside; none without one).
std::optional<TriMesh> tetrahedronProxy(const BudgetContext& ctx,
                                        const std::optional<InteriorBall>& ball) {
  if (ctx.options.kind == ProxyClass::kOutside) return enclosingTetrahedron(ctx.reference);
  if (ball) return inscribedTetrahedron(*ball, ctx.reference.source);
  return std::nullopt;
}

}  // namespace

LadderResult climbBudgetLadder(const BudgetContext& ctx, const VerifiedCandidate& primary) {
  LadderResult result;
  std::optional<VerifiedCandidate>& best = result.within;
  // A fallback that cannot be built for this input (the hull of a flat mesh) is skipped; a spent
  // time budget still ends the run.
  auto attempt = [&](auto&& make) -> std::optional<VerifiedCandidate> {
    try {
      return make();
    } catch (const CheckFailed&) {
      throw;
    } catch (const Error& e) {
      if (ctx.budget.expired()) throw;
      ctx.report.budget_ladder.push_back({e.what(), "", 0, false, std::nullopt});
      return std::nullopt;
    }
  };
  auto consider = [&](VerifiedCandidate c) {
    record(ctx, c);
    // (A simplifier that left no face at all has made no proxy.)
    const bool usable = (ctx.options.kind == ProxyClass::kGeneral || c.ok) && c.faces() > 0;
    if (!usable) return false;
    if (!withinBudget(ctx, c)) {
      if (!result.smallest || c.faces() < result.smallest->faces()) result.smallest = std::move(c);
      return false;
    }
    if (!best || tightness(ctx, c) > tightness(ctx, *best)) best = std::move(c);
    return true;
  };
  consider(primary);
  if (inputIsTheProblem(primary)) return result;
  const TriMesh& ref = ctx.reference;
  const bool outside = ctx.options.kind == ProxyClass::kOutside;
  if (best && primary.ok) {
    // At budgets of 12 to 48 faces a box can be tighter than the reduced proxy: it is cheap to
    // build, and verified only when its volume beats the proxy's.
    if (!outside || ctx.max_faces < kBoxFaces || ctx.max_faces > 4 * kBoxFaces) return result;
    TriMesh box = enclosingBox(ref);
    if (box.signedVolume() < best->mesh.signedVolume())
      consider(verifyCandidate(ctx, std::move(box), "box"));
    return result;
  }

  if (ctx.options.kind == ProxyClass::kGeneral) {
    if (best) return result;  // general proxies are not compared: within the budget is enough
    // A decimator a few faces short of the budget (its checks refused the last collapses) is
    // asked once more for as many fewer faces as it missed by.
    const size_t over = primary.faces() - ctx.max_faces;
    if (over * 10 <= ctx.max_faces && ctx.max_faces > over + kMinClosedFaces) {
      ProxyGenOptions again = ctx.options;
      again.max_faces = ctx.max_faces - over - 1;
      TriMesh m = ctx.timer.run("budget_ladder", [&] { return ctx.rebuild(again); });
      if (consider(verifyCandidate(ctx, std::move(m), ctx.method + " (lower target)")))
        return result;
    }
    // The decimators stall far above the budget on soups of many small closed parts (each needs
    // 4 faces at least): meshoptimizer's simplifier, then its sloppy one, merges parts.
    GeneralOptions g;
    g.max_faces = ctx.max_faces;
    g.budget = &ctx.budget;
    TriMesh m = ctx.timer.run("budget_ladder", [&] { return simplifyMeshopt(ctx.input, g); });
    consider(verifyCandidate(ctx, std::move(m), "meshopt"));
    return result;
  }

  // A closed surface has at least 4 faces: below that nothing can succeed, only the
  // tetrahedron is built, to say what the smallest proxy is.
  if (ctx.max_faces >= kMinClosedFaces) {
    for (const ProxyGenOptions& c : coarserOptions(ctx)) {
      ctx.budget.check("the face budget's fallbacks");
      std::optional<VerifiedCandidate> coarse = attempt([&] {
        const TriMesh m = ctx.timer.run("budget_ladder", [&] { return ctx.rebuild(c); });
        return reduceAndVerify(ctx, m, coarserName(ctx, c), false);
      });
      if (coarse && consider(std::move(*coarse))) break;
    }
    if (outside && ctx.method != "hull") {
      std::optional<VerifiedCandidate> hull = attempt([&] {
        const TriMesh m = ctx.timer.run("budget_ladder", [&] { return makeHullProxy(ref); });
        return reduceAndVerify(ctx, m, "hull", false);
      });
      if (hull) consider(std::move(*hull));
    }
  }
  std::optional<InteriorBall> ball;
  if (!outside) ball = ctx.timer.run("budget_ladder", [&] { return deepestInteriorPoint(ref); });
  if (ctx.max_faces >= kBoxFaces) {
    if (outside)
      consider(verifyCandidate(ctx, enclosingBox(ref), "box"));
    else if (ball)
      consider(verifyCandidate(ctx, inscribedBox(*ball, ref.source), "box"));
  }
  if (std::optional<TriMesh> tet = tetrahedronProxy(ctx, ball))
    consider(verifyCandidate(ctx, std::move(*tet), "tetrahedron"));
  return result;
}

void failBelowClosedMinimum(const BudgetContext& ctx) {
  std::optional<InteriorBall> ball;
  if (ctx.options.kind != ProxyClass::kOutside) ball = deepestInteriorPoint(ctx.reference);
  VerifiedCandidate tet;
  if (std::optional<TriMesh> m = tetrahedronProxy(ctx, ball))
    tet = verifyCandidate(ctx, std::move(*m), "tetrahedron");
  throwBudgetNotMet(ctx, tet.ok ? tet.faces() : 0);
}

void throwBudgetNotMet(const BudgetContext& ctx, size_t smallest) {
  const std::string kind = proxyClassName(ctx.options.kind);
  const std::string what =
      smallest > 0
          ? fmt::format("budget of {} faces not met: the smallest verified {} proxy has {} faces",
                        ctx.max_faces, kind, smallest)
          : fmt::format("budget of {} faces not met: no {} proxy within it passed the checks",
                        ctx.max_faces, kind);
  std::string why;
  if (ctx.options.kind != ProxyClass::kGeneral && ctx.max_faces < kMinClosedFaces)
    why = fmt::format("a closed surface needs at least {}", kMinClosedFaces);
  else if (ctx.options.kind == ProxyClass::kGeneral)
    why = "neither the decimation nor meshoptimizer reached it";
  else
    why = fmt::format(
        "the {} proxy and its fallbacks (coarser sizes, {}box, tetrahedron) could not be reduced "
        "further while keeping the guarantee",
        ctx.method, ctx.options.kind == ProxyClass::kOutside ? "convex hull, " : "");
  const std::string todo =
      smallest > ctx.max_faces
          ? fmt::format("use --max-faces {} or more, or --budget soft to write the larger proxy",
                        smallest)
          : "use a larger --max-faces, or --budget soft to write the larger proxy";
  throw CheckFailed(ctx.input.source, what, why, todo);
}

std::string tuningFlags(ProxyClass kind, const std::string& method) {
  if (method == "wrap") return "--alpha/--offset";
  if (method == "erode") return "--erosion/--voxel";
  if (method == "convex-parts") return "--parts";
  if (kind == ProxyClass::kGeneral) return "--ratio/--max-faces";
  return "";
}

}  // namespace proxyvis
