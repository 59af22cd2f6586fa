#pragma once
// The command-line side of proxy-gen's shards and plans (proxies/scene/shard.h, shard_plan.h):
// the check of --shard, and the flags a plan's units and merge repeat.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace proxyvis {

// The check of --shard, with a message that says what is wrong.
CLI::Validator shardSpecValidator();

// The flags of the parsed command line that a unit and the merge repeat, as "--name=value": the
// scene, --cache made absolute; without --plan, --shards, --out-dir, --json, --help, --version.
std::vector<std::string> planFlags(const CLI::App& app);

}  // namespace proxyvis
