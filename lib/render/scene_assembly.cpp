// The objects, proxies and build of a scene, for both renderers (see scene_assembly.h).
#include "render/scene_assembly.h"

#include <fmt/core.h>

namespace proxyvis {

int proxyOfKind(const SceneMeshDesc& mesh, const std::string& kind) {
  for (size_t i = 0; i < mesh.proxies.size(); ++i)
    if (mesh.proxies[i].kind == kind) return int(i);
  return -1;
}

int requestedProxy(const SceneMeshDesc& mesh, const RenderSceneOptions& options) {
  if (!options.use_proxies) return -1;
  if (options.proxy_kind.empty()) return mesh.proxies.empty() ? -1 : 0;
  return proxyOfKind(mesh, options.proxy_kind);
}

ProxyChoice chooseProxy(const SceneMeshDesc& mesh, const RenderSceneOptions& options,
                        uint64_t original_triangles,
                        const std::function<uint64_t(size_t proxy)>& proxy_triangles) {
  ProxyChoice choice;
  choice.proxy = requestedProxy(mesh, options);
  if (choice.proxy < 0) return choice;
  const uint64_t triangles = proxy_triangles(size_t(choice.proxy));
  if (options.keep_larger_proxies || triangles < original_triangles) return choice;
  choice.dropped = fmt::format(
      "mesh '{}': proxy {} has {} triangles, the original {}: not cheaper, the original is used "
      "in its place",
      mesh.name, mesh.proxies[size_t(choice.proxy)].file.filename().string(), triangles,
      original_triangles);
  choice.proxy = -1;
  return choice;
}

void SceneAssembly::setProxy(size_t mesh, int proxy_index) {
  // Both loaders call this for every mesh, and nearly always with the proxy assembleScene()
  // requested: only a change needs the pass over the objects (10^6 instances x 10^3 meshes would
  // otherwise cost 10^9 steps at load).
  if (proxy[mesh] == proxy_index) return;
  proxy[mesh] = proxy_index;
  for (RenderObject& o : objects)
    if (o.mesh == mesh) o.proxy = proxy_index;
}

bool SceneAssembly::anyProxy() const {
  for (const RenderObject& o : objects)
    if (o.proxy >= 0) return true;
  return false;
}

SceneAssembly assembleScene(const SceneDesc& desc, const RenderSceneOptions& options) {
  SceneAssembly a;
  const size_t num_meshes = desc.meshes.size();
  a.proxy.resize(num_meshes);
  for (size_t m = 0; m < num_meshes; ++m) a.proxy[m] = requestedProxy(desc.meshes[m], options);
  a.objects = renderObjects(desc, a.proxy);
  a.used.assign(num_meshes, false);
  for (const RenderObject& o : a.objects) a.used[o.mesh] = true;
  return a;
}

BuildChoice chooseSceneBuild(const SceneAssembly& assembly, const SceneDesc& desc,
                             const RenderSceneOptions& options,
                             const std::vector<uint64_t>& original_triangles,
                             const std::vector<uint64_t>& proxy_triangles) {
  const bool any_proxy = assembly.anyProxy();
  uint64_t flat_triangles = 0;
  for (const RenderObject& o : assembly.objects) {
    const uint64_t original = original_triangles[o.mesh];
    flat_triangles += original;
    if (any_proxy) flat_triangles += o.proxy >= 0 ? proxy_triangles[o.mesh] : original;
  }
  return chooseBuild(options.instance_build, !desc.instances.empty(), flat_triangles,
                     options.memory_budget_bytes);
}

}  // namespace proxyvis
