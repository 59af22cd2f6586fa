#include "util/json_field.h"

#include <cmath>
#include <limits>

#include "util/quoted_text.h"

namespace proxyvis {

namespace {

using nlohmann::json;

std::string shownPath(const std::string& path) {
  return path.empty() ? std::string("(top level)") : path;
}

// `inner` (a path relative to `outer`'s value) as a path from `outer`'s root.
std::string joinPath(const std::string& outer, const std::string& inner) {
  if (outer.empty()) return inner;
  if (inner.empty()) return outer;
  return inner.front() == '[' ? outer + inner : outer + "." + inner;
}

}  // namespace

JsonFieldError::JsonFieldError(std::string file, std::string path, std::string problem,
                               std::string why, std::string todo)
    : Error(std::move(file), shownPath(path) + ": " + problem, why, todo),
      path_(std::move(path)),
      problem_(std::move(problem)),
      why_(std::move(why)),
      todo_(std::move(todo)) {}

const std::filesystem::path& JsonField::noFile() {
  static const std::filesystem::path none;
  return none;
}

void JsonField::fail(const std::string& what, const std::string& why,
                     const std::string& todo) const {
  throw JsonFieldError(file_.string(), path_, what, why, todo);
}

void JsonField::rethrowUnder(const JsonFieldError& e) const {
  throw JsonFieldError(file_.string(), joinPath(path_, e.path()), e.problem(), e.why(), e.todo());
}

void JsonField::expectObject(std::initializer_list<const char*> allowed) const {
  if (!value_.is_object()) fail(std::string("expected an object, found ") + value_.type_name());
  for (const auto& [key, unused] : value_.items()) {
    (void)unused;
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      throw JsonFieldError(file_.string(), joinPath(path_, clipped(key)), "unknown key",
                           "a misspelt key would otherwise be ignored silently",
                           "known keys here: " + list);
    }
  }
}

bool JsonField::has(const char* key) const {
  return value_.is_object() && value_.contains(key);
}

JsonField JsonField::operator[](const char* key) const {
  if (!value_.is_object()) fail(std::string("expected an object, found ") + value_.type_name());
  auto it = value_.find(key);
  const std::string sub = joinPath(path_, key);
  if (it == value_.end())
    throw JsonFieldError(file_.string(), sub, "missing", "this key is required");
  return JsonField(*it, sub, file_);
}

JsonField JsonField::operator[](size_t index) const {
  if (!value_.is_array() || index >= value_.size()) fail("array index out of range");
  return JsonField(value_[index], path_ + "[" + std::to_string(index) + "]", file_);
}

size_t JsonField::arraySize() const {
  if (!value_.is_array()) fail(std::string("expected an array, found ") + value_.type_name());
  return value_.size();
}

std::string JsonField::asString() const {
  if (!value_.is_string()) fail(std::string("expected a string, found ") + value_.type_name());
  return value_.get<std::string>();
}

bool JsonField::asBool() const {
  if (!value_.is_boolean())
    fail(std::string("expected true or false, found ") + value_.type_name());
  return value_.get<bool>();
}

float JsonField::asFloat() const {
  const double d = asDouble();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail("number out of range", "must be finite");
  return float(d);
}

double JsonField::asDouble() const {
  if (!value_.is_number()) fail(std::string("expected a number, found ") + value_.type_name());
  return value_.get<double>();
}

int JsonField::asInt() const {
  if (!value_.is_number_integer())
    fail(std::string("expected an integer, found ") + value_.type_name());
  if (value_.is_number_unsigned() && value_.get<uint64_t>() > (uint64_t(1) << 30))
    fail("integer out of range");
  const auto v = value_.get<int64_t>();
  if (v < -(int64_t(1) << 30) || v > (int64_t(1) << 30)) fail("integer out of range");
  return int(v);
}

uint64_t JsonField::asUint64() const {
  if (!value_.is_number_integer())
    fail(std::string("expected an integer, found ") + value_.type_name());
  if (value_.is_number_unsigned()) return value_.get<uint64_t>();
  const auto v = value_.get<int64_t>();
  if (v < 0) fail("integer out of range", "must not be negative");
  return uint64_t(v);
}

uint32_t JsonField::asUint32() const {
  const uint64_t v = asUint64();
  if (v > std::numeric_limits<uint32_t>::max()) fail("integer out of range");
  return uint32_t(v);
}

std::vector<float> JsonField::asFloats() const {
  const size_t n = arraySize();
  std::vector<float> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = (*this)[i].asFloat();
  return out;
}

std::vector<std::string> JsonField::asStrings() const {
  const size_t n = arraySize();
  std::vector<std::string> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = (*this)[i].asString();
  return out;
}

Vec3f JsonField::asVec3() const {
  if (!value_.is_array() || value_.size() != 3) fail("expected an array of 3 numbers");
  return {(*this)[size_t(0)].asFloat(), (*this)[1].asFloat(), (*this)[2].asFloat()};
}

}  // namespace proxyvis
