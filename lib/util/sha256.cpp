#include "util/sha256.h"

#include <openssl/evp.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>

#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis {

std::string sha256Hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  const bool ok = EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr);
  PV_CHECK_MSG(ok && length == 32, "EVP_Digest(sha256) failed");
  static const char* kHex = "0123456789abcdef";
  std::string hex(2 * length, '0');
  for (unsigned int i = 0; i < length; ++i) {
    hex[2 * i] = kHex[digest[i] >> 4];
    hex[2 * i + 1] = kHex[digest[i] & 15];
  }
  return hex;
}

std::string sha256OfFile(const std::filesystem::path& path) {
  return sha256Hex(readTextFile(path));
}

std::string sha256OfOwnFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.is_open() || in.bad())
    throw WriteError(path.string(), "cannot read back an output", std::strerror(errno));
  return sha256Hex(bytes);
}

}  // namespace proxyvis
