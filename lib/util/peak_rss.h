#pragma once
// The peak resident set size of this process, in bytes: what the data-parallel and out-of-core
// reports call peak_rss_bytes.
//
// Linux keeps it as the "high water mark" (VmHWM in /proc/self/status), which writing 5 to
// /proc/self/clear_refs resets to the current RSS: a study that renders several configurations
// in one process measures each one's own peak that way. getrusage's ru_maxrss is the fallback
// (it cannot be reset).
#include <sys/resource.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace proxyvis {

// A "Vm...:" line of /proc/self/status in bytes, or 0 where there is none.
inline uint64_t procStatusBytes(const char* key) {
  uint64_t bytes = 0;
  if (FILE* f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    unsigned long long kib = 0;
    const size_t n = std::strlen(key);
    bool found = false;
    while (!found && std::fgets(line, sizeof line, f))
      found = std::strncmp(line, key, n) == 0 && std::sscanf(line + n, "%llu", &kib) == 1;
    std::fclose(f);
    if (found) bytes = uint64_t(kib) * 1024u;
  }
  return bytes;
}

// What is resident now (VmRSS), 0 where Linux does not say.
inline uint64_t currentRssBytes() {
  return procStatusBytes("VmRSS:");
}

inline uint64_t peakRssBytes() {
  if (const uint64_t hwm = procStatusBytes("VmHWM:")) return hwm;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024u;
}

// Resets the peak to the current RSS; false where the kernel does not allow it (the peak then
// keeps counting from the process's start).
inline bool resetPeakRss() {
  FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

}  // namespace proxyvis
