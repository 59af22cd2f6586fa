#pragma once
// Property tests of the JSON serializers (util/json_field.h): random values of a type written
// with its to_json, read back with its from_json through a JsonField, must be equal, and every
// key must be required and typed, with an error that names it. Fixed seeds: a failure repeats.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "util/json_field.h"

namespace proxyvis::test {

// Random values with the edges a serializer gets wrong: zeros, extremes, subnormals, strings
// with quotes, control characters and multi-byte UTF-8.
class RandomValues {
 public:
  explicit RandomValues(uint64_t seed) : rng_(seed) {}

  uint64_t u64() {
    switch (pick(4)) {
      case 0:
        return 0;
      case 1:
        return std::numeric_limits<uint64_t>::max() - pick(3);
      default:
        return rng_() >> pick(64);
    }
  }
  uint32_t u32() { return uint32_t(u64() >> 32); }
  // Within JsonField::asInt's range (|v| <= 2^30).
  int smallInt() { return int(int64_t(pick(1u << 31)) - (int64_t(1) << 30)); }
  int count() { return int(pick(1u << 20)); }
  double number() {
    switch (pick(6)) {
      case 0:
        return 0.0;
      case 1:
        return std::numeric_limits<double>::denorm_min() * double(1 + pick(1000));
      case 2:
        return (pick(2) ? -1 : 1) * std::numeric_limits<double>::max();
      case 3:
        return std::uniform_real_distribution<double>(-1, 1)(rng_);
      default: {
        double d = 0;
        do {  // any finite bit pattern: JSON has no inf or NaN
          const uint64_t bits = rng_();
          std::memcpy(&d, &bits, sizeof d);
        } while (!std::isfinite(d));
        return d;
      }
    }
  }
  bool flag() { return pick(2) == 1; }
  std::string text() {
    static const std::vector<std::string> pieces = {"a",  "Z",    "0",  " ",    "\"",   "\\",
                                                    "/",  "\n",   "\t", "\x01", "\x7f", "é",
                                                    "漢", "🙂", "{}", "[]"};
    std::string s;
    for (uint64_t i = 0, n = pick(12); i < n; ++i) s += pieces[pick(pieces.size())];
    return s;
  }
  std::vector<std::string> texts() {
    std::vector<std::string> v(pick(4));
    for (std::string& s : v) s = text();
    return v;
  }
  uint64_t pick(uint64_t n) { return rng_() % n; }
  // Sets each argument, left to right, to a random value of its type (an int gets smallInt()).
  template <typename... T>
  void fill(T&... fields) {
    (set(fields), ...);
  }

 private:
  void set(double& d) { d = number(); }
  template <size_t N>
  void set(double (&a)[N]) {
    for (double& d : a) d = number();
  }
  void set(uint64_t& u) { u = u64(); }
  void set(uint32_t& u) { u = u32(); }
  void set(int& i) { i = smallInt(); }
  void set(std::string& s) { s = text(); }
  void set(std::vector<std::string>& s) { s = texts(); }

  std::mt19937_64 rng_;
};

// The JSON path named by the JsonFieldError that reading `j` as a T throws; "(no error)" when
// it reads.
template <class T>
std::string errorPath(const nlohmann::json& j) {
  try {
    (void)JsonField(j).get<T>();
  } catch (const JsonFieldError& e) {
    return e.path();
  }
  return "(no error)";
}

// `count` values from make(values) survive to_json -> text -> from_json exactly, and writing the
// value read gives the same text.
template <class T, class Make>
void expectRoundTrips(Make make, int count = 300, uint64_t seed = 20261206) {
  RandomValues values(seed);
  for (int i = 0; i < count; ++i) {
    const T value = make(values);
    const std::string text = nlohmann::json(value).dump();
    const T back = JsonField(nlohmann::json::parse(text)).get<T>();
    ASSERT_TRUE(back == value) << "value " << i << " did not survive: " << text;
    ASSERT_EQ(nlohmann::json(back).dump(), text);
  }
}

// Removing any key of value's JSON object (but `optional` ones) is an error naming that key, and
// so is giving it a value of the wrong type.
template <class T>
void expectEveryKeyChecked(const T& value, const std::set<std::string>& optional = {}) {
  const nlohmann::json good = value;
  ASSERT_TRUE(good.is_object());
  for (const auto& [key, v] : good.items()) {
    if (optional.count(key)) continue;
    nlohmann::json missing = good;
    missing.erase(key);
    try {
      (void)JsonField(missing).get<T>();
      ADD_FAILURE() << "no error without \"" << key << "\"";
    } catch (const JsonFieldError& e) {
      EXPECT_EQ(e.path(), key);
      EXPECT_EQ(e.problem(), "missing");
    }
    nlohmann::json wrong = good;
    wrong[key] = v.is_string() ? nlohmann::json(12) : nlohmann::json("not this");
    try {
      (void)JsonField(wrong).get<T>();
      ADD_FAILURE() << "no error with \"" << key << "\" of the wrong type";
    } catch (const JsonFieldError& e) {
      EXPECT_EQ(e.path().substr(0, key.size()), key) << e.what();
    }
  }
}

}  // namespace proxyvis::test

// The two property tests every serialized type gets: SUITE.RandomValuesRoundTrip and
// SUITE.EveryKeyIsRequiredAndTyped, with values from MAKE(RandomValues&) (the latter seeded SEED).
#define PROXYVIS_JSON_PROPERTY_TESTS(SUITE, TYPE, MAKE, SEED)    \
  TEST(SUITE, RandomValuesRoundTrip) {                           \
    ::proxyvis::test::expectRoundTrips<TYPE>(MAKE);              \
  }                                                              \
  TEST(SUITE, EveryKeyIsRequiredAndTyped) {                      \
    ::proxyvis::test::RandomValues values(SEED);                 \
    ::proxyvis::test::expectEveryKeyChecked<TYPE>(MAKE(values)); \
  }
