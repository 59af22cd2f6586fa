#pragma once
// proxy-gen's work on one mesh of a scene: its proxy taken from the proxy cache or generated and
// written, or the reason it gets none (docs/proxies.md, "Whole scenes").
#include <filesystem>
#include <optional>
#include <string>

#include "proxies/pipeline/proxy_cache.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/proxy_report.h"
#include "scene/scene_desc.h"
#include "util/output_set.h"

namespace proxyvis {

// Outside wrap sizes for an open mesh in a scene when none are given (fractions of its
// diagonal). The single-mesh defaults follow every leaf of a plant: on the ecosys prototypes they
// took 602 s and most proxies were not cheaper than their original; these take 7 s
// (docs/proxies.md).
inline constexpr double kOpenMeshWrapAlpha = 0.1;
inline constexpr double kOpenMeshWrapOffset = 0.01;

struct SceneMeshProxy {
  // The generator's report with the mesh's name, its output and the cache state ("cached",
  // "generated", "off"), or the name and why the mesh gets no proxy.
  SceneMeshReport report;
  std::optional<ProxyRef> ref;  // the proxy to list in the scene (absent when skipped)
  std::string skipped;          // why the mesh gets no proxy; empty when it got one
  // What went wrong with the cache (a damaged entry generated again, an entry not stored), for a
  // note on stderr; empty when nothing did.
  std::string cache_note;
};

// Builds (or takes from `cache`, when not null) the proxy of `mesh` with `options` and writes it
// to `out` (with its .sha256 sidecar). A mesh with "make_proxy": false, with fewer than 4 faces,
// without an inside (for an inside proxy of an open mesh), or whose proxy would not have fewer
// faces is skipped. Throws what generateProxy and loadMesh throw.
SceneMeshProxy proxyForSceneMesh(const SceneMeshDesc& mesh, const ProxyGenOptions& options,
                                 const std::filesystem::path& out, const ProxyCache* cache);

// The scene's entry for the proxy in file `out` (content `proxy_bytes`) whose generator report
// is `report`: its class as written, with the file's hash when the class was proven.
ProxyRef proxyRefFor(const ProxyReport& report, ProxyClass kind, const std::filesystem::path& out,
                     const std::string& proxy_bytes);

}  // namespace proxyvis
