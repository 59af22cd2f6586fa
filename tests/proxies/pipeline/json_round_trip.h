#pragma once
// Helpers of the typed-JSON tests: a value through JSON text and back, and the message of the
// Error that reading a JSON value as a type throws.
#include <nlohmann/json.hpp>
#include <string>

#include "util/error.h"

namespace proxyvis::report_test {

template <typename T>
T throughText(const T& value) {
  return nlohmann::json::parse(nlohmann::json(value).dump(1)).template get<T>();
}

// "" when `j` reads as T.
template <typename T>
std::string readError(const nlohmann::json& j) {
  try {
    (void)j.get<T>();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace proxyvis::report_test
