#include "util/output_set.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "util/error.h"
#include "util/input_file.h"
#include "util/sha256.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Writes all of `data` to `fd`, retrying short writes; returns 0 or the errno of the failure.
int writeAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += n;
    size -= size_t(n);
  }
  return 0;
}

// Copies the staged file into a device, FIFO or open descriptor (these are written in place:
// renaming onto them would replace /dev/null or a terminal by a regular file).
void copyInto(const fs::path& tmp, const OutputTarget& target, const std::string& output) {
  const int in = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) throw WriteError(output, "cannot write output", systemError(errno));
  int out = target.fd;
  if (target.kind == OutputTarget::Kind::kStream) {
    std::fflush(out == 2 ? stderr : stdout);  // what the program printed comes first
  } else {
    out = ::open(target.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (out < 0) {
      const int err = errno;
      ::close(in);
      throw WriteError(output, "cannot write output", systemError(err));
    }
  }
  char buffer[1 << 16];
  int err = 0;
  for (;;) {
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno;
    if (n <= 0) break;
    if ((err = writeAll(out, buffer, size_t(n))) != 0) break;
  }
  ::close(in);
  if (target.kind != OutputTarget::Kind::kStream && ::close(out) != 0 && err == 0) err = errno;
  if (err != 0) throw WriteError(output, "cannot write output", systemError(err));
}

// Rethrows the current Error with the hidden temporary's name replaced by the output's: a writer
// only knows the path it was given, the user only the one they named. Same exit code.
[[noreturn]] void rethrowNamingTarget(const fs::path& tmp, const std::string& name) {
  try {
    throw;
  } catch (const Error& e) {
    const std::string hidden = printableText(tmp.string());
    std::string message = e.what();
    if (message.find(hidden) == std::string::npos) throw;
    for (size_t at = message.find(hidden); at != std::string::npos;
         at = message.find(hidden, at + name.size()))
      message.replace(at, hidden.size(), name);
    if (message.rfind(name + ": ", 0) == 0) message.erase(0, name.size() + 2);
    if (e.exitCode() == kExitCannotWrite) throw WriteError(name, message);
    if (e.exitCode() == kExitCheckFailed) throw CheckFailed(name, message);
    throw Error(name, message);
  }
}

}  // namespace

void writeFileBytes(const fs::path& path, const std::string& bytes, const std::string& output) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw WriteError(output, "cannot write output", systemError(errno));
  int err = writeAll(fd, bytes.data(), bytes.size());
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) throw WriteError(output, "cannot write output", systemError(err));
}

OutputSet::~OutputSet() {
  for (Staged& s : staged_) {
    std::error_code ec;
    fs::remove(s.tmp, ec);
    s.live.release();
  }
}

void OutputSet::add(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  const std::string name = target.string();
  if (isRegisteredInput(target))
    throw Error(name, "refusing to overwrite an input of this run", {},
                "choose another output path");
  Staged s;
  s.target = target;
  s.resolved = resolveOutputTarget(target);
  fs::path dir;
  if (s.resolved.kind == OutputTarget::Kind::kFile) {
    if (isRegisteredInput(s.resolved.path))
      throw Error(name, "refusing to overwrite an input of this run", {},
                  "choose another output path");
    dir = s.resolved.path.parent_path();
    std::error_code ec;
    if (missing_ == MissingFolders::kCreate)
      createOutputFolder(dir, name);
    else if (!fs::is_directory(dir, ec))
      throw WriteError(name, "cannot write output", "folder '" + dir.string() + "' does not exist",
                       "create it first");
    removeStaleTemporariesOnce(dir);
    s.tmp = temporaryPathFor(s.resolved.path);
  } else {
    // Writers want a regular file with the target's extension; the bytes are copied at commit.
    dir = fs::temp_directory_path();
    removeStaleTemporariesOnce(dir);
    s.tmp = temporaryPathFor(dir / target.filename());
  }
  // Registered before it exists, so that no moment leaves it behind on a signal.
  s.live = LiveTemporary(s.tmp, false);
  // Created here, exclusively: a folder we cannot write fails now with the system's reason,
  // before the writer reports something vaguer.
  const int fd = ::open(s.tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
    throw WriteError(name, "cannot write output",
                     "cannot create a file in '" + dir.string() + "': " + systemError(errno),
                     "choose another path or fix the folder's permissions");
  ::close(fd);
  try {
    write(s.tmp);
  } catch (...) {
    std::error_code ec;
    fs::remove(s.tmp, ec);
    rethrowNamingTarget(s.tmp, name);
  }
  std::error_code ec;
  if (!fs::is_regular_file(s.tmp, ec)) {
    fs::remove(s.tmp, ec);
    throw WriteError(name, "cannot write output", "the writer produced no file");
  }
  staged_.push_back(std::move(s));
}

void OutputSet::addText(const fs::path& target, const std::string& text) {
  add(target, [&](const fs::path& tmp) { writeFileBytes(tmp, text, target.string()); });
}

std::string OutputSet::sha256Of(const fs::path& target) const {
  for (const Staged& s : staged_) {
    if (s.target != target) continue;
    return sha256OfOwnFile(s.tmp);
  }
  checkFailed(__FILE__, __LINE__, "staged", "sha256Of: " + target.string() + " was not staged");
}

void OutputSet::commit() {
  for (Staged& s : staged_) {
    const std::string name = s.target.string();
    if (s.resolved.kind == OutputTarget::Kind::kFile) {
      if (std::rename(s.tmp.c_str(), s.resolved.path.c_str()) != 0)
        throw WriteError(name, "cannot write output", systemError(errno));
    } else {
      copyInto(s.tmp, s.resolved, name);
      std::error_code ec;
      fs::remove(s.tmp, ec);
    }
    s.live.release();
    s.tmp.clear();
  }
  staged_.clear();
}

}  // namespace proxyvis
