#pragma once
// proxy-gen SCENE ... --plan DIR --shards N: the shards of a scene run as the work units of a plan
// that scripts/slurm/submit.sh runs (docs/slurm.md, "proxy-gen's units"). Unit K is
// `proxy-gen SCENE <flags> --shard K/N --out-dir DIR/units/K.shard --done DIR/units/K.done`; the
// merge is `proxy-gen SCENE <flags> --out-dir OUT --merge-shards DIR/units/0.shard ...`.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace proxyvis {

// The largest --shards of a plan: Slurm's default MaxArraySize caps one job array at 1001 tasks.
inline constexpr uint64_t kMaxPlanShards = 1000;

// Writes DIR/plan.json (DIR/units created) for `shards` units whose command lines repeat `flags`
// (the run's own, as "--name=value"); `out_dir` and `json_path` (may be empty) are the merge's
// outputs. Refuses a folder whose units/ already holds finished units.
void writeShardPlan(const std::filesystem::path& dir, uint64_t shards,
                    const std::vector<std::string>& flags, const std::string& out_dir,
                    const std::string& json_path);

// `path` absolute and normalized, as a plan's command lines name files (they run elsewhere).
std::string absolutePathText(const std::string& path);

// Under Slurm a shard uses only the CPUs it was given: `threads` becomes the smaller of it (0 =
// all) and SLURM_CPUS_PER_TASK when that is set.
void limitThreadsToSlurm(int& threads);

}  // namespace proxyvis
