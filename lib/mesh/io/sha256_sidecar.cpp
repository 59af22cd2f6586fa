#include "mesh/io/sha256_sidecar.h"

#include <cctype>
#include <system_error>

#include "mesh/io/internal/printable.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/sha256.h"

namespace proxyvis {
namespace fs = std::filesystem;

namespace {

// A sidecar is one line; anything much longer is not one (and is not read whole).
constexpr uintmax_t kMaxSidecarBytes = 4096;

Error malformed(const fs::path& sidecar, const std::string& why) {
  return Error(sidecar.string(), "not a sha256sum line", why,
               "rewrite it with 'sha256sum FILE > FILE.sha256', or delete it");
}

// The lowercase hash a sha256sum line records ("<hex>  <name>" or "<hex> *<name>").
std::string recordedHash(const fs::path& sidecar, const std::string& text) {
  if (text.size() < 66)
    throw malformed(sidecar, "expected 64 hex digits, two spaces and the file name");
  std::string hash = text.substr(0, 64);
  for (char& c : hash) {
    if (!std::isxdigit(static_cast<unsigned char>(c)))
      throw malformed(sidecar, "'" + detail::printableExcerpt(text, 64) +
                                   "' does not start with 64 hex digits");
    c = char(std::tolower(static_cast<unsigned char>(c)));
  }
  if (text[64] != ' ' || (text[65] != ' ' && text[65] != '*'))
    throw malformed(sidecar, "expected two spaces after the hash");
  return hash;
}

}  // namespace

fs::path sidecarPathOf(const fs::path& mesh) {
  fs::path sidecar = mesh;
  sidecar += ".sha256";
  return sidecar;
}

std::string sidecarLine(const fs::path& mesh, const std::string& bytes) {
  return sha256Hex(bytes) + "  " + mesh.filename().string() + "\n";
}

void verifySidecar(const fs::path& mesh, const std::string& bytes) {
  const fs::path sidecar = sidecarPathOf(mesh);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(sidecar, ec))) return;  // none: nothing to verify
  if (checkInputFile(sidecar) > kMaxSidecarBytes)            // not a regular file: Error naming it
    throw malformed(sidecar, "it is longer than one line");
  const std::string expected = recordedHash(sidecar, readTextFile(sidecar));
  const std::string actual = sha256Hex(bytes);
  if (actual != expected)
    throw Error(
        mesh.string(), "content does not match its .sha256 sidecar",
        "its sha256 is " + actual + ", " + sidecar.filename().string() + " records " + expected,
        "the file is corrupt or was changed after it was written: restore a good copy, "
        "or delete the sidecar if the change was intended");
}

}  // namespace proxyvis
