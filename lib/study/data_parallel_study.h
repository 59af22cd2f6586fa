#pragma once
// `render-compare SCENE --data-parallel --forwarding LIST`: every forwarding policy x estimator
// (exact, roulette) x --spp, over --seeds, rendered data-parallel by the MPI job and scored
// against a data-parallel exact reference; the report (report.json, report.md, report.html and
// the images) has the forward counts, bytes, messages, per-rank peak memory, measured time (on
// shared memory, and with --emulate-network under the emulated fabric), MSE, and efficiency
// measured and modelled on --network (docs/data_parallel.md).
#include "distributed/data_parallel_job.h"
#include "study/compare_options.h"

namespace proxyvis {

int runDataParallelStudy(CompareOptions& options, const DataParallelFlags& flags,
                         const StudyFlagsGiven& given);

}  // namespace proxyvis
