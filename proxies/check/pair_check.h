#pragma once
// One original/proxy pair checked both ways: exactly (containment) and by sampled segments, with
// the derived statistics, mesh statistics and verdicts that proxy-check reports.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "proxies/check/class_stats.h"
#include "proxies/check/containment.h"
#include "proxies/check/ray_classify.h"
#include "util/proxy_class.h"

namespace proxyvis {

struct MeshSummary {
  std::string source;
  uint64_t faces = 0, vertices = 0;
  bool closed = false;
  double volume = 0;  // |signed volume|; meaningful only when closed
};

struct PairCheckOptions {
  uint64_t rays = 1'000'000;  // segments to classify
  // Indices to draw at most while looking for `rays` segments (a generator may give none for an
  // index); 0 = rays.
  uint64_t max_attempts = 0;
  uint64_t seed = 0;
  std::optional<ProxyClass> expect;
  uint64_t max_error_segments = 0;  // kept for --dump-errors
  uint64_t distance_samples = 20000;
  bool quiet = false;
  // Another segment distribution (e.g. the scene's); empty = the sphere around both meshes.
  SegmentGenerator generator;
  // Segments classified already (proxy-check's scene stream shares its draws among meshes): used
  // as the sampled counts instead of sampling; distribution_name/note describe them.
  const Classification* classified = nullptr;
  std::string distribution_name, distribution_note;
  // The original's vertices read in double (mesh/io/double_reading.h): the exact check then also
  // runs on that reading (`exact_double`), or, with double_only, on that reading alone.
  const std::vector<Vec3d>* original_double = nullptr;
  bool double_only = false;
};

struct PairCheckReport {
  std::string label;  // e.g. "dragon / outside (wrap)" in a scene; empty for a plain pair
  MeshSummary original, proxy;
  double distance_original_to_proxy = 0, distance_proxy_to_original = 0;  // sampled one-sided
  double original_diagonal = 0;  // of the original's bounding box: the distances' yardstick
  ContainmentResult exact;       // on the float reading (the double one with double_only)
  double exact_seconds = 0;
  std::string precision = "float";                // the readings checked: float, double, both
  std::optional<ContainmentResult> exact_double;  // with "both": the double reading's verdict
  // With "both": the two readings' verdicts differ (the class holds in one only). A failure.
  std::optional<std::string> precision_mismatch;
  // A scene's mesh placed with a transform: the exact check on the placed float copies the
  // renderer traces, and the failure when its verdict differs from the object-space one.
  std::optional<ContainmentResult> exact_placed;
  std::optional<std::string> placed_mismatch;
  std::string distribution;  // "sphere" or "scene"
  std::string distribution_note;
  uint64_t seed = 0, rays_requested = 0;
  Classification sampled;
  ClassStats stats;
  SampledClass sampled_class = SampledClass::kEquivalent;
  std::optional<std::string> mismatch;  // sampled vs exact disagree: a bug, reported loudly
  std::optional<ProxyClass> expected;
  std::optional<std::string> contradiction;  // the evidence contradicts `expected`
  // Fewer segments than requested were classified within max_attempts: how many, and why. A
  // warning (the verdicts rest on fewer segments), not a failure.
  std::optional<std::string> shortfall;
  double seconds = 0;  // everything, loading excluded

  bool failed() const {
    return mismatch.has_value() || contradiction.has_value() || precision_mismatch.has_value() ||
           placed_mismatch.has_value();
  }
};

MeshSummary summarizeMesh(const TriMesh& mesh, bool closed);

// Fills the verdict fields (stats, sampled class, mismatch, contradiction) from `sampled`,
// `exact` and `expected`.
void finishVerdicts(PairCheckReport& report);

// The class the exact check proved: outside for `contains`, inside for `contained`, otherwise
// general; general also when the sampled verdict disagrees with it (a mismatch) or the two
// readings disagree.
ProxyClass provenClass(const PairCheckReport& report);

// The exact check, the classification (sphere distribution unless options.generator is set: (both
// ends outside both meshes, as the guarantees require) and the mesh statistics. Throws Error for
// empty meshes.
PairCheckReport checkPair(const TriMesh& original, const TriMesh& proxy,
                          const PairCheckOptions& options);

}  // namespace proxyvis
