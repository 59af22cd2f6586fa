#pragma once
// Outputs are written to a temporary file beside the target and renamed at the end, so a failed
// or interrupted run never leaves a partial file behind (util/output_set.h writes several
// related files as one unit; util/output_path.h says where an output really goes).
#include <filesystem>
#include <functional>
#include <string>

namespace proxyvis {

// Calls write(tmp_path) with a temporary path in the target's folder (which must exist), then
// renames it onto `target`. A symbolic link is written through: the file it points to is
// replaced, the link stays. An existing device, FIFO or standard stream (/dev/null, /dev/stdout)
// is written in place, never replaced. If write throws, the temporary is removed and the
// exception propagates. Throws Error (exit 2) if `target` is an input of this run, WriteError
// (exit 3) with the system's reason if it cannot be written (a missing folder, a folder as the
// target, no permission, disk full).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp_path)>& write);

// Writes `text` to `target` atomically ("-" writes to stdout).
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace proxyvis
