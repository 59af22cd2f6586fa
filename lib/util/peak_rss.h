#pragma once
// The peak resident set size of this process, in bytes (getrusage's ru_maxrss, which Linux gives
// in KiB): what the data-parallel and out-of-core reports call peak_rss_bytes.
#include <sys/resource.h>

#include <cstdint>

namespace proxyvis {

inline uint64_t peakRssBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024u;
}

}  // namespace proxyvis
