#pragma once
// Several related outputs written as one unit (a proxy and its JSON report; error segments and
// the report that describes them). Each file is written to a temporary first; commit() then puts
// them in place in the order they were added, so the metadata added last (the report, which
// records each file's SHA-256) appears only once the files it describes are in place. A run that
// fails or is killed before commit() leaves none of them; one killed during commit() leaves at
// worst new files beside the previous report, which the recorded hashes expose.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "util/output_path.h"
#include "util/temp_files.h"

namespace proxyvis {

// What to do when the folder of an output does not exist: programs create the folders of the
// outputs named on their command line (`-o out/x.ply` works on a fresh checkout); library
// writers fail, so that a typo in a path computed by code does not scatter folders around.
enum class MissingFolders { kFail, kCreate };

class OutputSet {
 public:
  explicit OutputSet(MissingFolders missing = MissingFolders::kFail) : missing_(missing) {}
  ~OutputSet();  // removes what was staged and not committed
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Calls write(tmp) with a temporary path (same extension as `target`) and keeps the result for
  // commit(). A missing folder is created or a WriteError, as set at construction. Throws Error if
  // `target` is an input of this run (exit 2), WriteError if it cannot be written (exit 3);
  // whatever write throws propagates, and its temporary is removed.
  void add(const std::filesystem::path& target,
           const std::function<void(const std::filesystem::path& tmp)>& write);
  // add() for text; "-" is stdout.
  void addText(const std::filesystem::path& target, const std::string& text);

  // SHA-256 (hex) of what was staged for `target` (as given to add).
  std::string sha256Of(const std::filesystem::path& target) const;

  // Puts every staged file in place, in the order added: renamed onto its target (a regular
  // file), or copied into it (a device, FIFO or standard stream).
  void commit();

 private:
  struct Staged {
    std::filesystem::path target;  // as given
    OutputTarget resolved;
    std::filesystem::path tmp;
    LiveTemporary live;
  };
  MissingFolders missing_;
  std::vector<Staged> staged_;
};

// Writes `bytes` to `path` (created or truncated); throws WriteError naming `output` with the
// system's reason ("No space left on device", "Permission denied") on failure.
void writeFileBytes(const std::filesystem::path& path, const std::string& bytes,
                    const std::string& output);

}  // namespace proxyvis
