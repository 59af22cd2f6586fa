#pragma once
// Temporary files and folders of outputs being written: their names, a registry of the live ones
// that a terminating signal (SIGINT, SIGTERM, SIGHUP) removes before the process dies, and the
// removal of stale ones that a killed run (SIGKILL, power loss) left behind.
//
// A temporary is named ".<stem>.tmp<pid>_<n><ext>" beside its target, so the owning process can
// be told from the name: once that process is gone, the file is garbage.
#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace proxyvis {

// ".<stem>.tmp<pid>_<n><ext>" in the target's directory (the extension stays last: writers such
// as OpenImageIO, Draco and OpenMesh choose the format by it).
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// The pid in a temporary's file name, or nullopt if `name` is not one of ours.
std::optional<pid_t> temporaryOwner(const std::string& name);

// True while process `pid` exists (ours included).
bool processAlive(pid_t pid);

// Removes the temporaries in `dir` whose owning process no longer exists (files, and folders
// with what is in them); returns how many. Errors are ignored: this is housekeeping.
size_t removeStaleTemporaries(const std::filesystem::path& dir);

// Like removeStaleTemporaries, but at most once per directory per process (called before every
// write into a directory).
void removeStaleTemporariesOnce(const std::filesystem::path& dir);

// A live temporary, removed by the signal handler if the process is terminated while it exists.
// A folder is removed with the files directly in it (not deeper). The registry has fixed storage
// (the handler may not allocate); when it is full, or the path is too long, the temporary is
// simply not registered and left to removeStaleTemporaries.
class LiveTemporary {
 public:
  LiveTemporary() = default;
  LiveTemporary(const std::filesystem::path& path, bool is_folder);
  ~LiveTemporary() { release(); }
  LiveTemporary(LiveTemporary&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
  LiveTemporary& operator=(LiveTemporary&& other) noexcept;
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;
  // The path is gone (renamed into place or removed): the handler no longer touches it.
  void release();
  bool registered() const { return slot_ >= 0; }

 private:
  int slot_ = -1;
};

// Installs the handler for SIGINT, SIGTERM and SIGHUP (signals already ignored stay ignored): it
// removes every live temporary, then re-raises the signal with its default action, so the exit
// status still says which signal ended the process. Signals that arrive during the removal (on
// any thread) wait for it to finish.
void removeTemporariesOnTerminatingSignals();

// What the handler does, callable from tests: removes every live temporary now.
void removeLiveTemporariesForTesting();

}  // namespace proxyvis
