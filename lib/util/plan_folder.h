#pragma once
// The folder of a plan of work units (docs/slurm.md): plan.json, units/K.*, units/K.done.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace proxyvis {

// The part of every plan.json that scripts/slurm/submit.py reads, whichever program planned it:
// "version", "name" (the planning program), "units" (their number), "run_unit" and "merge" (the
// command lines, with {plan_dir} and {unit} for submit.py to fill in). The program's own record
// sits beside them under a key of its own ("render_compare", "proxy_gen").
struct PlanCommands {
  int version = 1;
  std::string name;
  uint64_t units = 0;
  std::vector<std::string> run_unit, merge;
  bool operator==(const PlanCommands&) const = default;
};
void to_json(nlohmann::json& j, const PlanCommands& p);
void from_json(const nlohmann::json& j, PlanCommands& p);

// Creates DIR/units and refuses a folder that already holds finished units (units/K.done): a
// new plan would mix them with units of another run. `run_kind` names that run ("study").
void createPlanFolder(const std::filesystem::path& dir, std::string_view run_kind);

// The running program's absolute path, for the commands a plan names.
std::string planningProgram();

}  // namespace proxyvis
