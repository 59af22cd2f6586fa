#include "util/staged_folder.h"

#include <fcntl.h>
#include <stdio.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <system_error>
#include <vector>

#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/output_path.h"
#include "util/sha256.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// True if the existing folder may be replaced by a run of `program`.
bool replaceable(const fs::path& folder, const std::string& program, const std::string& legacy) {
  std::error_code ec;
  if (fs::is_empty(folder, ec) && !ec) return true;
  if (!legacy.empty() && fs::is_regular_file(folder / legacy, ec)) return true;
  const fs::path manifest = folder / StagedFolder::kManifestName;
  if (!fs::is_regular_file(manifest, ec)) return false;
  try {
    return nlohmann::json::parse(readTextFile(manifest)).at("written_by") == program;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

StagedFolder::StagedFolder(const fs::path& folder, std::string program, std::string legacy_marker)
    : program_(std::move(program)) {
  const std::string name = folder.string();
  std::error_code ec;
  target_ = fs::weakly_canonical(fs::absolute(folder), ec);
  if (ec || target_.filename().empty()) target_ = fs::absolute(folder).lexically_normal();
  if (fs::exists(target_, ec)) {
    if (!fs::is_directory(target_, ec))
      throw WriteError(name, "cannot write the output folder", "a file of that name exists",
                       "choose another folder");
    if (!replaceable(target_, program_, legacy_marker))
      throw Error(name, "the output folder holds other files",
                  "it is replaced as a whole and is neither empty nor written by " + program_,
                  "choose a new or empty folder");
  }
  const fs::path parent = target_.parent_path();
  createOutputFolder(parent, name);
  removeStaleTemporariesOnce(parent);
  staging_ = temporaryPathFor(target_);
  live_ = LiveTemporary(staging_, true);
  if (!fs::create_directory(staging_, ec) || ec)
    throw WriteError(name, "cannot write the output folder",
                     "cannot create a folder in '" + parent.string() +
                         "': " + (ec ? ec.message() : std::string("it exists")),
                     "choose another folder or fix its permissions");
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  live_.release();
}

void StagedFolder::commit() {
  const std::string name = target_.string();
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(staging_, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) files.push_back(it->path().filename());
  if (ec) throw WriteError(name, "cannot list the staged folder", ec.message());
  std::sort(files.begin(), files.end());
  nlohmann::json hashes = nlohmann::json::object();
  for (const fs::path& f : files) hashes[f.string()] = sha256OfOwnFile(staging_ / f);
  writeTextAtomically(staging_ / kManifestName,
                      nlohmann::json{{"written_by", program_}, {"sha256", hashes}}.dump(2) + "\n");

  // One atomic exchange when there is a previous folder; the staging name then holds the old one,
  // which is removed (by the signal handler too, if we are killed before).
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
    const int exchange_error = errno;
    if (exchange_error == ENOENT) {
      if (std::rename(staging_.c_str(), target_.c_str()) != 0)
        throw WriteError(name, "cannot put the output folder in place", std::strerror(errno));
      live_.release();
      committed_ = true;
      return;
    }
    if (exchange_error != EINVAL && exchange_error != ENOSYS)
      throw WriteError(name, "cannot put the output folder in place",
                       std::strerror(exchange_error));
    // No RENAME_EXCHANGE on this file system: move the old folder aside, then ours in.
    const fs::path old = temporaryPathFor(target_);
    LiveTemporary old_live(old, true);
    if (std::rename(target_.c_str(), old.c_str()) != 0)
      throw WriteError(name, "cannot put the output folder in place", std::strerror(errno));
    if (std::rename(staging_.c_str(), target_.c_str()) != 0) {
      const int err = errno;
      std::rename(old.c_str(), target_.c_str());
      throw WriteError(name, "cannot put the output folder in place", std::strerror(err));
    }
    live_.release();
    committed_ = true;
    fs::remove_all(old, ec);
    return;
  }
  committed_ = true;
  fs::remove_all(staging_, ec);
  live_.release();
}

}  // namespace proxyvis
