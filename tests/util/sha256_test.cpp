#include "util/sha256.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace proxyvis {
namespace {

// Reference digests from FIPS 180-2, appendix B.
TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, FileMatchesBytes) {
  const auto path = std::filesystem::temp_directory_path() / "proxyvis_sha256_test.txt";
  std::ofstream(path, std::ios::binary) << "abc";
  EXPECT_EQ(sha256OfFile(path), sha256Hex("abc"));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace proxyvis
