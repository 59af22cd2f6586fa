// util/json_field.h: every problem names the file and the JSON path of the value, also through a
// nested type's own from_json (JsonField::get).
#include "util/json_field.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace proxyvis {
namespace {

using nlohmann::json;

struct Point {
  int x = 0, y = 0;
};
void from_json(const json& j, Point& p) {
  const JsonField f(j);
  p.x = f["x"].asInt();
  p.y = f["y"].asInt();
}

// The message of the JsonFieldError `read` throws ("" when it throws none).
template <class Read>
std::string errorOf(Read read) {
  try {
    read();
  } catch (const JsonFieldError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonField, MissingKeyNamesItsWholePath) {
  const std::filesystem::path file = "dir/plan.json";
  const json j = json::parse(R"({"a": {"b": [{}, {"c": 1}]}})");
  const JsonField top(j, "", file);
  EXPECT_EQ(top["a"]["b"][1]["c"].asInt(), 1);
  EXPECT_EQ(errorOf([&] { top["a"]["b"][size_t(0)]["c"].asInt(); }),
            "dir/plan.json: a.b[0].c: missing; this key is required");
}

TEST(JsonField, NestedReaderErrorsAreUnderTheCallersPath) {
  const std::filesystem::path file = "f.json";
  const json j = json::parse(R"({"points": [{"x": 1, "y": 2}, {"x": 3}, {"x": "4", "y": 5}]})");
  const JsonField top(j, "", file);
  EXPECT_EQ(top["points"][size_t(0)].get<Point>().y, 2);
  EXPECT_EQ(errorOf([&] { top["points"].getList<Point>(); }),
            "f.json: points[1].y: missing; this key is required");
  try {
    top["points"][2].get<Point>();
    FAIL() << "a string read as an integer";
  } catch (const JsonFieldError& e) {
    EXPECT_EQ(e.path(), "points[2].x");
    EXPECT_EQ(e.problem(), "expected an integer, found string");
    EXPECT_EQ(e.file(), "f.json");
  }
  // Through nlohmann's own get<T>() the path is relative to the value read, without a file.
  EXPECT_EQ(errorOf([&] { (void)j.at("points").at(1).get<Point>(); }),
            "y: missing; this key is required");
}

TEST(JsonField, NumbersAreCheckedForTheirType) {
  const json j = json::parse(
      R"({"neg": -1, "big": 4294967296, "huge": 18446744073709551615, "half": 0.5,
          "text": "1", "int": 1073741825})");
  const JsonField f(j);
  EXPECT_EQ(f["huge"].asUint64(), 18446744073709551615ull);
  EXPECT_EQ(f["big"].asUint64(), 4294967296ull);
  EXPECT_DOUBLE_EQ(f["half"].asDouble(), 0.5);
  EXPECT_DOUBLE_EQ(f["neg"].asDouble(), -1.0);
  EXPECT_EQ(errorOf([&] { f["neg"].asUint64(); }),
            "neg: integer out of range; must not be negative");
  EXPECT_EQ(errorOf([&] { f["big"].asUint32(); }), "big: integer out of range");
  EXPECT_EQ(errorOf([&] { f["int"].asInt(); }), "int: integer out of range");
  EXPECT_EQ(errorOf([&] { f["huge"].asInt(); }), "huge: integer out of range");
  EXPECT_EQ(errorOf([&] { f["half"].asUint64(); }), "half: expected an integer, found number");
  EXPECT_EQ(errorOf([&] { f["text"].asDouble(); }), "text: expected a number, found string");
}

TEST(JsonField, ListsAndObjectsAreChecked) {
  const json j = json::parse(R"({"names": ["a", 2], "one": "x", "obj": {"k": 1, "typo": 2}})");
  const JsonField f(j);
  EXPECT_EQ(errorOf([&] { f["names"].asStrings(); }), "names[1]: expected a string, found number");
  EXPECT_EQ(errorOf([&] { f["one"].asStrings(); }), "one: expected an array, found string");
  EXPECT_EQ(errorOf([&] { f["one"]["k"]; }), "one: expected an object, found string");
  EXPECT_EQ(errorOf([&] { f["obj"].expectObject({"k"}); }),
            "obj.typo: unknown key; a misspelt key would otherwise be ignored silently (known "
            "keys here: k)");
  EXPECT_EQ(errorOf([&] { JsonField(json(3)).asString(); }),
            "(top level): expected a string, found number");
}

}  // namespace
}  // namespace proxyvis
