#pragma once
// `render --data-parallel`: the same scene and flags, rendered by every MPI rank of the job
// (lib/distributed); rank 0 writes the image and the summary.
#include <filesystem>
#include <string>

#include "distributed/data_parallel_job.h"
#include "render/render_options.h"
#include "util/app_main.h"

namespace proxyvis {

struct DataParallelRenderRequest {
  std::filesystem::path scene, output;
  std::string estimator;  // "exact" or "roulette"
  int spp = 16;
  double seconds = 0;  // --time: refused (passes are exchanged in rounds of a fixed count)
  RenderFlags render;
  DataParallelFlags data_parallel;
  CommonOptions common;
};

int runDataParallelRender(DataParallelRenderRequest& request);

}  // namespace proxyvis
