#include "view3d/view3d_html.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "mesh/primitives.h"
#include "util/error.h"
#include "util/escape_html.h"

namespace proxyvis {
namespace {

using detail::base64;

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The page's embedded data (the JSON of <script id="pv-view3d-data">).
nlohmann::json pageData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"pv-view3d-data\">";
  const size_t start = html.find(open);
  EXPECT_NE(start, std::string::npos);
  const size_t end = html.find("</script>", start);
  return nlohmann::json::parse(html.substr(start + open.size(), end - start - open.size()));
}

std::string decodeBase64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  uint32_t bits = 0;
  int n = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = bits << 6 | uint32_t(digits.find(c));
    if ((n += 6) >= 8) out += char((bits >> (n -= 8)) & 255);
  }
  return out;
}

template <typename T>
std::vector<T> decodeArray(const nlohmann::json& base64_text) {
  const std::string bytes = decodeBase64(base64_text.get<std::string>());
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

struct Pair {
  TriMesh original = makeUvSphere({10, 0, 0}, 1, 12, 6, "original.off");
  TriMesh proxy = makeBoxMesh({8.5f, -1.5f, -1.5f}, {11.5f, 1.5f, 1.5f}, "proxy.ply");
};

View3dPage examplePage(const Pair& pair) {
  View3dPage page;
  page.title = "check </script><script>alert(1)</script>";
  page.original = &pair.original;
  page.proxy = &pair.proxy;
  page.claim = "outside";
  View3dSegmentLayer hm;
  hm.id = "hm";
  hm.label = "HM' segments";
  hm.meaning = "original blocks, proxy misses";
  hm.color = "#d62728";
  hm.counted = 7;
  hm.breaks_claim = true;
  for (int i = 0; i < 7; ++i) hm.segments.push_back({{0, float(i), 0}, {20, float(i), 0}});
  View3dSegmentLayer mh = hm;
  mh.id = "mh";
  mh.label = "MH' segments";
  mh.color = "#1f77b4";
  mh.counted = 0;
  mh.breaks_claim = false;
  mh.visible = false;
  mh.segments.clear();
  page.layers = {mh, hm};
  page.check.classes = {
      {{10, 0.1, 0.05, 0.17}, {7, 0.07, 0.03, 0.14}, {0, 0, 0, 0.04}, {83, 0.83, 0.74, 0.89}}};
  page.check.sampled_class = "general";
  page.check.exact = "intersecting";
  page.check.original = {"<b>original.off</b>", true};
  page.json = {{"counts", {{"HH", 10}, {"HM", 7}, {"MH", 0}, {"MM", 83}}}};
  return page;
}

TEST(View3dHtml, Base64) {
  EXPECT_EQ(base64("", 0), "");
  EXPECT_EQ(base64("f", 1), "Zg==");
  EXPECT_EQ(base64("fo", 2), "Zm8=");
  EXPECT_EQ(base64("foo", 3), "Zm9v");
  EXPECT_EQ(base64("foob", 4), "Zm9vYg==");
  EXPECT_EQ(base64("fooba", 5), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar", 6), "Zm9vYmFy");
  const unsigned char high[] = {0xff, 0xfe, 0x00};
  EXPECT_EQ(base64(high, 3), "//4A");
}

TEST(View3dHtml, EscapesTextAndScriptData) {
  EXPECT_EQ(escapeHtml("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&#39;");
  const nlohmann::json j = {{"file", "</script><!--x"}};
  const std::string text = detail::jsonForScript(j);
  EXPECT_EQ(text.find('<'), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(text), j);
  // Invalid UTF-8 (a file name) does not throw.
  EXPECT_NO_THROW(detail::jsonForScript({{"file", std::string("a\xff")}}));
}

TEST(View3dHtml, PageIsSelfContained) {
  const Pair pair;
  const std::string html = view3dHtml(examplePage(pair));
  // Three scripts: the import map, the data, the view's module; nothing loaded from elsewhere.
  EXPECT_EQ(occurrences(html, "<script"), 3u);
  EXPECT_EQ(occurrences(html, "</script>"), 3u);
  EXPECT_EQ(occurrences(html, "src="), 0u);
  EXPECT_EQ(occurrences(html, "href="), 0u);
  EXPECT_EQ(occurrences(html, "http://"), 0u);
  EXPECT_EQ(occurrences(html, "https://"), 0u);
  EXPECT_NE(html.find("<script type=\"importmap\">"), std::string::npos);
  EXPECT_NE(html.find("\"three\":\"data:text/javascript;base64,"), std::string::npos);
  EXPECT_NE(html.find("\"three/core\":\"data:text/javascript;base64,"), std::string::npos);
  EXPECT_NE(html.find("three/addons/controls/OrbitControls.js"), std::string::npos);
  EXPECT_EQ(html.find("three.core.min.js"), std::string::npos);  // rewritten into the map
  EXPECT_NE(html.find("Permission is hereby granted"), std::string::npos);  // three's license
  EXPECT_NE(html.find("alert(1)"), std::string::npos);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;original.off&lt;/b&gt;"), std::string::npos);
}

TEST(View3dHtml, TablesAndLayers) {
  const Pair pair;
  const std::string html = view3dHtml(examplePage(pair));
  EXPECT_NE(html.find("<tr class=\"breaks\"><td>HM'</td><td class=\"num\">7</td>"),
            std::string::npos);
  EXPECT_NE(html.find("breaks the outside claim"), std::string::npos);
  EXPECT_NE(html.find("[0.030000, 0.140000]"), std::string::npos);
  // The layer that breaks the claim comes first and is on; the other one is off.
  const size_t hm = html.find("data-layer=\"hm\" data-counted=\"7\" data-drawn=\"7\"");
  const size_t mh = html.find("data-layer=\"mh\" data-counted=\"0\" data-drawn=\"0\"");
  ASSERT_NE(hm, std::string::npos);
  ASSERT_NE(mh, std::string::npos);
  EXPECT_LT(hm, mh);
  EXPECT_NE(html.find("id=\"layer-hm\" checked>"), std::string::npos);
  EXPECT_NE(html.find("id=\"layer-mh\">"), std::string::npos);
  EXPECT_NE(html.find("id=\"layer-original\" checked>"), std::string::npos);
  EXPECT_NE(html.find("id=\"layer-proxy\" checked>"), std::string::npos);
}

TEST(View3dHtml, DataHoldsTheMeshesAboutTheirCentre) {
  const Pair pair;
  const nlohmann::json data = pageData(view3dHtml(examplePage(pair)));
  EXPECT_EQ(data["center"], nlohmann::json::array({10.0, 0.0, 0.0}));
  EXPECT_EQ(data["proxy"]["triangles"], 12);
  const auto positions = decodeArray<float>(data["proxy"]["positions"]);
  const auto indices = decodeArray<uint32_t>(data["proxy"]["indices"]);
  ASSERT_EQ(positions.size(), 24u);
  EXPECT_FLOAT_EQ(positions[0], -1.5f);
  EXPECT_FLOAT_EQ(positions[3], 1.5f);
  ASSERT_EQ(indices.size(), 36u);
  EXPECT_EQ(indices[1], 2u);
  EXPECT_EQ(data["original"]["triangles"], pair.original.numTriangles());
  // Segments clipped to the box of both meshes, enlarged by 5 % of its diagonal.
  ASSERT_EQ(data["layers"].size(), 2u);
  EXPECT_EQ(data["layers"][0]["id"], "hm");
  const auto lines = decodeArray<float>(data["layers"][0]["positions"]);
  ASSERT_EQ(lines.size(), 7u * 6);
  const float margin = 0.1f * 0.5f * std::sqrt(27.0f);
  EXPECT_NEAR(lines[0], -1.5f - margin, 1e-5);
  EXPECT_NEAR(lines[3], 1.5f + margin, 1e-5);
}

TEST(View3dHtml, CapsWhatItEmbeds) {
  const Pair pair;
  View3dPage page = examplePage(pair);
  const TriMesh big = makeUvSphere({10, 0, 0}, 1, 200, 100, "big.off");  // 39,600 triangles
  page.original = &big;
  View3dLimits limits;
  limits.max_original_triangles = 2'000;
  limits.max_segments_per_layer = 3;
  const std::string html = view3dHtml(page, limits);
  const nlohmann::json data = pageData(html);
  EXPECT_LE(data["original"]["triangles"].get<size_t>(), 2'000u);
  EXPECT_EQ(data["original"]["source_triangles"], big.numTriangles());
  EXPECT_EQ(data["proxy"]["triangles"], 12);  // the proxy is never reduced
  EXPECT_NE(html.find("decimated by vertex clustering"), std::string::npos);
  EXPECT_EQ(data["layers"][0]["drawn"], 3);
  EXPECT_EQ(decodeArray<float>(data["layers"][0]["positions"]).size(), 3u * 6);
  EXPECT_NE(html.find("3 of the 7 counted are drawn"), std::string::npos);
}

TEST(View3dHtml, RefusesEmptyMeshesAndBadLayers) {
  const Pair pair;
  View3dPage page = examplePage(pair);
  TriMesh empty;
  empty.source = "empty.off";
  page.proxy = &empty;
  EXPECT_THROW(view3dHtml(page), Error);
  page = examplePage(pair);
  page.layers[0].color = "red\" onclick=\"x";
  EXPECT_THROW(view3dHtml(page), std::invalid_argument);
  page = examplePage(pair);
  page.layers[0].id = "proxy";
  EXPECT_THROW(view3dHtml(page), std::invalid_argument);
}

}  // namespace
}  // namespace proxyvis
