#include "shard_flags.h"

#include <fmt/core.h>

#include <set>

#include "proxies/scene/shard.h"
#include "proxies/scene/shard_plan.h"

namespace proxyvis {

CLI::Validator shardSpecValidator() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        if (parseShardSpec(value)) return {};
        return fmt::format("must be i/n with 0 <= i < n <= {} (e.g. 0/4), got '{}'", kMaxShards,
                           value);
      },
      "i/n");
}

std::vector<std::string> planFlags(const CLI::App& app) {
  static const std::set<std::string> left_out{"--plan", "--shards", "--out-dir",
                                              "--json", "--help",   "--version"};
  std::vector<std::string> flags;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0) continue;
    if (opt->get_positional()) {
      flags.push_back(absolutePathText(opt->results().front()));
      continue;
    }
    if (opt->get_lnames().empty()) continue;
    const std::string name = "--" + opt->get_lnames().front();
    if (left_out.count(name)) continue;
    // One "--name=value" per value given: flags read back their "true" this way too.
    for (const std::string& value : opt->results())
      flags.push_back(name + "=" + (name == "--cache" ? absolutePathText(value) : value));
  }
  return flags;
}

}  // namespace proxyvis
