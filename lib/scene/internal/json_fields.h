#pragma once
// Typed access to JSON values that names the JSON path of every problem ("meshes[2].albedo:
// expected 3 numbers"), in the spirit of pbrt's ParameterDictionary::ReportUnused: a field that
// is not read is an error, never silently ignored.
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "util/vec3.h"

namespace proxyvis::detail {

using nlohmann::json;

// A JSON value together with its path and the file it came from, for error messages.
class Field {
 public:
  Field(const json& value, std::string path, const std::filesystem::path& file)
      : value_(value), path_(std::move(path)), file_(file) {}

  const json& value() const { return value_; }
  const std::string& path() const { return path_; }

  // Throws Error("FILE", "PATH: what", why, todo).
  [[noreturn]] void fail(const std::string& what, const std::string& why = {},
                         const std::string& todo = {}) const;

  // Requires an object whose keys are all in `allowed`; names the first unknown key.
  void expectObject(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const;
  Field operator[](const char* key) const;  // requires the key (missing -> error)
  Field operator[](size_t index) const;     // requires an array element
  size_t arraySize() const;                 // requires an array

  std::string asString() const;
  bool asBool() const;
  float asFloat() const;                // finite
  int asInt() const;                    // integral
  Vec3f asVec3() const;                 // 3 finite numbers
  std::vector<float> asFloats() const;  // array of finite numbers

 private:
  const json& value_;
  std::string path_;
  const std::filesystem::path& file_;
};

}  // namespace proxyvis::detail
