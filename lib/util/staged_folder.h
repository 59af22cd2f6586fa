#pragma once
// A folder of outputs written as one unit (render-compare's report folder): every file goes into
// a temporary folder beside the final one, a manifest with each file's SHA-256 is written last,
// and commit() swaps the temporary folder into place in one rename. A rerun into the same folder
// leaves nothing of the previous run; a failed or killed run leaves the previous folder intact.
#include <filesystem>
#include <string>

#include "util/temp_files.h"

namespace proxyvis {

class StagedFolder {
 public:
  // Stages `folder` (symbolic links followed; missing parents created). `program` writes the
  // manifest and is who may replace the folder later. An existing folder is replaced only if it
  // is empty, holds a manifest of `program`, or holds `legacy_marker` (a folder written before
  // manifests existed); anything else is refused with Error (exit 2), since replacing it would
  // delete the user's files. WriteError (exit 3) if the folder cannot be created.
  StagedFolder(const std::filesystem::path& folder, std::string program,
               std::string legacy_marker = {});
  ~StagedFolder();  // removes the staging folder unless committed
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where the files are written until commit().
  const std::filesystem::path& path() const { return staging_; }
  // Where they will be (links resolved).
  const std::filesystem::path& target() const { return target_; }

  // Writes kManifestName (each file's SHA-256) last, then puts the folder in place.
  void commit();

  static constexpr const char* kManifestName = "manifest.json";

 private:
  std::string program_;
  std::filesystem::path target_, staging_;
  LiveTemporary live_;
  bool committed_ = false;
};

}  // namespace proxyvis
