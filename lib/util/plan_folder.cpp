#include "plan_folder.h"

#include "error.h"
#include "json_field.h"

#include <system_error>

namespace proxyvis {

namespace fs = std::filesystem;

void to_json(nlohmann::json& j, const PlanCommands& p) {
  j = {{"version", p.version},
       {"name", p.name},
       {"units", p.units},
       {"run_unit", p.run_unit},
       {"merge", p.merge}};
}

void from_json(const nlohmann::json& j, PlanCommands& p) {
  const JsonField f(j);
  p.version = f["version"].asInt();
  p.name = f["name"].asString();
  p.units = f["units"].asUint64();
  p.run_unit = f["run_unit"].asStrings();
  p.merge = f["merge"].asStrings();
}

void createPlanFolder(const fs::path& dir, std::string_view run_kind) {
  std::error_code ec;
  fs::create_directories(dir / "units", ec);
  if (ec) throw WriteError(dir.string(), "cannot create the plan folder", ec.message());
  for (const auto& entry : fs::directory_iterator(dir / "units", ec))
    if (entry.path().extension() == ".done")
      throw Error(dir.string(), "the plan folder already holds finished units",
                  "a new plan would mix them with units of another " + std::string(run_kind),
                  "choose another folder or empty its units/");
}

std::string planningProgram() {
  return fs::canonical("/proc/self/exe").string();
}

}  // namespace proxyvis
