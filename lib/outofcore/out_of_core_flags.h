#pragma once
// The flags `render` and `render-compare` share for out-of-core rendering: the budget, roulette's
// q and cold reads, with one help text each (each program adds its own policy and batch flags).
#include <initializer_list>
#include <string>

namespace CLI {
class App;
}

namespace proxyvis {

struct OutOfCoreCommonFlags {
  std::string geometry_budget;  // empty: in core
  std::string load_q = "0.5";   // proxies-roulette's q, or "learned"
  bool cold_reads = false;
};
// Adds --geometry-budget (its help beginning with `budget_lead`), --load-q and --cold-reads (each
// help beginning with `lead`, e.g. "Out of core: ").
void addOutOfCoreCommonFlags(CLI::App& app, OutOfCoreCommonFlags& flags,
                             const std::string& budget_lead, const std::string& lead);

// Without --geometry-budget: Error for --load-q, --cold-reads or any of the program's own
// out-of-core flags `more` on the command line (they would act on nothing).
void refuseOutOfCoreFlagsAlone(const CLI::App& app, const OutOfCoreCommonFlags& flags,
                               std::initializer_list<const char*> more);

}  // namespace proxyvis
