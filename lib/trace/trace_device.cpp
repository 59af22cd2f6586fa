// One Embree device with one error callback (embree tutorials/minimal/minimal.cpp): Embree reports
// errors through the callback, possibly from its build threads, so they are collected under a
// mutex and turned into proxyvis::Error by the caller that knows what was being done.
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <mutex>

#include "trace/trace_scene.h"
#include "util/error.h"

namespace proxyvis {

struct TraceDevice::ErrorLog {
  std::mutex mutex;
  std::string messages;
  // Bytes Embree holds now and at most so far (its memory monitor callback): what BVHs and
  // geometry buffers really cost, for the memory estimate of a flattened build.
  std::atomic<int64_t> bytes{0};
  std::atomic<int64_t> peak_bytes{0};
};

namespace {

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
      return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
      return "RTC_ERROR_CANCELLED";
  }
  return "RTC_ERROR_?";
}

void onEmbreeError(void* user_ptr, RTCError code, const char* str) {
  auto* log = static_cast<TraceDevice::ErrorLog*>(user_ptr);
  std::lock_guard lock(log->mutex);
  if (!log->messages.empty()) log->messages += '\n';
  log->messages += errorName(code);
  log->messages += ": ";
  log->messages += str ? str : "(no message)";
}

// Called by Embree before it allocates (bytes > 0) and after it frees (bytes < 0); returning true
// lets the allocation proceed.
bool onEmbreeMemory(void* user_ptr, ssize_t bytes, bool /*post*/) {
  auto* log = static_cast<TraceDevice::ErrorLog*>(user_ptr);
  const int64_t now = log->bytes.fetch_add(int64_t(bytes), std::memory_order_relaxed) + bytes;
  int64_t peak = log->peak_bytes.load(std::memory_order_relaxed);
  while (now > peak && !log->peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed))
    ;
  return true;
}

}  // namespace

TraceDevice::TraceDevice() : log_(std::make_unique<ErrorLog>()) {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw Error("", "cannot create an Embree device", errorName(rtcGetDeviceError(nullptr)),
                "check that the CPU supports SSE2 and that libembree3 is installed");
  rtcSetDeviceErrorFunction(device_, onEmbreeError, log_.get());
  rtcSetDeviceMemoryMonitorFunction(device_, onEmbreeMemory, log_.get());
}

uint64_t TraceDevice::bytesInUse() const {
  return uint64_t(std::max<int64_t>(0, log_->bytes.load(std::memory_order_relaxed)));
}

uint64_t TraceDevice::peakBytes() const {
  return uint64_t(std::max<int64_t>(0, log_->peak_bytes.load(std::memory_order_relaxed)));
}

TraceDevice::~TraceDevice() {
  rtcReleaseDevice(device_);
}

std::string TraceDevice::takeErrors() {
  std::lock_guard lock(log_->mutex);
  std::string out;
  out.swap(log_->messages);
  return out;
}

void TraceDevice::throwIfError(const std::string& what) {
  std::string messages = takeErrors();
  if (!messages.empty()) throw Error("", "Embree failed while " + what, messages);
}

}  // namespace proxyvis
