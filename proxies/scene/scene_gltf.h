#pragma once
// proxy-gen SCENE --out-dir DIR --gltf OUT.glb: the scene with its new proxies as one glTF file.
#include <filesystem>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "proxies/scene/scene_outputs.h"
#include "util/output_set.h"

namespace proxyvis {

// Stages in `outputs` the scene written to `scene_json` (originals, lights, camera and every
// proxy it lists) as a glTF file at `out`; a proxy made by this run (at proxy_files[i]) carries
// its proof from outcomes[i].report in its mesh's extras (docs/gltf.md).
void addSceneGltfOutput(OutputSet& outputs, const std::filesystem::path& scene_json,
                        const std::vector<MeshOutcome>& outcomes,
                        const std::vector<std::filesystem::path>& proxy_files,
                        const std::filesystem::path& out, GltfCompression compression);

}  // namespace proxyvis
