#include "plan_folder.h"

#include "error.h"

#include <system_error>

namespace proxyvis {

namespace fs = std::filesystem;

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
