// Instance lists: the three line forms, comments, and errors that name file:line.
#include <gtest/gtest.h>

#include "scene/scene_desc.h"
#include "tests/support/scratch_dir.h"
#include "util/error.h"

namespace proxyvis {
namespace {

std::vector<SceneMeshDesc> twoMeshes() {
  std::vector<SceneMeshDesc> m(2);
  m[0].name = "GRASS1";
  m[1].name = "BUSH11";
  return m;
}

std::string errorOf(const test::ScratchDir& dir, const std::string& text) {
  const auto p = dir.write("list.txt", text);
  try {
    loadInstanceList(p, twoMeshes());
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for: " << text;
  return {};
}

TEST(InstanceList, ParsesTranslationsAndMatrices) {
  test::ScratchDir dir;
  const auto p = dir.write("list.txt",
                           "# header\n"
                           "GRASS1 1 2 3\n"
                           "   \n"
                           "BUSH11 0 -1 0 10  1 0 0 20  0 0 1 30 # rotated about z\n"
                           "BUSH11 2 0 0 1  0 2 0 2  0 0 2 3  0 0 0 1\n");
  const auto list = loadInstanceList(p, twoMeshes());
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].mesh, 0u);
  EXPECT_EQ(list[0].transform.apply({0, 0, 0}), Vec3f(1, 2, 3));
  EXPECT_EQ(list[1].mesh, 1u);
  EXPECT_EQ(list[1].transform.apply({1, 0, 0}), Vec3f(10, 21, 30));
  EXPECT_EQ(list[2].transform.apply({1, 1, 1}), Vec3f(3, 4, 5));
}

TEST(InstanceList, BadLinesNameFileAndLine) {
  test::ScratchDir dir;
  EXPECT_NE(errorOf(dir, "GRASS1 1 2 3\nTREE 1 2 3\n").find("list.txt:2: unknown mesh 'TREE'"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "GRASS1 1 2\n").find("list.txt:1: expected 3"), std::string::npos);
  EXPECT_NE(errorOf(dir, "# c\nGRASS1 1 2 x\n").find("list.txt:2: bad number 'x'"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "GRASS1 1 2 nan\n").find("bad number"), std::string::npos);
  EXPECT_NE(errorOf(dir, "GRASS1 0 0 0 0 0 0 0 0 0 0 0 0\n").find("singular"), std::string::npos);
  EXPECT_NE(errorOf(dir, "GRASS1 1 0 0 0 0 1 0 0 0 0 1 0 0 0 2 1\n").find("last matrix row"),
            std::string::npos);
  EXPECT_THROW(loadInstanceList(dir.path() / "missing.txt", twoMeshes()), Error);
}

TEST(InstanceList, TransformsOutOfRangeAreRefused) {
  test::ScratchDir dir;
  EXPECT_NE(errorOf(dir, "GRASS1 1 2 3\nGRASS1 4e6 0 0\n")
                .find("list.txt:2: translation coordinate 4e+06 out of range"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "BUSH11 1e7 0 0 0  0 1 0 0  0 0 1 0\n")
                .find("list.txt:1: transform scales by 1e+07, more than 1e+06"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "BUSH11 1e-7 0 0 0  0 1 0 0  0 0 1 0\n")
                .find("list.txt:1: transform scales down by 1e+07"),
            std::string::npos);
}

TEST(InstanceList, QuotedTokensArePrintableAndShort) {
  test::ScratchDir dir;
  const std::string name = errorOf(dir, "TR\x1b[2JEE 1 2 3\n");
  EXPECT_NE(name.find("list.txt:1: unknown mesh 'TR\\x1b[2JEE'"), std::string::npos) << name;
  const std::string number = errorOf(dir, "GRASS1 1 2 " + std::string(100000, '7') + "x\n");
  EXPECT_NE(number.find("bad number '" + std::string(60, '7') + "...'"), std::string::npos);
  EXPECT_LT(number.size(), 300u);
}

}  // namespace
}  // namespace proxyvis
