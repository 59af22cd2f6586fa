#include "proxies/scene/shard_plan.h"

#include <fmt/core.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "util/app_main.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/plan_folder.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

std::string absolutePathText(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

void writeShardPlan(const fs::path& dir, uint64_t shards, const std::vector<std::string>& flags,
                    const std::string& out_dir, const std::string& json_path) {
  createPlanFolder(dir, "run");
  const std::string program = planningProgram();
  PlanCommands commands;
  commands.name = "proxy-gen";
  commands.units = shards;
  // Units and merge run the planned command line: the program and the run's own flags.
  std::vector<std::string> planned{program};
  planned.insert(planned.end(), flags.begin(), flags.end());
  commands.run_unit = planned;
  commands.run_unit.insert(commands.run_unit.end(), {"--shard", fmt::format("{{unit}}/{}", shards),
                                                     "--out-dir", "{plan_dir}/units/{unit}.shard",
                                                     "--done", "{plan_dir}/units/{unit}.done"});
  commands.merge = std::move(planned);
  commands.merge.push_back("--out-dir=" + absolutePathText(out_dir));
  if (!json_path.empty())
    commands.merge.push_back("--json=" +
                             (json_path == "-" ? json_path : absolutePathText(json_path)));
  commands.merge.push_back("--merge-shards");
  for (uint64_t k = 0; k < shards; ++k)
    commands.merge.push_back(fmt::format("{{plan_dir}}/units/{}.shard", k));
  json plan = commands;
  plan["proxy_gen"] = {{"shards", shards}, {"flags", flags}};
  writeTextAtomically(dir / "plan.json", plan.dump(2) + "\n");
}

void limitThreadsToSlurm(int& threads) {
  const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
  if (!cpus) return;
  const std::optional<double> n = parseNumber(cpus);
  if (!n || *n < 1 || *n > 4096) return;
  if (threads <= 0 || threads > int(*n)) threads = int(*n);
}

}  // namespace proxyvis
