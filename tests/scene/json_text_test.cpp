// The scene JSON layout: shortest float text that reads back exactly, numbers arrays on one line,
// objects indented, and valid JSON that parses to the same values.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/internal/json_text.h"
#include "util/rng.h"

namespace proxyvis::detail {
namespace {

using nlohmann::ordered_json;

TEST(ShortestFloatText, ShortDecimalsStayShort) {
  EXPECT_EQ(shortestFloatText(0.8f), "0.8");
  EXPECT_EQ(shortestFloatText(0.1f), "0.1");
  EXPECT_EQ(shortestFloatText(16.0f), "16");
  EXPECT_EQ(shortestFloatText(-3.9f), "-3.9");
  EXPECT_EQ(shortestFloatText(1.0f / 3.0f), "0.33333334");
}

TEST(ShortestFloatText, ReadsBackAsTheSameFloatThroughDouble) {
  // Random bit patterns cover every exponent; read as JSON readers do: strtod, then narrow.
  const uint64_t seed = 7;
  Rng rng(seed, 0);
  for (int i = 0; i < 200000; ++i) {
    const float v = std::bit_cast<float>(rng.nextU32());
    if (!std::isfinite(v)) continue;
    const std::string text = shortestFloatText(v);
    ASSERT_EQ(float(std::strtod(text.c_str(), nullptr)), v) << text << " seed " << seed;
    ASSERT_EQ(ordered_json::parse(text).get<float>(), v) << text << " seed " << seed;
    ASSERT_LE(text.size(), 24u) << text;
  }
}

TEST(SceneJsonText, NumberArraysOnOneLineObjectsIndented) {
  ordered_json j;
  j["eye"] = {double(0.8f), 16.0, -3.5};
  j["resolution"] = {128, 96};
  j["corners"] = {{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}};
  j["list"] = ordered_json::array({ordered_json{{"a", 1}}, ordered_json{{"b", "x"}}});
  j["empty"] = ordered_json::array();
  const std::string text = sceneJsonText(j);
  EXPECT_EQ(text,
            "{\n"
            "  \"eye\": [0.8, 16, -3.5],\n"
            "  \"resolution\": [128, 96],\n"
            "  \"corners\": [[1, 2, 3], [4, 5, 6]],\n"
            "  \"list\": [\n"
            "    {\n"
            "      \"a\": 1\n"
            "    },\n"
            "    {\n"
            "      \"b\": \"x\"\n"
            "    }\n"
            "  ],\n"
            "  \"empty\": []\n"
            "}");
  // Same values back, with the float read as a float.
  const ordered_json back = ordered_json::parse(text);
  EXPECT_EQ(back["eye"][0].get<float>(), 0.8f);
  EXPECT_EQ(back["corners"], j["corners"]);
  EXPECT_EQ(back["list"], j["list"]);
}

TEST(SceneJsonText, LongArraysOfArraysBreakPerElement) {
  ordered_json rows = ordered_json::array();
  for (int i = 0; i < 8; ++i) rows.push_back({i + 0.25, i + 0.5, i + 0.75});
  const std::string text = sceneJsonText(ordered_json{{"rows", rows}});
  std::istringstream lines(text);
  std::string line;
  int row_lines = 0;
  while (std::getline(lines, line))
    if (line.find("[") != std::string::npos && line.find("]") != std::string::npos) ++row_lines;
  EXPECT_EQ(row_lines, 8) << text;  // each inner array whole on its own line
  EXPECT_EQ(ordered_json::parse(text)["rows"], rows);
}

}  // namespace
}  // namespace proxyvis::detail
