#pragma once
// proxy-gen SCENE --merge-shards DIR...: the shards of a scene run merged into the output of one
// whole run, byte for byte (docs/proxy_gen_shards.md). The merge trusts only the shards'
// manifests (shard_manifest.h) and the proxy files' hashes recorded there.
#include <optional>
#include <string>
#include <vector>

#include "proxies/pipeline/proxy_pipeline.h"
#include "util/app_main.h"

namespace proxyvis {

struct MergeRequest {
  std::string scene;    // SCENE as named on the command line
  std::string out_dir;  // --out-dir: where the whole run would write
  std::string kind;
  ProxyGenOptions base;  // the settings given to the merge, which must be the shards'
  std::optional<std::string> cache_dir;
  std::vector<std::string> shard_dirs;
};

// Checks that `request.shard_dirs` hold shards 0..n-1 of one split of this scene, each exactly
// once, made with these settings by this build, with intact files; then writes DIR/<mesh>.<kind>
// .ply (with sidecars), DIR/scene.json and the report exactly as the whole run would, and returns
// its exit code. Throws Error naming the offending file (nothing written) otherwise.
int mergeShards(const MergeRequest& request, const CommonOptions& common);

}  // namespace proxyvis
