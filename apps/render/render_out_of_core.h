#pragma once
// `render --geometry-budget B`: the same scene and flags, rendered with the originals on disk
// and at most B bytes of built originals in memory (lib/outofcore); exact visibility, by the
// policy --ooc-policy names.
#include <filesystem>
#include <string>

#include "outofcore/out_of_core_flags.h"
#include "render/render_options.h"
#include "util/app_main.h"

namespace CLI {
class App;
}

namespace proxyvis {

struct OutOfCoreFlags : OutOfCoreCommonFlags {
  std::string policy = "exact-batched";
  int batch_passes = 0;  // 0: the whole frame in one batch
};
// Adds --geometry-budget, --ooc-policy, --batch-passes, --load-q and --cold-reads.
void addOutOfCoreFlags(CLI::App& app, OutOfCoreFlags& flags);

struct OutOfCoreRenderRequest {
  std::filesystem::path scene, output;
  std::string estimator;  // must be "exact": the policy decides how
  int spp = 16;
  double seconds = 0;  // --time: refused (not yet available out of core)
  RenderFlags render;
  OutOfCoreFlags out_of_core;
  CommonOptions common;
};

int runOutOfCoreRender(OutOfCoreRenderRequest& request);

}  // namespace proxyvis
