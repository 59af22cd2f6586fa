#pragma once
// What a proxy written as glTF carries about itself: its node's name (following the engines'
// conventions where one exists) and the proof in the node's extras (docs/gltf.md); and the proof
// of a proxy that an encoder moved (quantization).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "mesh/tri_mesh.h"
#include "proxies/check/pair_check.h"
#include "proxies/pipeline/proxy_report.h"

namespace proxyvis {

// extras.proxyvis of a proxy's node, from proxy-gen's report: class, kind, method, budget, faces,
// volume ratio, Hausdorff distances with their unit, the exact containment verdict, the input's
// SHA-256 and the program's build.
nlohmann::json gltfProofExtras(const ProxyReport& report, const std::string& source_sha256,
                               const std::string& program_build);

// `rays` segments of the sphere distribution classified against both meshes (seeded), keeping up
// to `keep_errors` HM'/MH' segments (for a report's 3D view).
PairCheckReport classifyProxySegments(const TriMesh& original, const TriMesh& proxy, uint64_t rays,
                                      uint64_t seed, uint64_t keep_errors);

// extras.proxyvis.segments from such a check: the HH/HM/MH/MM counts and the 95 % upper bounds
// on the HM and MH rates.
nlohmann::json gltfSegmentEvidence(const PairCheckReport& report);

// A proxy is proved before it is encoded; an encoder that moves vertices (Draco quantization)
// writes another mesh. Checks `written` (the file decoded again) exactly against `original` for
// the class in `report` and records the verdict as its written_check; throws CheckFailed when
// the written mesh no longer has the class. A general proxy needs no such proof.
void proveWrittenProxy(const TriMesh& original, const TriMesh& written, ProxyReport& report,
                       const std::string& file);

// The node name of a proxy of `original` with the written class in `report`: "NAME-occonly" for
// inside proxies (Godot imports such nodes as occluders only), "NAME-occludee" for outside
// proxies (bounding volumes), "NAME-lod" for general ones.
std::string gltfProxyNodeName(const std::string& original, const ProxyReport& report);

}  // namespace proxyvis
