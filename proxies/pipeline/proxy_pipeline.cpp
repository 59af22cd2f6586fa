#include "proxies/pipeline/proxy_pipeline.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "mesh/io/double_reading.h"
#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/check/distance_report.h"
#include "proxies/check/mesh_distance.h"
#include "proxies/general/general_proxy.h"
#include "proxies/inside/inside_proxy.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/pipeline/budget_ladder.h"
#include "proxies/pipeline/budget_shapes.h"
#include "proxies/pipeline/clearance.h"
#include "proxies/pipeline/written_class.h"
#include "proxies/shared/bounded_simplify.h"
#include "proxies/shared/input_geometry.h"
#include "proxies/shared/parity_solid.h"
#include "proxies/shared/time_budget.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace proxyvis {
namespace {

std::string resolveMethod(const ProxyGenOptions& options) {
  const std::vector<std::string>& methods = proxyMethods(options.kind);
  const std::string method = options.method.empty() ? methods.front() : options.method;
  if (std::find(methods.begin(), methods.end(), method) == methods.end()) {
    std::string list;
    for (const std::string& m : methods) list += (list.empty() ? "" : ", ") + m;
    throw Error(
        "", fmt::format("unknown method '{}' for --kind {}", method, proxyClassName(options.kind)),
        fmt::format("the {} methods are {}", proxyClassName(options.kind), list));
  }
  return method;
}

// Options outside their range: the CLI refuses them already, other callers get the same rule.
void checkOptionRanges(const ProxyGenOptions& o) {
  auto check = [](const std::optional<double>& v, ParameterRange range, const char* name) {
    if (v && !range.contains(*v))
      throw Error("",
                  fmt::format("{} must be in [{:g}, {:g}], got {:g}", name, range.lo, range.hi, *v),
                  "it is a fraction of the bounding-box diagonal");
  };
  check(o.alpha, kAlphaRange, "--alpha");
  check(o.offset, kOffsetRange, "--offset");
  check(o.erosion, kErosionRange, "--erosion");
  check(o.voxel, kVoxelRange, "--voxel");
  check(o.ratio, kRatioRange, "--ratio");
  if (o.min_faces < 4 || o.min_faces > kMaxFacesLimit)
    throw Error("",
                fmt::format("--min-faces must be in [4, {}], got {}", kMaxFacesLimit, o.min_faces),
                "a closed proxy has at least 4 faces");
  if (o.max_faces > kMaxFacesLimit)
    throw Error("",
                fmt::format("--max-faces must be at most {}, got {}", kMaxFacesLimit, o.max_faces));
  if (o.clearance && !kClearanceRange.contains(*o.clearance))
    throw Error(
        "",
        fmt::format("--clearance must be in [0, {:g}], got {:g}", kClearanceRange.hi, *o.clearance),
        "it is a distance in scene units");
  if (o.clearance_ulps && !kClearanceUlpsRange.contains(*o.clearance_ulps))
    throw Error("", fmt::format("--clearance-ulps must be in [0, {:g}], got {:g}",
                                kClearanceUlpsRange.hi, *o.clearance_ulps));
  if (o.max_seconds != 0 && !kMaxSecondsRange.contains(o.max_seconds))
    throw Error("", fmt::format("--max-seconds must be in [{:g}, {:g}], got {:g}",
                                kMaxSecondsRange.lo, kMaxSecondsRange.hi, o.max_seconds));
}

// What a method needs of the input geometry (proxies/shared/input_geometry.h): the convex hull
// and the inside methods a volume, the wrap and the simplifiers a surface.
GeometryNeed geometryNeed(ProxyClass kind, const std::string& method) {
  if (kind == ProxyClass::kInside) return GeometryNeed::kSolid;
  if (kind == ProxyClass::kOutside && (method == "hull" || method == "convex-parts"))
    return GeometryNeed::kSolid;
  return GeometryNeed::kSurface;
}

// The advice of a failed guarantee names only flags the method reads.
std::string failureAdvice(ProxyClass kind, const std::string& method) {
  const std::string flags = tuningFlags(kind, method);
  return flags.empty() ? "try --method wrap, or a larger --max-faces"
                       : fmt::format("try other {}, or a larger --max-faces", flags);
}

// A general proxy's simplifier settings from the flags (its budget is the caller's).
GeneralOptions generalOptions(const ProxyGenOptions& o) {
  GeneralOptions g;
  g.max_faces = o.max_faces;
  g.ratio = o.ratio.value_or(g.ratio);
  return g;
}

// An outside or inside wrap's settings from the flags, recorded in the report's parameters.
template <class Options>
Options wrapOptions(const ProxyGenOptions& o, ProxyParameters& params, const TimeBudget* budget) {
  Options w;
  w.alpha = o.alpha.value_or(w.alpha);
  w.offset = o.offset.value_or(w.offset);
  w.budget = budget;
  params.alpha = w.alpha;
  params.offset = w.offset;
  return w;
}

struct Built {
  TriMesh mesh;          // before the budget
  bool bounded = false;  // reduce with simplifyBounded (outside/inside) rather than not at all
  std::optional<uint64_t> seeds, voxels;  // inside wrap, erode
  std::optional<uint64_t> parts;          // convex parts: the pieces made
};

Built build(const TriMesh& reference, const ProxyGenOptions& o, const std::string& method,
            ProxyParameters& params, const TimeBudget* budget) {
  Built b;
  if (o.kind == ProxyClass::kOutside) {
    b.bounded = true;
    if (method == "hull") {
      HullOptions h;
      params.hull_epsilon = h.epsilon;
      b.mesh = makeHullProxy(reference, h);
    } else if (method == "convex-parts") {
      ConvexPartsOptions c;
      const size_t faces = requestedFaces(o, reference);
      // About a dozen faces per piece at a face budget: fewer pieces cannot follow the shape,
      // more leave each too few faces to stay near its hull.
      c.max_parts = o.parts ? *o.parts : faces > 0 ? std::clamp<size_t>(faces / 12, 2, 32) : 16;
      c.face_budget = faces;
      c.budget = budget;
      params.parts = c.max_parts;
      params.parts_epsilon = c.epsilon;
      ConvexPartsStats stats;
      b.mesh = makeConvexPartsProxy(reference, c, &stats);
      b.parts = stats.parts;
    } else {
      b.mesh = makeWrapProxy(reference, wrapOptions<WrapOptions>(o, params, budget));
    }
  } else if (o.kind == ProxyClass::kInside) {
    b.bounded = true;
    InsideStats stats;
    if (method == "wrap") {
      const auto w = wrapOptions<InsideWrapOptions>(o, params, budget);
      b.mesh = makeInsideWrapProxy(reference, w, &stats);
      b.seeds = stats.seeds;
    } else {
      ErodeOptions e;
      e.erosion = o.erosion.value_or(2 * e.voxel);
      // A small budget needs no fine grid: the collapse to it costs in proportion to the voxel
      // surface and removes the detail anyway.
      const size_t faces = requestedFaces(o, reference);
      e.voxel = o.voxel     ? *o.voxel
                : faces > 0 ? erodeVoxelForBudget(reference, faces, e.voxel, e.erosion)
                            : e.voxel;
      e.budget = budget;
      params.erosion = e.erosion;
      params.voxel = e.voxel;
      b.mesh = makeErodeProxy(reference, e, &stats);
      b.voxels = stats.voxels;
    }
  } else {
    GeneralOptions g = generalOptions(o);
    g.budget = budget;
    params.ratio = g.ratio;
    if (method == "qem")
      b.mesh = simplifyQem(reference, g);
    else if (method == "cgal-sms")
      b.mesh = simplifyCgalSms(reference, g);
    else
      b.mesh = simplifyMeshopt(reference, g);
  }
  return b;
}

}  // namespace

const std::vector<std::string>& proxyMethods(ProxyClass kind) {
  static const std::vector<std::string> outside{"wrap", "hull", "convex-parts"},
      inside{"wrap", "erode"}, general{"qem", "cgal-sms", "meshopt"};
  return kind == ProxyClass::kOutside ? outside : kind == ProxyClass::kInside ? inside : general;
}

namespace {

// The input's facts in the report.
ProxyInputFacts inputFacts(const TriMesh& input, const MeshReport& r) {
  return {input.source, r.faces, r.closed, r.watertight, r.manifold, r.boundary_edges};
}

// The face budget the proxy is reduced to (0: none): the user's --max-faces or --ratio, the
// general simplifier's own target, or, when a bounded proxy came out with more faces than its
// input, the input's count (such a proxy saves nothing: a wrapped 2-triangle ground quad has
// thousands).
size_t budgetFaces(const TriMesh& input, const ProxyGenOptions& options, const Built& built,
                   ProxyParameters& params) {
  size_t max_faces = options.max_faces;
  if (built.bounded && max_faces == 0 && options.ratio) {
    // Outside/inside with --ratio: a budget relative to the input (a scene's meshes differ).
    max_faces = requestedFaces(options, input);
    params.max_faces_from_ratio = max_faces;
    params.min_faces = options.min_faces;
  }
  if (built.bounded && max_faces == 0 && built.mesh.numTriangles() > input.numTriangles()) {
    max_faces = std::max<size_t>(input.numTriangles(), 12);
    params.max_faces_auto = max_faces;
  }
  if (options.kind == ProxyClass::kGeneral)
    max_faces = generalTargetFaces(input, generalOptions(options));
  return max_faces;
}

// The verified candidate closest to the budget. Only a budget the user gave (--max-faces,
// --ratio) fails the run when it is not met; the automatic ones (the input's count, general's
// default ratio) are goals, and soft budgets keep the smallest verified proxy.
VerifiedCandidate chooseWithinBudget(BudgetContext& ctx, VerifiedCandidate chosen) {
  const ProxyGenOptions& options = ctx.options;
  if (ctx.max_faces == 0) return chosen;
  const bool user_budget = options.max_faces > 0 || options.ratio.has_value();
  LadderResult ladder = climbBudgetLadder(ctx, chosen);
  if (!ladder.within && ladder.smallest && user_budget && options.hard_budget)
    throwBudgetNotMet(ctx, ladder.smallest->faces());
  std::optional<VerifiedCandidate>& better = ladder.within ? ladder.within : ladder.smallest;
  if (better && (better->faces() <= chosen.faces() || !chosen.ok)) {
    if (better->source != chosen.source) ctx.report.budget_fallback = better->source;
    chosen = std::move(*better);
  }
  ctx.report.budget_reached = chosen.faces() <= ctx.max_faces;
  return chosen;
}

// The checks of the chosen proxy in the report; true when they all hold.
bool recordChecks(ProxyReport& report, const VerifiedCandidate& chosen, ProxyClass kind) {
  const MeshReport& r = chosen.report;
  const uint64_t si = r.self_intersecting_pairs.value_or(0);
  report.checks = ProxyChecks{r.closed, r.manifold, si, {}, {}, {}, {}, {}, {}};
  bool verified = r.closed && r.manifold && si == 0;
  if (chosen.containment) {
    report.checks.containment = containmentName(chosen.containment->verdict);
    report.checks.containment_detail = chosen.containment->detail;
    report.checks.separation = chosen.containment->separation;
    // chosen.ok: also the clearance (verifyCandidate).
    verified = verified && chosen.ok && chosen.containment->verdict == expectedVerdict(kind);
  }
  return verified;
}

// The chosen proxy proved again against the input's double reading; false (with the reason in
// the checks' detail) when the verdict differs there.
bool provedInDouble(ProxyReport& report, const VerifiedCandidate& chosen, const TriMesh& input,
                    const std::vector<Vec3d>& input_double, const BudgetContext& ctx) {
  // Decimals that floats represent read the same both ways: the float proof is that one too.
  if (readsAsFloat(input, input_double)) {
    report.checks.containment_double = containmentName(chosen.containment->verdict);
    return true;
  }
  ContainmentOptions o;
  o.original_positions = &input_double;
  const ContainmentResult d =
      ctx.timer.run("verify", [&] { return checkContainment(input, chosen.mesh, o); });
  report.checks.containment_double = containmentName(d.verdict);
  if (d.verdict == chosen.containment->verdict) return true;
  report.checks.containment_detail = fmt::format(
      "{} in the float reading of the input, but {} in its double reading: {}",
      containmentName(chosen.containment->verdict), containmentName(d.verdict), d.detail);
  return false;
}

}  // namespace

void addDoubleReading(ProxyGenOptions& options, const std::filesystem::path& file,
                      const TriMesh& input, std::vector<Vec3d>& storage) {
  if (options.kind == ProxyClass::kGeneral || !storesDecimals(file)) return;
  try {
    storage = readDoublePositions(file, input);
    options.input_double = &storage;
  } catch (const Error& e) {
    options.input_double_missing = e.what();
  }
}

namespace {

// Volume ratio and sampled Hausdorff distances against the reference.
void recordMetrics(ProxyReport& report, const TriMesh& proxy, const MeshReport& proxy_report,
                   const TriMesh& reference, const MeshReport& in_report, bool stand_in,
                   const ProxyGenOptions& options) {
  const double diag = reference.diagonal();
  // A closed manifold input's own signed volume (cheap); by ray parity for a watertight
  // non-manifold input or the hole-filled stand-in (proxies/shared/parity_solid.h).
  const std::optional<double> ref_volume = !(in_report.watertight || stand_in) ? std::nullopt
                                           : in_report.closed
                                               ? std::optional<double>(reference.signedVolume())
                                               : parityVolume(reference);
  if (ref_volume && proxy_report.closed && *ref_volume > 0)
    report.volume_ratio = proxy.signedVolume() / *ref_volume;
  HausdorffDistances h;
  h.proxy_to_original =
      sampledOneSidedDistance(proxy, reference, options.hausdorff_samples, options.seed);
  h.original_to_proxy =
      sampledOneSidedDistance(reference, proxy, options.hausdorff_samples, options.seed + 1);
  h.diagonal = diag;
  // Fractions of the diagonal (the unit of --alpha and --offset); "hausdorff" adds scene units.
  report.hausdorff_proxy_to_original = h.proxy_to_original / diag;
  report.hausdorff_original_to_proxy = h.original_to_proxy / diag;
  report.hausdorff = h;
}

[[noreturn]] void throwNotVerified(const TriMesh& input, const ProxyGenOptions& options,
                                   const std::string& method, const VerifiedCandidate& chosen,
                                   const ProxyChecks& checks) {
  const MeshReport& r = chosen.report;
  const uint64_t si = r.self_intersecting_pairs.value_or(0);
  std::string what;
  if (!r.closed)
    what = "the proxy is not closed";
  else if (!r.manifold)
    what = "the proxy is not manifold";
  else if (si > 0)
    what = fmt::format("the proxy has {} self-intersecting face pairs", si);
  else if (chosen.containment->verdict == expectedVerdict(options.kind))
    // The verdict holds in the float reading; the clearance or the double reading does not.
    what = checks.containment_detail.value_or(chosen.containment->detail);
  else
    what = fmt::format("containment is '{}', not '{}': {}",
                       containmentName(chosen.containment->verdict),
                       containmentName(expectedVerdict(options.kind)), chosen.containment->detail);
  throw CheckFailed(input.source,
                    fmt::format("the {} {} proxy failed its guarantee: {}", method,
                                proxyClassName(options.kind), what),
                    inputIsTheProblem(chosen)
                        ? "it is not written: the input bounds no consistent volume "
                          "(non-manifold or self-intersecting parts)"
                        : "it is not written",
                    inputIsTheProblem(chosen) ? "repair the mesh, or use --kind outside"
                                              : failureAdvice(options.kind, method));
}

}  // namespace

ProxyGenResult generateProxy(const TriMesh& input, const ProxyGenOptions& options) {
  const Stopwatch whole;
  const std::string method = resolveMethod(options);
  ProxyReport report;
  StageTimer timer(report.seconds, options.on_stage);
  checkOptionRanges(options);
  // Before CGAL or OpenMesh see the mesh: they crash, abort or loop on some geometry that loads.
  requireProxyGeometry(input, geometryNeed(options.kind, method),
                       fmt::format("the {} {} proxy", method, proxyClassName(options.kind)));
  const TimeBudget budget =
      options.max_seconds > 0 ? TimeBudget(options.max_seconds, input.source) : TimeBudget();

  const MeshReport in_report = timer.run("validate_input", [&] { return validateMesh(input); });
  report.input = inputFacts(input, in_report);
  report.kind = options.kind;
  report.method = method;
  ProxyParameters& params = report.parameters;
  params.max_faces = options.max_faces;
  params.fill_holes = options.fill_holes;
  params.seed = options.seed;
  if (options.max_seconds > 0) params.max_seconds = options.max_seconds;

  // The mesh the proxy is built and verified against: the input, which for inside needs only to
  // bound a volume by ray parity (watertight, non-manifold edges allowed); or the input with its
  // holes filled, a stand-in for which no class holds (written_class.h).
  TriMesh reference = input;
  std::optional<std::string> stand_in;
  if (options.kind == ProxyClass::kInside && !in_report.watertight) {
    // Filling holes closes boundary edges; edges with an odd number of faces stay as they are.
    if (!options.fill_holes || in_report.boundary_edges == 0)
      throw noInteriorError(input.source, in_report.boundary_edges, in_report.odd_edges,
                            "an inside proxy");
    size_t holes = 0;
    reference = timer.run("fill_holes", [&] { return fillHoles(input, &holes); });
    report.holes_filled = holes;
    stand_in = filledHolesReason(in_report.boundary_edges, holes);
    budget.check("the hole filling");
  }

  auto rebuild = [&](const ProxyGenOptions& o) {
    ProxyParameters unused;
    return build(reference, o, method, unused, &budget).mesh;
  };
  if (options.kind != ProxyClass::kGeneral && options.hard_budget && options.max_faces > 0 &&
      options.max_faces < kMinClosedFaces)
    failBelowClosedMinimum(
        {input, reference, options, method, options.max_faces, budget, timer, report, rebuild});
  Built built =
      timer.run("build", [&] { return build(reference, options, method, params, &budget); });
  budget.check("building the proxy");
  report.seeds = built.seeds;
  report.voxels = built.voxels;
  report.parts = built.parts;
  report.faces_before_budget = built.mesh.numTriangles();
  const size_t max_faces = budgetFaces(input, options, built, params);
  params.budget = options.hard_budget ? "hard" : "soft";

  BudgetContext ctx{input, reference, options, method, max_faces, budget, timer, report, rebuild};
  if (options.kind != ProxyClass::kGeneral) {
    ctx.clearance =
        clearanceDistance(input, options.clearance, options.clearance_ulps, options.placements);
    params.clearance = options.clearance;
    if (!options.clearance)
      params.clearance_ulps = options.clearance_ulps.value_or(kDefaultClearanceUlps);
  }
  VerifiedCandidate chosen =
      chooseWithinBudget(ctx, options.kind == ProxyClass::kGeneral
                                  ? verifyCandidate(ctx, std::move(built.mesh), method)
                                  : reduceAndVerify(ctx, built.mesh, method, true));
  bool verified = recordChecks(report, chosen, options.kind);
  if (verified && options.input_double && !stand_in && chosen.containment)
    verified = provedInDouble(report, chosen, input, *options.input_double, ctx);
  if (!options.input_double_missing.empty() && chosen.containment)
    report.checks.containment_double = "not checked: " + options.input_double_missing;
  report.faces = chosen.mesh.numTriangles();
  report.verified = verified;
  setWrittenClass(report, options.kind, verified, stand_in);
  if (stand_in && chosen.containment) report.checks.containment_against = "the hole-filled input";
  if (chosen.containment) report.checks.clearance = ctx.clearance;
  timer.run("metrics", [&] {
    recordMetrics(report, chosen.mesh, chosen.report, reference, in_report, stand_in.has_value(),
                  options);
  });
  report.seconds["total"] = whole.seconds();

  if (options.kind != ProxyClass::kGeneral && !verified)
    throwNotVerified(input, options, method, chosen, report.checks);
  return {std::move(chosen.mesh), verified, std::move(report)};
}

}  // namespace proxyvis
