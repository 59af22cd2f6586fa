// plan/unit_file.h: a unit result's header and images read back bit for bit; a truncated or
// altered file is refused.
#include "plan/unit_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "tests/support/scratch_dir.h"
#include "util/error.h"

namespace proxyvis {
namespace {

std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

TEST(UnitFile, HeaderAndImagesReadBackExactly) {
  test::ScratchDir dir;
  UnitFile file;
  file.header = {{"unit", 3}, {"text", "é\n\""}};
  file.images.push_back(Image{3, 2, 3, std::vector<float>(18)});
  file.images.push_back(Image{});  // an image a unit does not keep
  file.images.push_back(Image{1, 1, 1, {-0.0f}});
  for (size_t i = 0; i < 18; ++i) file.images[0].pixels[i] = float(i) * 1.5e-39f;
  const UnitFile written = file;
  writeUnitFile(dir / "u.result", file);
  const UnitFile back = readUnitFile(dir / "u.result");
  EXPECT_EQ(back.header.at("unit"), 3);
  EXPECT_EQ(back.header.at("text"), "é\n\"");
  ASSERT_EQ(back.images.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_TRUE(back.images[i] == written.images[i]) << i;
  EXPECT_TRUE(std::signbit(back.images[2].pixels[0]));
}

TEST(UnitFile, TruncatedOrAlteredFilesAreRefused) {
  test::ScratchDir dir;
  UnitFile file;
  file.header = {{"unit", 0}};
  file.images.push_back(Image{4, 4, 3, std::vector<float>(48, 0.25f)});
  writeUnitFile(dir / "u.result", file);
  const std::string good = fileBytes(dir / "u.result");
  std::string altered = good;
  altered[good.size() / 2] ^= 1;
  writeBytes(dir / "altered.result", altered);
  EXPECT_THROW(readUnitFile(dir / "altered.result"), Error);
  writeBytes(dir / "short.result", good.substr(0, good.size() - 9));
  EXPECT_THROW(readUnitFile(dir / "short.result"), Error);
  writeBytes(dir / "other.result", "PVUNIT2\n" + good.substr(8));
  EXPECT_THROW(readUnitFile(dir / "other.result"), Error);
}

}  // namespace
}  // namespace proxyvis
