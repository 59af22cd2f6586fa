#include "proxies/pipeline/gltf_proof.h"

#include "proxies/check/check_report.h"
#include "proxies/check/containment.h"
#include "proxies/check/pair_check.h"
#include "proxies/pipeline/written_class.h"
#include "util/error.h"

namespace proxyvis {
using json = nlohmann::json;

json gltfProofExtras(const json& report, const std::string& source_sha256,
                     const std::string& program_build) {
  json proof;
  proof["class"] = report.value("class", json());
  proof["kind"] = report.value("kind", json());
  if (report.contains("class_reason")) proof["class_reason"] = report["class_reason"];
  proof["verified"] = report.value("verified", false);
  proof["method"] = report.value("method", json());
  proof["budget"] =
      report.contains("parameters") ? report["parameters"].value("budget", json()) : json();
  proof["max_faces"] =
      report.contains("parameters") ? report["parameters"].value("max_faces", json()) : json();
  proof["faces"] = report.value("faces", json());
  proof["volume_ratio"] = report.value("volume_ratio", json());
  if (report.contains("hausdorff")) proof["hausdorff"] = report["hausdorff"];
  if (report.contains("checks")) {
    const json& checks = report["checks"];
    proof["containment"] = checks.value("containment", json());
    proof["containment_detail"] = checks.value("containment_detail", json());
    proof["closed"] = checks.value("closed", json());
    proof["manifold"] = checks.value("manifold", json());
    proof["self_intersecting_pairs"] = checks.value("self_intersecting_pairs", json());
  }
  proof["segments"] = nullptr;  // gltfSegmentEvidence, when the caller classified segments
  proof["source_sha256"] = source_sha256;
  proof["program_build"] = program_build;
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
  const json check = toJson(report);
  const json& intervals = check["intervals"];
  return {{"distribution", "sphere"},
          {"rays", report.rays_requested},
          {"seed", report.seed},
          {"counts", check["counts"]},
          {"HM_rate_upper_95", intervals["HM"].value("hi", json())},
          {"MH_rate_upper_95", intervals["MH"].value("hi", json())},
          {"sampled_class", check["sampled_class"]}};
}

void proveWrittenProxy(const TriMesh& original, const TriMesh& written, json& report,
                       const std::string& file) {
  const std::optional<ProxyClass> cls = writtenClass(report);
  if (!cls || *cls == ProxyClass::kGeneral) return;
  const ContainmentResult r = checkContainment(original, written);
  const ContainmentVerdict expected =
      *cls == ProxyClass::kOutside ? ContainmentVerdict::kContains : ContainmentVerdict::kContained;
  report["written_check"] = {{"containment", containmentName(r.verdict)}, {"detail", r.detail}};
  if (r.verdict != expected)
    throw CheckFailed(
        file, "the quantized proxy is no longer " + std::string(proxyClassName(*cls)),
        std::string("after encoding: ") + containmentName(r.verdict) + " (" + r.detail + ")",
        "write it without quantization (--draco-bits 0) or with meshopt; nothing "
        "was written");
}

std::string gltfProxyNodeName(const std::string& original, const json& report) {
  const std::string cls = report.value("class", json()).is_string()
                              ? report["class"].get<std::string>()
                              : std::string("general");
  if (cls == "inside") return original + "-occonly";
  if (cls == "outside") return original + "-occludee";
  return original + "-lod";
}

}  // namespace proxyvis
