#pragma once
// proxy-gen SCENE --out-dir DIR: the proxies of every mesh of a scene (or of one shard of it),
// generated in parallel or taken from the proxy cache, then the scene with its proxies, the
// report, and for a shard its manifest (docs/proxies.md, "Whole scenes";
// docs/proxy_gen_shards.md).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "proxies/pipeline/proxy_cache.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "util/app_main.h"

namespace proxyvis {

struct SceneRunRequest {
  std::string scene;              // SCENE as named on the command line
  std::string out_dir;            // --out-dir
  std::string kind;               // --kind
  ProxyGenOptions base;           // every mesh's settings; its seed is the run's (--seed)
  std::string cache_dir;          // --cache (empty = the default folder)
  bool no_cache = false;          // --no-cache
  std::string shard;              // --shard i/n as given (checked); empty = the whole scene
  std::string done_file;          // --done: a plan unit's marker, written last on success
  std::string scene_gltf;         // --gltf: the scene with its proxies as one glTF file
  std::string compress = "none";  // --compress of that file
  bool progress = false;          // --progress: the bar also when stderr is not a terminal
};

// The run; returns its exit code (the worst mesh's). Throws Error before any work for outputs
// that would replace an input or an unusable --cache, WriteError when DIR cannot be made.
int runSceneProxies(const SceneRunRequest& request, const CommonOptions& common);

// The proxy cache folder a scene run asks for: `cache_dir` when given, none with `no_cache`,
// else the default folder (none without one).
std::optional<std::string> cacheDirSetting(const std::string& cache_dir, bool no_cache);

}  // namespace proxyvis
