#pragma once
// What proxy-gen writes for one mesh (docs/proxy_reports.md, docs/gltf.md): the proxy file (a
// glTF with its proof in the node's extras, proved again when quantization moved its vertices),
// the --report page, the JSON report and the text summary.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "mesh/io/mesh_io.h"
#include "mesh/tri_mesh.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/proxy_report.h"
#include "util/app_main.h"
#include "util/output_set.h"

namespace proxyvis {

// HM'/MH' segments kept for --report's 3D view (it draws a few thousand of each class).
inline constexpr uint64_t kReportErrorSegments = 2000;

struct ProxyOutputRequest {
  std::string input;        // the mesh file as named on the command line
  GltfPick pick;            // the part of a glTF input (--mesh / --node)
  std::string output;       // -o: .ply, .obj, .off, .drc, .gltf, .glb
  std::string compress;     // --compress (glTF output): none, draco, meshopt
  int draco_bits = 0;       // --draco-bits
  std::string report_html;  // --report (empty = none)
  uint64_t check_rays = 0;  // segments classified for a glTF's proof and for --report
  uint64_t seed = 0;
};

// Stages the proxy file and the --report page in `outputs`, and records the page (and a
// re-proved quantized glTF's written_check) in result.report. Throws CheckFailed when a
// quantized proxy loses its class, Error when --report has no segments to show.
void stageProxyOutputs(const ProxyOutputRequest& request, const TriMesh& input,
                       ProxyGenResult& result, OutputSet& outputs);

// A proxy written with another class than the kind asked for (e.g. general for --fill-holes:
// the guarantee would hold only for the hole-filled mesh) gets one note line on stderr.
void noteWrittenClass(const ProxyReport& report, const std::string& file);

// The JSON goes to --json, put in place after the files staged in `outputs` that it describes;
// the human summary to stdout, or to stderr when stdout carries JSON.
void emit(const nlohmann::json& report, const std::string& summary, const CommonOptions& common,
          OutputSet& outputs);

}  // namespace proxyvis
