#pragma once
// proxy-gen's human summary of one proxy, printed on stdout by default (the JSON report goes to
// --json): what went in and came out, the class and why it holds, volume and Hausdorff distance
// with their units, and the seconds of each stage in the order they run, total last.
#include <string>
#include <utility>
#include <vector>

#include "proxies/pipeline/proxy_report.h"

namespace proxyvis {

// The stages as the summary and the progress bar name them, in the order they run, from the
// report's "seconds" keys ("load" is timed by proxy-gen itself, the rest by the pipeline).
// Several keys can share a name ("simplify" and "budget_ladder" are both the budget reduction).
struct StageName {
  const char* key;    // in the report's "seconds"
  const char* label;  // shown
  int step;           // position among the six steps of the progress bar (0-based)
};
const std::vector<StageName>& proxyGenStages();
inline constexpr int kProxyGenSteps =
    6;  // load, validate, build, budget reduction, verify, measure

// The summary of a proxy-gen report (with proxy-gen's output and load seconds), several lines,
// each ending in a newline.
std::string proxySummaryText(const ProxyReport& report);

}  // namespace proxyvis
