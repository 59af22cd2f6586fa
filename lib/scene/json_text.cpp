// Scene JSON text (internal/json_text.h). nlohmann's dump(2) puts every array element on its own
// line and prints a float's double in full; a 2-mesh scene became 150 lines of single numbers.
#include "scene/internal/json_text.h"

#include <algorithm>
#include <charconv>

#include "util/error.h"

namespace proxyvis::detail {

using nlohmann::ordered_json;

namespace {

// An array of at most this many characters, made of number arrays, stays on one line.
constexpr size_t kMaxLineArray = 72;

bool isNumberArray(const ordered_json& v) {
  return v.is_array() &&
         std::all_of(v.begin(), v.end(), [](const ordered_json& e) { return e.is_number(); });
}

std::string scalarText(const ordered_json& v) {
  if (v.is_number_float()) {
    const double d = v.get<double>();
    const float f = float(d);
    if (double(f) == d) return shortestFloatText(f);  // stored from a float
  }
  return v.dump();
}

// `v` (a scalar or an array of them, nested) on one line: "[1, 2, 3]".
std::string oneLine(const ordered_json& v) {
  if (!v.is_array()) return scalarText(v);
  std::string out = "[";
  for (size_t i = 0; i < v.size(); ++i) {
    if (i > 0) out += ", ";
    out += oneLine(v[i]);
  }
  return out + "]";
}

void append(std::string& out, const ordered_json& v, size_t indent) {
  const std::string inner(indent + 2, ' ');
  if (v.is_object() && !v.empty()) {
    out += "{\n";
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (!first) out += ",\n";
      first = false;
      out += inner + ordered_json(it.key()).dump() + ": ";
      append(out, it.value(), indent + 2);
    }
    out += '\n';
    out.append(indent, ' ');
    out += '}';
    return;
  }
  if (!v.is_array() || v.empty() || isNumberArray(v)) {
    out += v.is_array() ? oneLine(v) : v.is_object() ? "{}" : scalarText(v);
    return;
  }
  if (std::all_of(v.begin(), v.end(), isNumberArray)) {
    const std::string line = oneLine(v);
    if (line.size() <= kMaxLineArray) {
      out += line;
      return;
    }
  }
  out += "[\n";
  for (size_t i = 0; i < v.size(); ++i) {
    if (i > 0) out += ",\n";
    out += inner;
    append(out, v[i], indent + 2);
  }
  out += '\n';
  out.append(indent, ' ');
  out += ']';
}

}  // namespace

std::string shortestFloatText(float v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), v);
  PV_CHECK(ec == std::errc());
  // Readers parse a double and narrow it; in rare cases that double rounding differs from
  // parsing a float. Then the exact double of `v` (17 digits) is written instead.
  double d = 0;
  const auto parsed = std::from_chars(buf, end, d);
  if (parsed.ec == std::errc() && parsed.ptr == end && float(d) == v) return std::string(buf, end);
  return ordered_json(double(v)).dump();
}

std::string sceneJsonText(const nlohmann::ordered_json& value) {
  std::string out;
  append(out, value, 0);
  return out;
}

}  // namespace proxyvis::detail
