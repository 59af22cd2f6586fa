#include "proxies/pipeline/proxy_outputs.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "proxies/check/check_view3d.h"
#include "proxies/pipeline/gltf_proof.h"
#include "util/error.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

void stageProxyOutputs(const ProxyOutputRequest& r, const TriMesh& input, ProxyGenResult& result,
                       OutputSet& outputs) {
  const bool gltf = isGltfPath(r.output);
  std::optional<PairCheckReport> check;
  if ((gltf || !r.report_html.empty()) && r.check_rays > 0)
    check = classifyProxySegments(input, result.proxy, r.check_rays, r.seed,
                                  r.report_html.empty() ? 0 : kReportErrorSegments);
  SaveOptions save;
  save.draco_quantization = r.draco_bits;
  save.gltf_compression = parseGltfCompression(r.compress, r.output);
  if (gltf) {
    save.gltf_name = gltfProxyNodeName(fs::path(r.input).stem().string(), result.report);
    json proof = gltfProofExtras(result.report, sha256OfFile(r.input), programBuildId());
    if (!r.pick.mesh.empty()) proof["source_mesh"] = r.pick.mesh;
    if (!r.pick.node.empty()) proof["source_node"] = r.pick.node;
    if (check) proof["segments"] = gltfSegmentEvidence(*check);
    save.gltf_extras = {{"proxyvis", proof}};
  }
  const std::string bytes = encodeMesh(result.proxy, r.output, save);
  if (movesVertices(r.output, save))
    proveWrittenProxy(input, parseMeshBytes(bytes, r.output), result.report, r.output);
  addEncodedMeshOutput(outputs, bytes, r.output);
  if (!r.report_html.empty()) {
    if (!check)
      throw Error("", "--report needs classified segments", "--check-rays 0 classifies none",
                  "drop --check-rays 0");
    outputs.addText(r.report_html, checkReportHtml(input, result.proxy, *check));
    result.report.report_html = r.report_html;
  }
}

void noteWrittenClass(const ProxyReport& report, const std::string& file) {
  if (!report.class_reason) return;
  std::fprintf(stderr, "proxy-gen: note: %s: written as class %s, not %s: %s\n", file.c_str(),
               proxyClassName(report.written_class.value_or(ProxyClass::kGeneral)),
               proxyClassName(report.kind), report.class_reason->c_str());
}

void emit(const json& report, const std::string& summary, const CommonOptions& common,
          OutputSet& outputs) {
  if (!common.json_path.empty()) outputs.addText(common.json_path, report.dump(2) + "\n");
  outputs.commit();
  printHumanReport(common, summary);
}

}  // namespace proxyvis
