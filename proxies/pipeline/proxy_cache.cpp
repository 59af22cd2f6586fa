#include "proxies/pipeline/proxy_cache.h"

#include <cstring>

#include <fmt/core.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <system_error>

#include "proxies/pipeline/json_visit.h"
#include "proxies/pipeline/report_fields.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/output_set.h"
#include "util/program_build_id.h"
#include "util/proxy_class.h"
#include "util/sha256.h"

namespace fs = std::filesystem;

namespace proxyvis {

namespace {

// Bumped when the entry layout or the key's content changes: older entries then miss.
constexpr int kCacheFormat = 1;
// No proxy file or report proxy-gen writes comes near this; a larger entry is damaged.
constexpr uintmax_t kMaxEntryBytes = uintmax_t(1) << 30;

std::string optionalNumber(const std::optional<double>& v) {
  return v ? fmt::format("{:.17g}", *v) : "default";
}

}  // namespace

// The keys of an entry's record (proxies/pipeline/json_visit.h): one list for writing and reading.
template <typename V>
void fields(ProxyCacheRecord& r, V& v) {
  v("format", r.format);
  v("key", r.key);
  v("report", r.report);
  v("proxy_sha256", r.proxy_sha256);
}

void to_json(nlohmann::json& j, const ProxyCacheRecord& r) {
  j = toJsonValue(r);
}

ProxyCacheRecord readProxyCacheRecord(const JsonField& f) {
  return readFields<ProxyCacheRecord>(f);
}

void from_json(const nlohmann::json& j, ProxyCacheRecord& r) {
  r = readWithoutFile(j, readProxyCacheRecord);
}

std::optional<std::string> readOwnFileBytes(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  const uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxEntryBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) return std::nullopt;
  return bytes;
}

nlohmann::json proxyCacheSettings(const ProxyGenOptions& o) {
  // Numbers as text with all their digits: the key must not depend on how JSON prints doubles.
  nlohmann::json settings = {{"kind", proxyClassName(o.kind)},
                             {"method", o.method.empty() ? "default" : o.method},
                             {"alpha", optionalNumber(o.alpha)},
                             {"offset", optionalNumber(o.offset)},
                             {"ratio", optionalNumber(o.ratio)},
                             {"max_faces", o.max_faces},
                             {"min_faces", o.min_faces},
                             {"erosion", optionalNumber(o.erosion)},
                             {"voxel", optionalNumber(o.voxel)},
                             {"fill_holes", o.fill_holes},
                             {"hard_budget", o.hard_budget},
                             {"seed", std::to_string(o.seed)},
                             {"hausdorff_samples", o.hausdorff_samples}};
  if (o.parts) settings["parts"] = *o.parts;
  settings["clearance"] = optionalNumber(o.clearance);
  settings["clearance_ulps"] = optionalNumber(o.clearance_ulps);
  if (!o.placements.empty()) {
    // The placements' exact floats, as a digest (a scene may have thousands of instances).
    std::string bytes(o.placements.size() * sizeof(Affine3f), '\0');
    std::memcpy(bytes.data(), o.placements.data(), bytes.size());
    settings["placements"] = sha256Hex(bytes);
  }
  return settings;
}

std::string proxyCacheKey(const std::string& input_sha256, const nlohmann::json& settings) {
  return sha256Hex(fmt::format("proxyvis proxy cache {}\ninput {}\nsettings {}\nbuild {}\n",
                               kCacheFormat, input_sha256, settings.dump(), programBuildId()));
}

fs::path defaultProxyCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  // The XDG rule: only an absolute path counts.
  if (xdg && *xdg && fs::path(xdg).is_absolute()) return fs::path(xdg) / "proxyvis" / "proxies";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".cache" / "proxyvis" / "proxies";
  return {};
}

ProxyCache::ProxyCache(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_))
    throw WriteError(dir_.string(), "cannot use the proxy cache folder",
                     ec ? ec.message() : "it is not a folder",
                     "give another --cache DIR or --no-cache");
}

std::optional<CachedProxy> ProxyCache::find(const std::string& key, std::string* why) const {
  const auto damaged = [&](const std::string& reason) -> std::optional<CachedProxy> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const fs::path meta_path = dir_ / (key + ".json");
  std::error_code ec;
  if (!fs::exists(meta_path, ec)) return std::nullopt;
  const std::optional<std::string> meta_text = readOwnFileBytes(meta_path);
  if (!meta_text) return damaged("its report cannot be read");
  const nlohmann::json meta = nlohmann::json::parse(*meta_text, nullptr, false);
  if (meta.is_discarded() || !meta.is_object()) return damaged("its report is not JSON");
  ProxyCacheRecord record;
  try {
    const JsonField f(meta, "", meta_path);
    // An entry of another layout is told apart before its other keys are read.
    if (!f.has("format") || !f.has("key") || f["format"].asInt() != kCacheFormat ||
        f["key"].asString() != key)
      return damaged("its report belongs to another entry");
    record = readProxyCacheRecord(f);
  } catch (const Error& e) {
    return damaged(e.what());
  }
  if (record.report.skipped) return CachedProxy{std::move(record.report), {}};
  if (!record.proxy_sha256) return damaged("its report has no proxy_sha256");
  CachedProxy entry{std::move(record.report), {}};
  const std::string& hash = *record.proxy_sha256;
  const std::optional<std::string> bytes = readOwnFileBytes(dir_ / (key + ".ply"));
  if (!bytes) return damaged("its proxy file is missing or unreadable");
  if (sha256Hex(*bytes) != hash)
    return damaged("its proxy file does not have the recorded SHA-256 (truncated or changed)");
  entry.proxy_bytes = std::move(*bytes);
  return entry;
}

void ProxyCache::store(const std::string& key, const CachedProxy& entry) const {
  ProxyCacheRecord record{kCacheFormat, key, entry.report, std::nullopt};
  if (!entry.report.skipped) {
    const fs::path ply = dir_ / (key + ".ply");
    writeAtomically(
        ply, [&](const fs::path& tmp) { writeFileBytes(tmp, entry.proxy_bytes, ply.string()); });
    record.proxy_sha256 = sha256Hex(entry.proxy_bytes);
  }
  // Last: the entry exists only once the proxy file it vouches for is in place.
  writeTextAtomically(dir_ / (key + ".json"), nlohmann::json(record).dump(1) + "\n");
}

}  // namespace proxyvis
