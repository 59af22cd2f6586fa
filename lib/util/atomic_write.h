#pragma once
// Outputs are written to a temporary file beside the target and renamed at the end, so a failed
// run never leaves a partial file behind.
#include <filesystem>
#include <functional>
#include <string>

namespace proxyvis {

// Calls write(tmp_path) with a temporary path in the target's directory, then renames it to
// `target`. If write throws, the temporary file is removed and the exception propagates; if the
// directory is missing or the rename fails, throws WriteError (exit code 3).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp_path)>& write);

// Writes `text` to `target` atomically ("-" writes to stdout).
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace proxyvis
