#include "image/oiio_module.h"

#include <dlfcn.h>

#include <string>

#include "util/atomic_write.h"
#include "util/error.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRebuild =
    "it is built with the programs and must stay in their folder: rebuild, or copy it there";

const OiioModule* loadOiioModule() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("/proc/self/exe", "cannot find the program's folder", ec.message(), kRebuild);
  const fs::path file = exe.parent_path() / kOiioModuleFile;
  // RTLD_LOCAL: OIIO's many libraries stay out of the program's symbol scope.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw Error(file.string(), "cannot load the image module", dlerror(), kRebuild);
  using Entry = const OiioModule* (*)(const OiioModuleHost*);
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "proxyvis_oiio_module"));
  if (!entry) throw Error(file.string(), "not an image module", dlerror(), kRebuild);
  static const OiioModuleHost host{kOiioModuleAbi, &writeAtomically};
  const OiioModule* module = entry(&host);
  if (!module || module->abi != kOiioModuleAbi)
    throw Error(file.string(), "image module of another build", "its interface differs", kRebuild);
  return module;  // never unloaded: OIIO keeps threads and caches until exit
}

}  // namespace

const OiioModule& oiioModule() {
  // A failed load throws out of the initialisation, so the next call tries again.
  static const OiioModule* const module = loadOiioModule();
  return *module;
}

std::future<void> preloadOiioModule() {
  return std::async(std::launch::async, [] { oiioModule(); });
}

}  // namespace proxyvis
