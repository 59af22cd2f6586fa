#pragma once
// One list of a struct's JSON keys serves both directions. A struct's `fields(s, v)` (found by
// argument-dependent lookup) names each key and member once; JsonWriter writes them (to_json),
// FieldReader reads them back through the path-tracking Field reader (from_json), so the writer
// and the reader of a file cannot disagree. Keys: v(key, member) always present (an optional
// member: present when set); v.nullable(key, optional): null when unset; v.nonEmpty(key, vector):
// absent when empty.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "proxies/pipeline/proxy_report.h"
#include "proxies/pipeline/report_fields.h"

namespace proxyvis {

template <typename T>
struct Tag {};

// The leaf types and those with a JSON form of their own (defined in report_fields.cpp and
// proxy_report.cpp).
inline uint64_t readAs(const Field& f, Tag<uint64_t>) {
  return f.asUint64();
}
inline double readAs(const Field& f, Tag<double>) {
  return f.asDouble();
}
inline bool readAs(const Field& f, Tag<bool>) {
  return f.asBool();
}
inline int readAs(const Field& f, Tag<int>) {
  return f.asInt();
}
inline std::string readAs(const Field& f, Tag<std::string>) {
  return f.asString();
}
ProxyClass readAs(const Field& f, Tag<ProxyClass>);
nlohmann::json readAs(const Field& f, Tag<nlohmann::json>);  // an object, kept as it is
std::map<std::string, double> readAs(const Field& f, Tag<std::map<std::string, double>>);
HausdorffDistances readAs(const Field& f, Tag<HausdorffDistances>);
LadderEntry readAs(const Field& f, Tag<LadderEntry>);
inline SceneMeshReport readAs(const Field& f, Tag<SceneMeshReport>) {
  return readSceneMeshReport(f);
}

struct FieldReader;
struct JsonWriter;

// A struct that lists its keys.
template <typename T>
concept HasFields = requires(T& t, JsonWriter& w) {
  fields(t, w);
};

template <typename T>
requires(!HasFields<T>) nlohmann::json toJsonValue(const T& v) {
  return v;
}
inline nlohmann::json toJsonValue(ProxyClass c) {
  return proxyClassName(c);
}
nlohmann::json toJsonValue(const HausdorffDistances& h);
nlohmann::json toJsonValue(const LadderEntry& e);
template <HasFields T>
nlohmann::json toJsonValue(const T& v);

// A struct with fields(): read as an object, key by key.
template <HasFields T>
T readAs(const Field& f, Tag<T>);

template <typename T>
std::vector<T> readAs(const Field& f, Tag<std::vector<T>>) {
  std::vector<T> out;
  for (size_t i = 0, n = f.arraySize(); i < n; ++i) out.push_back(readAs(f[i], Tag<T>{}));
  return out;
}

struct FieldReader {
  const Field& f;
  template <typename T>
  void operator()(const char* key, T& v) {
    v = readAs(f[key], Tag<T>{});
  }
  template <typename T>
  void operator()(const char* key, std::optional<T>& v) {
    v = f.has(key) ? std::optional<T>(readAs(f[key], Tag<T>{})) : std::nullopt;
  }
  template <typename T>
  void nullable(const char* key, std::optional<T>& v) {
    const Field value = f[key];
    v = value.value().is_null() ? std::nullopt : std::optional<T>(readAs(value, Tag<T>{}));
  }
  template <typename T>
  void nonEmpty(const char* key, std::vector<T>& v) {
    v = f.has(key) ? readAs(f[key], Tag<std::vector<T>>{}) : std::vector<T>{};
  }
};

template <HasFields T>
T readAs(const Field& f, Tag<T>) {
  if (!f.value().is_object())
    f.fail(std::string("expected an object, found ") + f.value().type_name());
  T value;
  FieldReader reader{f};
  fields(value, reader);
  return value;
}

template <typename T>
nlohmann::json toJsonValue(const std::vector<T>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const T& e : v) a.push_back(toJsonValue(e));
  return a;
}

struct JsonWriter {
  nlohmann::json& j;
  template <typename T>
  void operator()(const char* key, const T& v) {
    j[key] = toJsonValue(v);
  }
  template <typename T>
  void operator()(const char* key, const std::optional<T>& v) {
    if (v) j[key] = toJsonValue(*v);
  }
  template <typename T>
  void nullable(const char* key, const std::optional<T>& v) {
    j[key] = v ? toJsonValue(*v) : nlohmann::json(nullptr);
  }
  template <typename T>
  void nonEmpty(const char* key, const std::vector<T>& v) {
    if (!v.empty()) j[key] = toJsonValue(v);
  }
};

template <HasFields T>
nlohmann::json toJsonValue(const T& v) {
  nlohmann::json j = nlohmann::json::object();
  JsonWriter writer{j};
  fields(const_cast<T&>(v), writer);  // the writer only reads
  return j;
}

// A file's value read as T, with errors naming the file and the key's path.
template <typename T>
T readFields(const Field& f) {
  return readAs(f, Tag<T>{});
}

}  // namespace proxyvis
