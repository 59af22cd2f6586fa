#pragma once
// `render-compare SCENE --geometry-budget B`: the out-of-core policies (exact-batched,
// proxies-exact, proxies-roulette) x --batch-passes x --spp, each over --seeds with the
// configurations interleaved seed by seed, rendered with the originals on disk and at most B
// bytes of them built; scored against a converged exact reference (MSE, efficiency relative to
// the best exact-batched batch at the same spp) with the loads, bytes read, load seconds and
// peak RSS of each, and the oracle ceiling of this setting (docs/out_of_core.md).
#include <string>

#include "outofcore/out_of_core_flags.h"
#include "study/compare_options.h"

namespace CLI {
class App;
}

namespace proxyvis {

struct OutOfCoreStudyFlags : OutOfCoreCommonFlags {
  std::string policies = "exact-batched,proxies-exact,proxies-roulette";
  std::string batch_passes = "0";  // a list: each is a configuration (0: the whole frame)
};
// Adds --geometry-budget, --ooc-policies, --batch-passes, --load-q and --cold-reads.
void addOutOfCoreStudyFlags(CLI::App& app, OutOfCoreStudyFlags& flags);

int runOutOfCoreStudy(CompareOptions& options, const OutOfCoreStudyFlags& flags,
                      const StudyFlagsGiven& given);

}  // namespace proxyvis
