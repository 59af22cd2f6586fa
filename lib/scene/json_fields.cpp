#include "scene/internal/json_fields.h"

#include <cmath>

#include "scene/internal/quoted.h"
#include "util/error.h"

namespace proxyvis::detail {

namespace {

const char* typeName(const json& v) {
  return v.type_name();
}

}  // namespace

void Field::fail(const std::string& what, const std::string& why, const std::string& todo) const {
  throw Error(file_.string(), (path_.empty() ? std::string("(top level)") : path_) + ": " + what,
              why, todo);
}

void Field::expectObject(std::initializer_list<const char*> allowed) const {
  if (!value_.is_object()) fail(std::string("expected an object, found ") + typeName(value_));
  for (const auto& [key, unused] : value_.items()) {
    (void)unused;
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      const std::string shown = clipped(key);
      const std::string sub = path_.empty() ? shown : path_ + "." + shown;
      throw Error(file_.string(), sub + ": unknown key",
                  "a misspelt key would otherwise be ignored silently", "known keys here: " + list);
    }
  }
}

bool Field::has(const char* key) const {
  return value_.is_object() && value_.contains(key);
}

Field Field::operator[](const char* key) const {
  if (!value_.is_object()) fail(std::string("expected an object, found ") + typeName(value_));
  auto it = value_.find(key);
  const std::string sub = path_.empty() ? key : path_ + "." + key;
  if (it == value_.end()) throw Error(file_.string(), sub + ": missing", "this key is required");
  return Field(*it, sub, file_);
}

Field Field::operator[](size_t index) const {
  if (!value_.is_array() || index >= value_.size()) fail("array index out of range");
  return Field(value_[index], path_ + "[" + std::to_string(index) + "]", file_);
}

size_t Field::arraySize() const {
  if (!value_.is_array()) fail(std::string("expected an array, found ") + typeName(value_));
  return value_.size();
}

std::string Field::asString() const {
  if (!value_.is_string()) fail(std::string("expected a string, found ") + typeName(value_));
  return value_.get<std::string>();
}

bool Field::asBool() const {
  if (!value_.is_boolean()) fail(std::string("expected true or false, found ") + typeName(value_));
  return value_.get<bool>();
}

float Field::asFloat() const {
  if (!value_.is_number()) fail(std::string("expected a number, found ") + typeName(value_));
  const double d = value_.get<double>();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail("number out of range", "must be finite");
  return float(d);
}

int Field::asInt() const {
  if (!value_.is_number_integer())
    fail(std::string("expected an integer, found ") + typeName(value_));
  const auto v = value_.get<int64_t>();
  if (v < -(int64_t(1) << 30) || v > (int64_t(1) << 30)) fail("integer out of range");
  return int(v);
}

std::vector<float> Field::asFloats() const {
  const size_t n = arraySize();
  std::vector<float> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = (*this)[i].asFloat();
  return out;
}

Vec3f Field::asVec3() const {
  if (!value_.is_array() || value_.size() != 3) fail("expected an array of 3 numbers");
  return {(*this)[size_t(0)].asFloat(), (*this)[1].asFloat(), (*this)[2].asFloat()};
}

}  // namespace proxyvis::detail
