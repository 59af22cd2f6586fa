#include "proxies/scene/scene_gltf.h"

#include "proxies/pipeline/gltf_proof.h"
#include "scene/gltf_scene_export.h"
#include "util/lower_case.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace proxyvis {
namespace fs = std::filesystem;
using json = nlohmann::json;

void addSceneGltfOutput(OutputSet& outputs, const fs::path& scene_json,
                        const std::vector<MeshOutcome>& outcomes,
                        const std::vector<fs::path>& proxy_files, const fs::path& out,
                        GltfCompression compression) {
  const SceneDesc scene = loadSceneDesc(scene_json);
  std::vector<TriMesh> originals;
  std::vector<std::vector<TriMesh>> proxy_meshes(scene.meshes.size());
  std::vector<std::vector<GltfSceneProxy>> proxies(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const SceneMeshDesc& mesh = scene.meshes[m];
    originals.push_back(loadSceneMesh(mesh));
    proxy_meshes[m].reserve(mesh.proxies.size());  // stable addresses below
    for (const ProxyRef& ref : mesh.proxies) {
      GltfSceneProxy p;
      p.mesh = &proxy_meshes[m].emplace_back(loadMesh(ref.file));
      p.cls = ref.verified_class ? proxyClassName(*ref.verified_class) : "general";
      std::error_code ec;
      const bool made_now = m < proxy_files.size() && fs::equivalent(ref.file, proxy_files[m], ec);
      if (made_now && m < outcomes.size() && outcomes[m].report.proxy) {
        json proof =
            gltfProofExtras(*outcomes[m].report.proxy, sha256OfFile(mesh.file), programBuildId());
        if (mesh.gltf_mesh >= 0) proof["source_gltf_mesh"] = mesh.gltf_mesh;
        p.extras = {{"proxyvis", proof}};
      } else {
        p.extras = {{"proxyvis", {{"class", p.cls}, {"sha256", ref.sha256}}}};
      }
      proxies[m].push_back(std::move(p));
    }
  }
  const bool binary = lowerExtension(out) == ".glb";  // the caller allows .glb and .gltf only
  outputs.addText(out,
                  encodeSceneGltf(scene, originals, proxies, binary, compression, out.string()));
}

}  // namespace proxyvis
