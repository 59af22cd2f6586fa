#pragma once
// `render-compare SCENE --data-parallel --forwarding LIST`: every forwarding policy x estimator
// (exact, roulette) x --spp, over --seeds, rendered data-parallel by the MPI job and scored
// against a data-parallel exact reference; the report (report.json, report.md, report.html and
// the images) has the forward counts, bytes, messages, per-rank peak memory, measured time, MSE,
// and efficiency measured and modelled at --forward-cost-us (docs/data_parallel.md).
#include "distributed/data_parallel_job.h"
#include "study/compare_options.h"

namespace proxyvis {

// `estimators_given`: --estimators was on the command line (else exact,roulette).
int runDataParallelStudy(CompareOptions& options, const DataParallelFlags& flags,
                         bool estimators_given);

}  // namespace proxyvis
