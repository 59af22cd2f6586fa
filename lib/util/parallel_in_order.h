#pragma once
// Independent jobs run in parallel with the failure that a sequential loop would report: when
// several jobs throw, the one with the lowest index is rethrown, whatever the threads' timing
// (one error line that does not change from run to run).
#include <tbb/parallel_for.h>

#include <cstddef>
#include <exception>
#include <vector>

namespace proxyvis {

// Calls job(i) for every i in [0, n), in parallel; every job runs even when another failed.
template <class Job>
void parallelInOrder(size_t n, const Job& job) {
  std::vector<std::exception_ptr> failed(n);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    try {
      job(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace proxyvis
