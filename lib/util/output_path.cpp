#include "util/output_path.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <system_error>

#include "util/error.h"
#include "util/temp_files.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// The descriptor a path names without naming a file: "-", /dev/stdout, /dev/stderr, /dev/fd/N,
// /proc/self/fd/N. Renaming onto these would replace the link (or the terminal's node); opening
// them anew would start writing at offset 0 of a redirected file.
std::optional<int> streamDescriptor(const std::string& p) {
  if (p == "-" || p == "/dev/stdout") return 1;
  if (p == "/dev/stderr") return 2;
  for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::string pre = prefix;
    if (p.size() > pre.size() && p.compare(0, pre.size(), pre) == 0 &&
        p.find_first_not_of("0123456789", pre.size()) == std::string::npos &&
        p.size() - pre.size() < 6)
      return std::stoi(p.substr(pre.size()));
  }
  return std::nullopt;
}

// The nearest folder of `dir` or its ancestors that exists (what a create_directories of `dir`
// would create in).
fs::path nearestExisting(fs::path dir) {
  std::error_code ec;
  while (!dir.empty() && !fs::exists(fs::symlink_status(dir, ec)) && dir != dir.parent_path())
    dir = dir.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

// Creates and removes a temporary in `dir`: the only test of writability that also holds for
// root, read-only mounts and full inode tables.
void probeWritable(const fs::path& dir, const std::string& output) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw WriteError(output, "cannot write output", "'" + dir.string() + "' is not a folder",
                     "choose another path");
  const fs::path probe = temporaryPathFor(dir / "write-test");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    throw WriteError(output, "cannot write output",
                     "cannot create a file in '" + dir.string() + "': " + systemError(errno),
                     "choose another path or fix the folder's permissions");
  ::close(fd);
  ::unlink(probe.c_str());
}

// True if `inner` is `outer` or lies inside it (both canonical).
bool isWithin(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

}  // namespace

OutputTarget resolveOutputTarget(const fs::path& path) {
  OutputTarget target;
  const std::string name = path.string();
  std::error_code ec;
  fs::path p = path;
  // Follow the chain of symbolic links ourselves: a link to a missing file is written through
  // (the link stays a link), which weakly_canonical would not do.
  for (int hops = 0;; ++hops) {
    if (const std::optional<int> fd = streamDescriptor(p.string())) {
      if (::fcntl(*fd, F_GETFD) < 0)
        throw WriteError(name, "cannot write output",
                         "descriptor " + std::to_string(*fd) + " is not open",
                         "redirect it or name a file");
      target.kind = OutputTarget::Kind::kStream;
      target.fd = *fd;
      return target;
    }
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    if (hops == 40)
      throw WriteError(name, "cannot write output", "too many levels of symbolic links");
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) throw WriteError(name, "cannot write output", ec.message());
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  const fs::file_status status = fs::status(p, ec);
  if (fs::is_directory(status))
    throw WriteError(name, "cannot write output", "it is a folder", "name a file in it");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    target.kind = OutputTarget::Kind::kDevice;
    target.path = p;
    return target;
  }
  // The folder may itself be reached through links: resolve it, keep the file name.
  fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  fs::path resolved_parent = fs::weakly_canonical(parent, ec);
  if (ec) resolved_parent = fs::absolute(parent, ec);
  target.path = resolved_parent / p.filename();
  // /dev/stdout's /proc/self/fd/1 under another name (a link to /dev/fd/1, say).
  if (streamDescriptor(target.path.string())) return resolveOutputTarget(target.path);
  return target;
}

void createOutputFolder(const fs::path& dir, const std::string& output) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw WriteError(output, "cannot create the output folder '" + dir.string() + "'",
                     ec ? ec.message() : "a file of that name exists", "choose another path");
}

void checkOutputs(const std::vector<std::string>& inputs, const std::vector<OutputFlag>& outputs) {
  std::error_code ec;
  std::vector<fs::path> existing_inputs;
  for (const std::string& input : inputs)
    if (!input.empty() && fs::exists(input, ec))
      existing_inputs.push_back(fs::canonical(input, ec));

  std::vector<std::pair<const OutputFlag*, fs::path>> seen;  // outputs checked, resolved
  for (const OutputFlag& out : outputs) {
    if (out.path.empty()) continue;
    fs::path resolved;
    if (out.is_folder) {
      resolved = fs::weakly_canonical(out.path, ec);
      if (ec) resolved = fs::absolute(out.path);
      for (const fs::path& input : existing_inputs)
        if (isWithin(input, resolved))
          throw Error(out.path, out.flag + " would contain the input '" + input.string() + "'",
                      "the folder is replaced as a whole", "choose another " + out.flag);
      if (fs::exists(resolved, ec) && !fs::is_directory(resolved, ec))
        throw WriteError(out.path, "cannot write output", "it exists and is not a folder",
                         "choose another " + out.flag);
      probeWritable(nearestExisting(resolved.parent_path()), out.path);
    } else {
      const OutputTarget target = resolveOutputTarget(out.path);
      if (target.kind == OutputTarget::Kind::kStream) {
        resolved = "/dev/fd/" + std::to_string(target.fd);
      } else {
        resolved = target.path;
        for (size_t i = 0; i < inputs.size(); ++i) {
          if (inputs[i].empty()) continue;
          std::error_code eq;
          if (fs::equivalent(resolved, inputs[i], eq) && !eq)
            throw Error(out.path, out.flag + " names the input '" + inputs[i] + "'",
                        "writing it would destroy the input", "choose another output path");
        }
        if (target.kind == OutputTarget::Kind::kFile)
          probeWritable(nearestExisting(resolved.parent_path()), out.path);
      }
    }
    for (const auto& [other, other_path] : seen) {
      std::error_code eq;
      if (other_path == resolved || (fs::equivalent(other_path, resolved, eq) && !eq))
        throw Error(out.path, out.flag + " and " + other->flag + " name the same output",
                    "one would replace the other", "give them different paths");
    }
    seen.emplace_back(&out, resolved);
  }
}

}  // namespace proxyvis
