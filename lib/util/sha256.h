#pragma once
// SHA-256 content hashes (OpenSSL's libcrypto), as lowercase hex: the same text sha256sum prints.
// Used for the sidecar hash every mesh writer leaves beside its file and for the proxy hashes a
// scene records, so that a changed or corrupted file is noticed.
#include <filesystem>
#include <string>
#include <string_view>

namespace proxyvis {

// 64 lowercase hex digits.
std::string sha256Hex(std::string_view bytes);

// The hash of a whole file (read through util/input_file.h); throws Error naming the file.
std::string sha256OfFile(const std::filesystem::path& path);

// The hash of a file this run wrote (not registered as an input, unlike sha256OfFile); throws
// WriteError naming the file if it cannot be read back.
std::string sha256OfOwnFile(const std::filesystem::path& path);

}  // namespace proxyvis
