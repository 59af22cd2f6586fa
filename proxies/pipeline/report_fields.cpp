#include "proxies/pipeline/report_fields.h"

namespace proxyvis {

double readDouble(const Field& f) {
  if (!f.value().is_number())
    f.fail(std::string("expected a number, found ") + f.value().type_name());
  return f.value().get<double>();
}

uint64_t readCount(const Field& f) {
  const nlohmann::json& v = f.value();
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0))
    f.fail(std::string("expected an integer >= 0, found ") + f.value().type_name());
  return f.value().get<uint64_t>();
}

std::optional<double> readDoubleOrNull(const Field& f) {
  if (f.value().is_null()) return std::nullopt;
  return readDouble(f);
}

std::optional<double> optionalDouble(const Field& parent, const char* key) {
  return parent.has(key) ? std::optional<double>(readDouble(parent[key])) : std::nullopt;
}

std::optional<uint64_t> optionalCount(const Field& parent, const char* key) {
  return parent.has(key) ? std::optional<uint64_t>(readCount(parent[key])) : std::nullopt;
}

std::optional<std::string> optionalString(const Field& parent, const char* key) {
  return parent.has(key) ? std::optional<std::string>(parent[key].asString()) : std::nullopt;
}

std::optional<bool> optionalBool(const Field& parent, const char* key) {
  return parent.has(key) ? std::optional<bool>(parent[key].asBool()) : std::nullopt;
}

}  // namespace proxyvis
