#pragma once
// proxy-gen's cache of generated proxies on disk (docs/proxies.md, "The proxy cache"). An entry
// is keyed by the SHA-256 of the input mesh file's bytes and of every setting that changes the
// output (ProxyGenOptions, the program's build), so a second run of the same command copies the
// proxies instead of generating them again, and any change of input or setting misses.
//
// An entry is two files in the cache folder: "<key>.ply" (the proxy file exactly as written,
// absent when the mesh gets no proxy) and "<key>.json" (the generator's report with its proof,
// and the SHA-256 of the .ply). Both are written atomically (temporary + rename), the .json last,
// so a killed run leaves at most a stale temporary and never an entry that is used: an entry
// whose .json is missing, unreadable, or whose .ply does not have the recorded hash is a miss and
// is written again.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/proxy_report.h"

namespace proxyvis {

class JsonField;

// A cached result: the report (its proxy's, or why the mesh gets none: skipped; no name or cache
// state) and the proxy file's bytes (empty when skipped).
struct CachedProxy {
  SceneMeshReport report;
  std::string proxy_bytes;
};

// "<key>.json": the entry's layout version and key, the report, and the SHA-256 of "<key>.ply"
// (absent when the mesh gets no proxy).
struct ProxyCacheRecord {
  int format = 0;
  std::string key;
  SceneMeshReport report;
  std::optional<std::string> proxy_sha256;
  bool operator==(const ProxyCacheRecord&) const = default;
};
void to_json(nlohmann::json& j, const ProxyCacheRecord& r);
void from_json(const nlohmann::json& j, ProxyCacheRecord& r);
// from_json's reader, for a file's value: errors name the file and the key's path.
ProxyCacheRecord readProxyCacheRecord(const JsonField& f);

// The bytes of a file this run wrote or keeps in its cache (not registered as an input, so the
// run may replace it), or nullopt when it is missing, not a regular file, larger than 1 GiB or
// unreadable.
std::optional<std::string> readOwnFileBytes(const std::filesystem::path& path);

// The settings of `options` that change a generated proxy, as canonical JSON (the time budget is
// left out: it can only make a run fail, and failures are not cached).
nlohmann::json proxyCacheSettings(const ProxyGenOptions& options);

// The entry key: 64 hex digits of SHA-256 over the input's hash, the settings and the build id.
std::string proxyCacheKey(const std::string& input_sha256, const nlohmann::json& settings);

// The default folder: $XDG_CACHE_HOME/proxyvis/proxies, else $HOME/.cache/proxyvis/proxies;
// empty when neither variable is set.
std::filesystem::path defaultProxyCacheDir();

class ProxyCache {
 public:
  // Uses (and creates) `dir`. Throws WriteError naming it when it cannot be created or is not a
  // folder.
  explicit ProxyCache(std::filesystem::path dir);

  const std::filesystem::path& dir() const { return dir_; }

  // The entry for `key`, or nullopt when there is none or it is damaged (then `why`, if given,
  // says what was wrong; an absent entry leaves it empty). Never throws for a bad entry.
  std::optional<CachedProxy> find(const std::string& key, std::string* why = nullptr) const;

  // Writes the entry for `key` (replacing a damaged one). Throws WriteError when it cannot.
  void store(const std::string& key, const CachedProxy& entry) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace proxyvis
