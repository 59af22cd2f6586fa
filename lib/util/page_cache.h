#pragma once
// Cold reads without dropping the machine's caches: asks the kernel to forget the cached pages
// of one file (posix_fadvise POSIX_FADV_DONTNEED), so that the next read of it comes from the
// disk, or, on a virtual machine, from whatever the host caches. Only that file's clean pages are
// dropped; no privilege is needed and nothing else on the machine is affected.
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>

namespace proxyvis {

// False if the file cannot be opened or the kernel refuses the advice (the read is then warm).
inline bool dropFromPageCache(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED) == 0;
  ::close(fd);
  return ok;
}

}  // namespace proxyvis
