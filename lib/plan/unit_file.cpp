#include "plan/unit_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <memory>

#include "util/atomic_write.h"
#include "util/error.h"
#include "util/fnv1a.h"
#include "util/input_file.h"
#include "util/json_field.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

static_assert(std::endian::native == std::endian::little, "unit files are little-endian");

constexpr std::string_view kMagic = "PVUNIT1\n";

void appendU64(std::string& out, uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

uint64_t readU64(std::string_view bytes, size_t at) {
  uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

// Maps every page of fresh memory [data, data + bytes) in one call. Touching fresh pages one by
// one costs a page fault each, which under some hypervisors is most of a merge's reading time
// (248 MB: 0.9 s of faults against 0.5 s populated, in this project's container). Best effort:
// a kernel before Linux 5.14 refuses the advice and the pages fault in as usual.
void populate(const void* data, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  static const uintptr_t page = uintptr_t(::sysconf(_SC_PAGESIZE));
  const uintptr_t begin = (uintptr_t(data) + page - 1) & ~(page - 1);
  const uintptr_t end = (uintptr_t(data) + bytes) & ~(page - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data, (void)bytes;
#endif
}

// A unit file's bytes in an uninitialised buffer (no zero-filling of what the read overwrites),
// placed so that the images that follow the header start on a float boundary: the merge copies
// each image once, from here into its vector. The buffer is the calling thread's, reused from
// file to file, so that its pages are mapped once, not once per unit.
struct FileContents {
  const float* storage = nullptr;
  size_t offset = 0;  // where the file's first byte is in `storage`
  std::string_view bytes;
  // The floats from `file_offset` on; nullptr when that is not on a float boundary (the file
  // changed between reading its header's length and the rest).
  const float* floatsAt(size_t file_offset) const {
    if ((offset + file_offset) % sizeof(float) != 0) return nullptr;
    return storage + (offset + file_offset) / sizeof(float);
  }
};

// Reads the whole unit file (an input: checkInputFile's checks and registration) into the
// calling thread's buffer; valid until the thread's next call.
FileContents readUnitBytes(const fs::path& path) {
  const uintmax_t size = checkInputFile(path);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw Error(path.string(), "cannot open file", std::strerror(errno), "check its mode");
  // The header's length sits at a fixed place; the images begin right after the header.
  uint64_t header_size = 0;
  const size_t prefix = kMagic.size() + 8;
  if (size >= prefix && ::pread(fd, &header_size, 8, off_t(kMagic.size())) != 8) header_size = 0;
  FileContents c;
  c.offset = (sizeof(float) - (prefix + header_size) % sizeof(float)) % sizeof(float);
  const size_t floats = (c.offset + size_t(size) + sizeof(float) - 1) / sizeof(float);
  thread_local std::unique_ptr<float[]> buffer;
  thread_local size_t capacity = 0;
  if (floats > capacity) {
    buffer.reset();
    buffer = std::make_unique_for_overwrite<float[]>(floats);
    capacity = floats;
    populate(buffer.get(), floats * sizeof(float));
  }
  c.storage = buffer.get();
  char* data = reinterpret_cast<char*>(buffer.get()) + c.offset;
  size_t done = 0;
  int err = 0;
  while (done < size) {
    const ssize_t n = ::pread(fd, data + done, size_t(size) - done, off_t(done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno;
    if (n <= 0) break;
    done += size_t(n);
  }
  ::close(fd);
  if (done != size)
    throw Error(path.string(), "cannot read file",
                err != 0 ? std::strerror(err) : "it changed size while being read",
                "retry when nothing else writes it");
  c.bytes = std::string_view(data, size);
  return c;
}

[[noreturn]] void notAUnit(const fs::path& path, const std::string& why) {
  throw Error(path.string(), "not a complete render-compare unit result", why,
              "delete the unit's .done marker and run the unit again (submit.sh --resume)");
}

}  // namespace

void writeUnitFile(const fs::path& path, UnitFile file) {
  nlohmann::json list = nlohmann::json::array();
  size_t floats = 0;
  for (const Image& im : file.images) {
    list.push_back({{"width", im.width}, {"height", im.height}, {"channels", im.channels}});
    floats += im.pixels.size();
  }
  file.header["images"] = list;
  const std::string header = file.header.dump();
  std::string bytes;
  bytes.reserve(kMagic.size() + 16 + header.size() + 4 * floats);
  bytes += kMagic;
  appendU64(bytes, header.size());
  bytes += header;
  for (const Image& im : file.images)
    if (!im.pixels.empty())
      bytes.append(reinterpret_cast<const char*>(im.pixels.data()),
                   im.pixels.size() * sizeof(float));
  appendU64(bytes, fnv1aWords(bytes));
  writeTextAtomically(path, bytes);
}

UnitFile readUnitFile(const fs::path& path) {
  const FileContents file_bytes = readUnitBytes(path);
  const std::string_view all = file_bytes.bytes;
  if (all.size() < kMagic.size() + 16 || all.substr(0, kMagic.size()) != kMagic)
    notAUnit(path, "it does not start with the unit file's signature");
  const size_t body = all.size() - 8;
  if (fnv1aWords(all.substr(0, body)) != readU64(all, body))
    notAUnit(path, "its checksum does not match its contents (truncated or altered)");
  const uint64_t header_size = readU64(all, kMagic.size());
  size_t at = kMagic.size() + 8;
  if (header_size > body - at) notAUnit(path, "its header runs past the end");
  UnitFile file;
  try {
    file.header = nlohmann::json::parse(all.substr(at, header_size));
  } catch (const nlohmann::json::exception& e) {
    notAUnit(path, std::string("its header is not JSON: ") + e.what());
  }
  at += header_size;
  try {
    const JsonField images = JsonField(file.header)["images"];
    for (size_t i = 0, count = images.arraySize(); i < count; ++i) {
      const JsonField j = images[i];
      Image im;
      im.width = j["width"].asInt();
      im.height = j["height"].asInt();
      im.channels = j["channels"].asInt();
      if (im.width < 0 || im.height < 0 || im.channels < 0)
        notAUnit(path, "an image has a negative size");
      const uint64_t n = uint64_t(im.width) * uint64_t(im.height) * uint64_t(im.channels);
      if (n > (body - at) / sizeof(float)) notAUnit(path, "an image runs past the end");
      // Every image starts on a float boundary of the buffer (readUnitBytes aligned the first
      // one; each is a whole number of floats): the floats are copied once into their vector.
      const float* first = file_bytes.floatsAt(at);
      if (!first) notAUnit(path, "it changed while being read");
      im.pixels.reserve(n);
      populate(im.pixels.data(), n * sizeof(float));
      im.pixels.assign(first, first + n);
      at += n * sizeof(float);
      file.images.push_back(std::move(im));
    }
  } catch (const JsonFieldError& e) {
    notAUnit(path, "its header is not what a unit writes: " + e.path() + ": " + e.problem());
  }
  if (at != body) notAUnit(path, "it has bytes after its last image");
  return file;
}

}  // namespace proxyvis
