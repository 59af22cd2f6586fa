#include "proxies/check/pair_check.h"

#include <fmt/core.h>

#include <cmath>

#include "mesh/io/double_reading.h"
#include "proxies/check/mesh_distance.h"
#include "trace/trace_scene.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

std::unique_ptr<TraceScene> buildScene(TraceDevice& device, const TriMesh& mesh) {
  TraceSceneBuilder builder(device);
  builder.addMesh(mesh);
  return builder.build();
}

}  // namespace

MeshSummary summarizeMesh(const TriMesh& mesh, bool closed) {
  MeshSummary s;
  s.source = mesh.source;
  s.faces = mesh.numTriangles();
  s.vertices = mesh.numVertices();
  s.closed = closed;
  s.volume = std::abs(mesh.signedVolume());
  return s;
}

namespace {

// Why a second exact check (`other`, on `other_where`) contradicts the first, or nothing.
std::optional<std::string> verdictsDiffer(const ContainmentResult& first,
                                          const std::optional<ContainmentResult>& other,
                                          const char* first_where, const char* other_where) {
  if (!other || other->verdict == first.verdict) return std::nullopt;
  return fmt::format("the exact check finds '{}' {} and '{}' {} ({})",
                     containmentName(first.verdict), first_where, containmentName(other->verdict),
                     other_where, other->detail);
}

}  // namespace

void finishVerdicts(PairCheckReport& r) {
  r.stats = deriveStats(r.sampled.counts);
  r.sampled_class = sampledClass(r.sampled.counts);
  r.mismatch = sampledExactMismatch(r.sampled.counts, r.exact.verdict);
  r.precision_mismatch = verdictsDiffer(
      r.exact, r.exact_double, "on the float reading of the original", "on the double reading");
  r.placed_mismatch = verdictsDiffer(r.exact, r.exact_placed, "in object space",
                                     "on the placed float copies the renderer traces");
  r.contradiction.reset();
  if (r.expected)
    r.contradiction = contradictsExpectation(*r.expected, r.sampled.counts, r.exact.verdict);
}

PairCheckReport checkPair(const TriMesh& original, const TriMesh& proxy,
                          const PairCheckOptions& options) {
  const Stopwatch whole;
  PairCheckReport r;
  r.seed = options.seed;
  r.rays_requested = options.rays;
  r.expected = options.expect;
  // A double reading equal to the float one (a binary format) is checked once.
  const bool second_reading =
      options.original_double && !readsAsFloat(original, *options.original_double);
  ContainmentOptions reading;
  if (second_reading) reading.original_positions = options.original_double;
  if (options.original_double && options.double_only) {
    r.exact = checkContainment(original, proxy, reading);
    r.precision = "double";
  } else {
    r.exact = checkContainment(original, proxy);
    if (options.original_double) {
      r.exact_double = second_reading ? checkContainment(original, proxy, reading) : r.exact;
      r.precision = "both";
    }
  }
  r.exact_seconds = whole.seconds();
  r.original = summarizeMesh(original, r.exact.original_closed);
  r.proxy = summarizeMesh(proxy, r.exact.proxy_closed);
  // The volume a closed mesh bounds by ray parity, whatever its faces' orientation or manifoldness.
  if (r.exact.original_volume) r.original.volume = std::abs(*r.exact.original_volume);
  if (r.exact.proxy_volume) r.proxy.volume = std::abs(*r.exact.proxy_volume);
  // Distances use their own streams so they never shift the segment streams.
  r.distance_original_to_proxy =
      sampledOneSidedDistance(original, proxy, options.distance_samples, hashKeys(options.seed, 1));
  r.distance_proxy_to_original =
      sampledOneSidedDistance(proxy, original, options.distance_samples, hashKeys(options.seed, 2));
  r.original_diagonal = original.diagonal();

  SegmentGenerator generator = options.generator;
  if (generator || options.classified) {
    r.distribution = options.distribution_name;
    r.distribution_note = options.distribution_note;
  } else {
    generator = sphereSegments(enclosingSphere(original.bounds(), proxy.bounds()), options.seed);
    r.distribution = "sphere";
    r.distribution_note = options.distribution_note.empty() ? "" : options.distribution_note + "; ";
    r.distribution_note +=
        "segments between independent uniform points on a sphere around both meshes: both ends "
        "lie outside both, so an outside proxy can show no HM' and an inside proxy no MH'";
  }
  if (options.classified) {
    r.sampled = *options.classified;
  } else {
    TraceDevice device;
    std::unique_ptr<TraceScene> original_scene = buildScene(device, original);
    std::unique_ptr<TraceScene> proxy_scene = buildScene(device, proxy);
    ClassifyOptions co;
    co.segments = options.rays;
    co.max_attempts = options.max_attempts;
    co.max_error_segments = options.max_error_segments;
    co.quiet = options.quiet;
    r.sampled = classifySegments(*original_scene, *proxy_scene, generator, co);
  }
  if (r.sampled.counts.total() < options.rays)
    r.shortfall = fmt::format(
        "only {} of {} segments classified after {} attempts: the distribution's other segments "
        "pass neither the original nor the proxy{}",
        r.sampled.counts.total(), options.rays, r.sampled.attempts,
        r.distribution_note.empty() ? "" : " (see the distribution note)");
  finishVerdicts(r);
  r.seconds = whole.seconds();
  return r;
}

ProxyClass provenClass(const PairCheckReport& r) {
  if (r.mismatch || r.precision_mismatch || r.placed_mismatch) return ProxyClass::kGeneral;
  if (r.exact.verdict == ContainmentVerdict::kContains) return ProxyClass::kOutside;
  if (r.exact.verdict == ContainmentVerdict::kContained) return ProxyClass::kInside;
  return ProxyClass::kGeneral;
}

}  // namespace proxyvis
