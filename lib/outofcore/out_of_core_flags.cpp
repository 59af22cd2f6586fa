#include "outofcore/out_of_core_flags.h"

#include <CLI/CLI.hpp>

#include "util/error.h"

namespace proxyvis {

void addOutOfCoreCommonFlags(CLI::App& app, OutOfCoreCommonFlags& f, const std::string& budget_lead,
                             const std::string& lead) {
  app.add_option("--geometry-budget", f.geometry_budget,
                 budget_lead +
                     ": originals stay on disk and at most this much of them is built in memory "
                     "at once, in bytes (2G, 500M) or as a share of their in-core size (25%) "
                     "(docs/out_of_core.md)");
  app.add_option("--load-q", f.load_q,
                 lead +
                     "proxies-roulette's probability of loading a mesh with an outside proxy and "
                     "tracing its queue in a batch, or 'learned': per batch and mesh from earlier "
                     "batches' load costs and proxy errors (needs several batches: see "
                     "--batch-passes)")
      ->capture_default_str();
  app.add_flag("--cold-reads", f.cold_reads,
               lead +
                   "drop each original's file from the page cache before it is loaded (that file "
                   "only), so loads read from the disk");
}

void refuseOutOfCoreFlagsAlone(const CLI::App& app, const OutOfCoreCommonFlags& flags,
                               std::initializer_list<const char*> more) {
  if (!flags.geometry_budget.empty()) return;
  auto refuse = [&](const char* name) {
    if (app.count(name) > 0)
      throw Error("", std::string(name) + " needs --geometry-budget",
                  "it only acts on the out-of-core renderer", "give --geometry-budget, or drop it");
  };
  for (const char* name : {"--load-q", "--cold-reads"}) refuse(name);
  for (const char* name : more) refuse(name);
}

}  // namespace proxyvis
