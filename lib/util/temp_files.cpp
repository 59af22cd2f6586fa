#include "util/temp_files.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <system_error>

namespace proxyvis {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  name += target.extension().string();
  return target.parent_path() / name;
}

std::optional<pid_t> temporaryOwner(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return std::nullopt;
  // The last ".tmp<digits>_<digits>" followed by the end or an extension.
  for (size_t at = name.rfind(".tmp"); at != std::string::npos && at > 0;
       at = name.rfind(".tmp", at - 1)) {
    size_t i = at + 4;
    const size_t pid_begin = i;
    while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
    const size_t pid_end = i;
    if (pid_end == pid_begin || pid_end - pid_begin > 9 || i >= name.size() || name[i] != '_')
      continue;
    ++i;
    const size_t n_begin = i;
    while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
    if (i == n_begin || (i < name.size() && name[i] != '.')) continue;
    const long pid = std::stol(name.substr(pid_begin, pid_end - pid_begin));
    if (pid <= 0) return std::nullopt;
    return pid_t(pid);
  }
  return std::nullopt;
}

bool processAlive(pid_t pid) {
  if (pid == ::getpid()) return true;
  return ::kill(pid, 0) == 0 || errno == EPERM;  // EPERM: it exists, owned by another user
}

size_t removeStaleTemporaries(const fs::path& dir) {
  std::error_code ec;
  size_t removed = 0;
  for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    const std::optional<pid_t> owner = temporaryOwner(it->path().filename().string());
    if (!owner || processAlive(*owner)) continue;
    std::error_code remove_ec;
    if (fs::remove_all(it->path(), remove_ec) > 0 && !remove_ec) ++removed;
  }
  return removed;
}

void removeStaleTemporariesOnce(const fs::path& dir) {
  static std::mutex mutex;
  static std::set<fs::path> done;
  std::error_code ec;
  fs::path key = fs::weakly_canonical(dir, ec);
  if (ec) key = dir;
  {
    std::lock_guard lock(mutex);
    if (!done.insert(key).second) return;
  }
  removeStaleTemporaries(dir);
}

// ---- the registry of live temporaries (read by the signal handler) ----

namespace {

constexpr int kSlots = 128;
constexpr size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kFile = 2, kFolder = 3 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxPath];
};
Slot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads these");

// Only system calls: this runs in a signal handler. Removes the files directly in `path`, then
// the folder itself. Other threads keep running while the handler does: one that writes into the
// folder could create a file after a pass and make the folder's removal fail, so the folder is
// first renamed away ("<path>.gone", still a temporary's name), where no path-based write lands.
void removeFlatFolder(const char* path) {
  char moved[kMaxPath + 8];
  const size_t length = std::strlen(path);
  std::memcpy(moved, path, length);
  std::memcpy(moved + length, ".gone", 6);
  if (::rename(path, moved) == 0) path = moved;
  for (int pass = 0; pass < 3; ++pass) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    alignas(8) char buffer[8192];
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (long offset = 0; offset < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
        const char* name = entry->d_name;
        const bool dot = name[0] == '.' && (name[1] == 0 || (name[1] == '.' && name[2] == 0));
        if (!dot) ::unlinkat(fd, name, 0);
        offset += entry->d_reclen;
      }
    }
    ::close(fd);
    if (::rmdir(path) == 0 || errno == ENOENT) return;
  }
}

void removeLiveTemporaries() {
  for (Slot& slot : g_slots) {
    const int state = slot.state.load(std::memory_order_acquire);
    if (state == kFile) ::unlink(slot.path);
    if (state == kFolder) removeFlatFolder(slot.path);
  }
}

// 0: no terminating signal yet; 1: one thread removes the temporaries; 2: done.
std::atomic<int> g_cleanup{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler uses it");

// A process often gets the signal twice (timeout(1) and systemd signal the process and then its
// group): the second lands on another thread. With the default action back in place it ended the
// process in the middle of the first one's removal, so the handler stays installed, the first
// call removes, and any other waits for it to finish.
extern "C" void onTerminatingSignal(int sig) {
  const int saved_errno = errno;
  int expected = 0;
  if (g_cleanup.compare_exchange_strong(expected, 1)) {
    removeLiveTemporaries();
    g_cleanup.store(2);
  } else {
    const struct timespec pause { 0, 1000000 };
    while (g_cleanup.load() != 2) ::nanosleep(&pause, nullptr);
  }
  errno = saved_errno;
  // The default action, then the signal again: it stays blocked until we return, then ends the
  // process as if we had never caught it.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  ::sigaction(sig, &default_action, nullptr);
  ::raise(sig);
}

}  // namespace

LiveTemporary::LiveTemporary(const fs::path& path, bool is_folder) {
  std::error_code ec;
  const std::string text = fs::absolute(path, ec).string();
  if (ec || text.size() >= kMaxPath) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slots[i].path, text.c_str(), text.size() + 1);
    g_slots[i].state.store(is_folder ? kFolder : kFile, std::memory_order_release);
    slot_ = i;
    return;
  }
}

LiveTemporary& LiveTemporary::operator=(LiveTemporary&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void LiveTemporary::release() {
  if (slot_ < 0) return;
  g_slots[slot_].state.store(kFree, std::memory_order_release);
  slot_ = -1;
}

void removeTemporariesOnTerminatingSignals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
      struct sigaction action {};
      action.sa_handler = onTerminatingSignal;
      // No other terminating signal on this thread while it removes (it would wait for itself).
      sigemptyset(&action.sa_mask);
      for (int blocked : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, blocked);
      ::sigaction(sig, &action, nullptr);
    }
  });
}

void removeLiveTemporariesForTesting() {
  removeLiveTemporaries();
}

}  // namespace proxyvis
