#pragma once
// Typed reads of proxy-gen's own JSON files (reports, cache entries, shard manifests) through the
// path-tracking JsonField reader (util/json_field.h), which names the file and the key's path in
// every error (json_visit.h builds the readers of whole structs on these).
#include <cstdint>
#include <optional>
#include <string>

#include "util/json_field.h"

namespace proxyvis {

using Field = JsonField;

double readDouble(const Field& f);   // a number
uint64_t readCount(const Field& f);  // an integer >= 0

// Reads `j` with `read` as a value of no file (the ADL from_json of a type): errors name the key.
template <typename Read>
auto readWithoutFile(const nlohmann::json& j, Read&& read) {
  static const std::filesystem::path no_file;
  return read(Field(j, "", no_file));
}

}  // namespace proxyvis
