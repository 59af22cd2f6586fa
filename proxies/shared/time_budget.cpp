#include "proxies/shared/time_budget.h"

#include <fmt/core.h>

#include "util/error.h"

namespace proxyvis {

TimeBudget::TimeBudget(double seconds, std::string source)
    : limited_(true),
      seconds_(seconds),
      end_(std::chrono::steady_clock::now() +
           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
               std::chrono::duration<double>(seconds))),
      source_(std::move(source)) {}

bool TimeBudget::expired() const {
  return limited_ && std::chrono::steady_clock::now() >= end_;
}

void TimeBudget::check(const char* stage) const {
  if (!expired()) return;
  throw Error(source_, fmt::format("stopped: {} did not finish within {:g} s", stage, seconds_),
              "--max-seconds bounds the work spent on one mesh",
              "raise --max-seconds, or ask for a coarser proxy (larger --alpha, smaller budget)");
}

}  // namespace proxyvis
