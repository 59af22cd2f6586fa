// The out-of-core renderer's settings from their flags' text (contract in out_of_core_render.h).
#include <fmt/core.h>

#include <optional>

#include "outofcore/out_of_core_render.h"
#include "util/app_main.h"
#include "util/error.h"

namespace proxyvis {

const char* outOfCorePolicyName(OutOfCorePolicy p) {
  switch (p) {
    case OutOfCorePolicy::kExactBatched:
      return "exact-batched";
    case OutOfCorePolicy::kProxiesExact:
      return "proxies-exact";
    case OutOfCorePolicy::kProxiesRoulette:
      return "proxies-roulette";
  }
  return "?";
}

OutOfCorePolicy parseOutOfCorePolicy(const std::string& name) {
  for (OutOfCorePolicy p : {OutOfCorePolicy::kExactBatched, OutOfCorePolicy::kProxiesExact,
                            OutOfCorePolicy::kProxiesRoulette})
    if (name == outOfCorePolicyName(p)) return p;
  throw Error("", "--ooc-policy: unknown policy '" + name + "'", {},
              "use exact-batched, proxies-exact or proxies-roulette");
}

void applyLoadQ(const std::string& text, OutOfCoreSettings& settings) {
  settings.learn_q = text == "learned";
  if (settings.learn_q) return;
  const std::optional<double> q = parseNumber(text);
  if (!q || !(*q > 0 && *q <= 1))
    throw Error("", "--load-q " + text + " is not a probability in (0, 1] or 'learned'", {},
                "e.g. --load-q 0.5, or --load-q learned (per mesh, from earlier batches)");
  settings.load_q = *q;
}

std::string loadQText(const OutOfCoreSettings& settings) {
  return settings.learn_q ? "learned" : fmt::format("{:g}", settings.load_q);
}

}  // namespace proxyvis
