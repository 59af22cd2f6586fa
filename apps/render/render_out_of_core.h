#pragma once
// `render --geometry-budget B`: the same scene and flags, rendered with the originals on disk
// and at most B bytes of built originals in memory (lib/outofcore); exact visibility, by the
// policy --ooc-policy names.
#include <filesystem>
#include <string>

#include "render/render_options.h"
#include "util/app_main.h"

namespace CLI {
class App;
}

namespace proxyvis {

struct OutOfCoreFlags {
  std::string geometry_budget;  // empty: in core
  std::string policy = "exact-batched";
  int batch_passes = 0;  // 0: the whole frame in one batch
  bool cold_reads = false;
  std::string load_q = "0.5";  // proxies-roulette's probability of tracing a mesh's queue, or
                               // "learned"
};
// Adds --geometry-budget, --ooc-policy, --batch-passes and --load-q.
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
