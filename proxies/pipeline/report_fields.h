#pragma once
// proxy-gen's own JSON files (reports, cache entries, shard manifests) are read through the
// path-tracking JsonField reader (util/json_field.h), which names the file and the key's path in
// every error; json_visit.h builds the readers of whole structs on it.
#include <cstdint>
#include <optional>
#include <string>

#include "util/json_field.h"

namespace proxyvis {

using Field = JsonField;

// Reads `j` with `read` as a value of no file (the ADL from_json of a type): errors name the key.
template <typename Read>
auto readWithoutFile(const nlohmann::json& j, Read&& read) {
  return read(JsonField(j));
}

}  // namespace proxyvis
