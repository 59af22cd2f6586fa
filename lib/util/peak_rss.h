#pragma once
// The peak resident set size of this process, in bytes: what the data-parallel and out-of-core
// reports call peak_rss_bytes.
//
// Linux keeps it as the "high water mark" (VmHWM in /proc/self/status), which writing 5 to
// /proc/self/clear_refs resets to the current RSS: a study that renders several configurations
// in one process measures each one's own peak that way. getrusage's ru_maxrss is the fallback
// (it cannot be reset).
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>

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

// Hands the heap's freed memory back to the system (malloc_trim) and resets the peak: a step
// measured from here has its own peak, counted from what is really resident now (returned).
inline uint64_t startPeakRssMeasurement() {
  malloc_trim(0);
  resetPeakRss();
  return currentRssBytes();
}

// The peak RSS of a run measured phase by phase: each phase's peak is the high-water mark since
// the previous phase ended (reset then), the run's peak the largest of them. `before`: what was
// resident when the run started (after giving the heap's freed memory back).
class PeakRssPhases {
 public:
  PeakRssPhases() : before_(startPeakRssMeasurement()), peak_(before_) {}
  uint64_t before() const { return before_; }
  // Ends the phase: its peak (whole-process where the kernel cannot reset the mark), folded into
  // the run's; the next phase starts from what is resident now.
  uint64_t endPhase() {
    const uint64_t p = peakRssBytes();
    peak_ = std::max(peak_, p);
    resetPeakRss();
    return p;
  }
  // The run's peak so far (the current phase included).
  uint64_t peak() const { return std::max(peak_, peakRssBytes()); }
  // Growth over `before`, of a peak.
  uint64_t growth(uint64_t peak_bytes) const {
    return peak_bytes > before_ ? peak_bytes - before_ : 0;
  }

 private:
  uint64_t before_, peak_;
};

}  // namespace proxyvis
