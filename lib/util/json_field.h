#pragma once
// Typed access to JSON values that names the JSON path of every problem ("meshes[2].albedo:
// expected 3 numbers", "renders[1].spp: missing"), in the spirit of pbrt's
// ParameterDictionary::ReportUnused: the one way proxyvis reads JSON it wrote or was given.
//
// A type that crosses a file or process boundary has nlohmann-json's ADL serializers
// (`to_json(json&, const T&)`, `from_json(const json&, T&)`) beside it in its library; its
// from_json reads through a JsonField, and JsonField::get<T>() calls it with the errors' paths
// placed under the field's own path (so "unit_list[3].kind: missing" names the whole path).
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "util/error.h"
#include "util/vec3.h"

namespace proxyvis {

// An Error from reading JSON: "FILE: PATH: PROBLEM; WHY (TODO)". The parts are kept so that a
// nested reader's path can be placed under its caller's (JsonField::get).
class JsonFieldError : public Error {
 public:
  JsonFieldError(std::string file, std::string path, std::string problem, std::string why = {},
                 std::string todo = {});
  const std::string& path() const { return path_; }  // "" = the value read
  const std::string& problem() const { return problem_; }
  const std::string& why() const { return why_; }
  const std::string& todo() const { return todo_; }

 private:
  std::string path_, problem_, why_, todo_;
};

// A JSON value together with its path and the file it came from, for error messages.
class JsonField {
 public:
  // `file` must outlive the field (and the fields taken from it).
  JsonField(const nlohmann::json& value, std::string path = {},
            const std::filesystem::path& file = noFile())
      : value_(value), path_(std::move(path)), file_(file) {}

  const nlohmann::json& value() const { return value_; }
  const std::string& path() const { return path_; }

  // Throws JsonFieldError(FILE, PATH, what, why, todo).
  [[noreturn]] void fail(const std::string& what, const std::string& why = {},
                         const std::string& todo = {}) const;

  // Requires an object whose keys are all in `allowed`; names the first unknown key.
  void expectObject(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const;
  JsonField operator[](const char* key) const;  // requires the key (missing -> error)
  JsonField operator[](size_t index) const;     // requires an array element
  size_t arraySize() const;                     // requires an array

  std::string asString() const;
  bool asBool() const;
  float asFloat() const;                       // finite, within float's range
  double asDouble() const;                     // any number, exactly as written
  int asInt() const;                           // integral, |v| <= 2^30
  uint32_t asUint32() const;                   // integral, 0 <= v < 2^32
  uint64_t asUint64() const;                   // integral, v >= 0
  Vec3f asVec3() const;                        // 3 finite numbers
  std::vector<float> asFloats() const;         // array of finite numbers
  std::vector<std::string> asStrings() const;  // array of strings

  // T read by its from_json (found by ADL); a JsonFieldError it throws is rethrown with its path
  // under this field's and this field's file.
  template <class T>
  T get() const {
    T out{};
    try {
      from_json(value_, out);
    } catch (const JsonFieldError& e) {
      rethrowUnder(e);
    }
    return out;
  }

  // Each element of an array read with get<T>().
  template <class T>
  std::vector<T> getList() const {
    std::vector<T> out;
    for (size_t i = 0, n = arraySize(); i < n; ++i) out.push_back((*this)[i].get<T>());
    return out;
  }

 private:
  static const std::filesystem::path& noFile();
  [[noreturn]] void rethrowUnder(const JsonFieldError& e) const;

  const nlohmann::json& value_;
  std::string path_;
  const std::filesystem::path& file_;
};

}  // namespace proxyvis
