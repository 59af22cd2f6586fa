#include "util/atomic_write.h"

#include "util/output_set.h"

namespace proxyvis {

namespace fs = std::filesystem;

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  OutputSet outputs;
  outputs.add(target, write);
  outputs.commit();
}

void writeTextAtomically(const fs::path& target, const std::string& text) {
  OutputSet outputs;
  outputs.addText(target, text);
  outputs.commit();
}

}  // namespace proxyvis
