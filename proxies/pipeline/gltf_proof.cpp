#include "proxies/pipeline/gltf_proof.h"

#include "proxies/check/check_report.h"
#include "proxies/check/containment.h"
#include "proxies/check/pair_check.h"
#include "util/error.h"

namespace proxyvis {
using json = nlohmann::json;

json gltfProofExtras(const ProxyReport& report, const std::string& source_sha256,
                     const std::string& program_build) {
  const json r = report;
  const json& checks = r["checks"];
  json proof = {{"class", r["class"]},
                {"kind", r["kind"]},
                {"verified", report.verified},
                {"method", report.method},
                {"budget", report.parameters.budget},
                {"max_faces", report.parameters.max_faces},
                {"faces", report.faces},
                {"volume_ratio", r["volume_ratio"]},
                {"hausdorff", r["hausdorff"]},
                {"containment", checks.value("containment", json())},
                {"containment_detail", checks.value("containment_detail", json())},
                {"clearance", checks.value("clearance", json())},
                {"separation", checks.value("separation", json())},
                {"closed", report.checks.closed},
                {"manifold", report.checks.manifold},
                {"self_intersecting_pairs", report.checks.self_intersecting_pairs},
                {"segments", nullptr},  // gltfSegmentEvidence, when the caller classified segments
                {"source_sha256", source_sha256},
                {"program_build", program_build}};
  if (report.class_reason) proof["class_reason"] = *report.class_reason;
  return proof;
}

PairCheckReport classifyProxySegments(const TriMesh& original, const TriMesh& proxy, uint64_t rays,
                                      uint64_t seed, uint64_t keep_errors) {
  PairCheckOptions options;
  options.rays = rays;
  options.seed = seed;
  options.distance_samples = 1000;  // the report's own distances are the ones kept
  options.quiet = true;
  options.max_error_segments = keep_errors;
  return checkPair(original, proxy, options);
}

json gltfSegmentEvidence(const PairCheckReport& report) {
  return {{"distribution", "sphere"},
          {"rays", report.rays_requested},
          {"seed", report.seed},
          {"counts", countsJson(report.sampled.counts)},
          {"HM_rate_upper_95", rateUpper(report.stats.hm)},
          {"MH_rate_upper_95", rateUpper(report.stats.mh)},
          {"sampled_class", sampledClassName(report.sampled_class)}};
}

void proveWrittenProxy(const TriMesh& original, const TriMesh& written, ProxyReport& report,
                       const std::string& file) {
  const std::optional<ProxyClass> cls = report.written_class;
  if (!cls || *cls == ProxyClass::kGeneral) return;
  const ContainmentResult r = checkContainment(original, written);
  const ContainmentVerdict expected =
      *cls == ProxyClass::kOutside ? ContainmentVerdict::kContains : ContainmentVerdict::kContained;
  report.written_check = WrittenCheck{containmentName(r.verdict), r.detail};
  if (r.verdict != expected)
    throw CheckFailed(
        file, "the quantized proxy is no longer " + std::string(proxyClassName(*cls)),
        std::string("after encoding: ") + containmentName(r.verdict) + " (" + r.detail + ")",
        "write it without quantization (--draco-bits 0) or with meshopt; nothing "
        "was written");
}

std::string gltfProxyNodeName(const std::string& original, const ProxyReport& report) {
  const ProxyClass cls = report.written_class.value_or(ProxyClass::kGeneral);
  if (cls == ProxyClass::kInside) return original + "-occonly";
  if (cls == ProxyClass::kOutside) return original + "-occludee";
  return original + "-lod";
}

}  // namespace proxyvis
