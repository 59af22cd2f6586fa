#pragma once
// The folder of a plan of work units (docs/slurm.md): plan.json, units/K.*, units/K.done.
#include <filesystem>
#include <string>
#include <string_view>

namespace proxyvis {

// Creates DIR/units and refuses a folder that already holds finished units (units/K.done): a
// new plan would mix them with units of another run. `run_kind` names that run ("study").
void createPlanFolder(const std::filesystem::path& dir, std::string_view run_kind);

// The running program's absolute path, for the commands a plan names.
std::string planningProgram();

}  // namespace proxyvis
