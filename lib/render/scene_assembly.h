#pragma once
// What a scene renders, decided once for both renderers: the objects (renderObjects), the proxy
// each mesh is traced with, and the BVH build. The single-process renderer (loadRenderScene) and
// the data-parallel one (DistributedScene) assemble a scene through these functions only, so that
// for the same flags both build the same Embree scenes and an exact data-parallel image equals the
// single-process one bit for bit.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/render_scene.h"
#include "render/render_scene_build.h"
#include "scene/scene_desc.h"

namespace proxyvis {

// The proxy of `mesh` that `options` ask for (-1: none): the first whose "kind" is
// options.proxy_kind, or the first listed when that is empty; none when !options.use_proxies.
// Reads no file: what the class checks (proxies/check/class_trust.h) look at before loading.
int requestedProxy(const SceneMeshDesc& mesh, const RenderSceneOptions& options);

// The index of the first proxy of `mesh` whose "kind" is `kind`, -1 if none.
int proxyOfKind(const SceneMeshDesc& mesh, const std::string& kind);

struct ProxyChoice {
  int proxy = -1;       // the proxy traced in place of the original, -1: the original
  std::string dropped;  // a warning when the requested proxy is not traced, else empty
};

// The proxy the renderers trace for `mesh`: requestedProxy(), unless it has at least as many
// triangles as the original (`original_triangles`) and !options.keep_larger_proxies. Such a proxy
// cannot make a ray cheaper while the self-shadowing rule makes every ray from its object pay for
// two traversals: the original is its own exact proxy. `proxy_triangles(index)` gives the
// requested proxy's triangle count; it is called once, and only when a proxy is requested (so a
// caller may load the proxy in it).
ProxyChoice chooseProxy(const SceneMeshDesc& mesh, const RenderSceneOptions& options,
                        uint64_t original_triangles,
                        const std::function<uint64_t(size_t proxy)>& proxy_triangles);

struct SceneAssembly {
  std::vector<RenderObject> objects;  // renderObjects(): ids as in every Embree scene
  std::vector<int> proxy;             // per mesh: the proxy traced, -1 = the original
  std::vector<bool> used;             // per mesh: placed, or the mesh of an instance

  // Per mesh, the proxy chooseProxy() settled on; every object of the mesh follows it.
  void setProxy(size_t mesh, int proxy_index);
  bool anyProxy() const;  // some object is traced with a proxy
};

// The objects and each mesh's requested proxy (chooseProxy() narrows it once the triangles are
// known). Throws Error as renderObjects().
SceneAssembly assembleScene(const SceneDesc& desc, const RenderSceneOptions& options);

// The build of the scene's Embree scenes (chooseBuild) from the triangles it would flatten: every
// object's original and, when some object uses a proxy, every object's proxy (its original where
// it has none), as the proxies' scene holds them. Per mesh: `original_triangles`, and
// `proxy_triangles` of the mesh's chosen proxy (ignored where it has none).
BuildChoice chooseSceneBuild(const SceneAssembly& assembly, const SceneDesc& desc,
                             const RenderSceneOptions& options,
                             const std::vector<uint64_t>& original_triangles,
                             const std::vector<uint64_t>& proxy_triangles);

}  // namespace proxyvis
