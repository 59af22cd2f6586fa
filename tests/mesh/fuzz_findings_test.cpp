// Inputs the fuzz targets (fuzz/) found, minimized, as regression tests: each must be refused
// with an Error quickly. The bytes are written here, not stored as files.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "mesh/io/mesh_io.h"
#include "util/error.h"

namespace proxyvis {
namespace {

// The message of parsing `bytes` as `name`, which must fail within `seconds`.
std::string refusal(const std::string& bytes, const std::string& name, double seconds = 2) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  try {
    parseMeshBytes(bytes, name);
    ADD_FAILURE() << name << " loaded";
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
            seconds);
  return message;
}

// Reproducers too long to spell as escapes, written as hex.
std::string fromHex(const std::string& hex) {
  std::string bytes;
  for (size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes += char(std::stoi(hex.substr(i, 2), nullptr, 16));
  return bytes;
}

// fuzz_off: a first word of binary bytes that only ended in "4OFF" passed the header check (the
// 4D variant was left to OpenMesh), and OpenMesh then read 84 million empty faces from these 262
// bytes (a second of CPU, and more for a larger count).
TEST(FuzzFindings, OffKeywordAfterBinaryBytesIsRefused) {
  const std::string bytes =
      std::string("\000\000\000\000\266\077\006\000\260`", 10) + std::string(32, '\000') +
      std::string("4OFF", 4) + std::string(8, '\000') + std::string("OFF\n", 4) +
      std::string(10, '\000') +
      std::string("\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 1 2 3\n4 0 1 \n3 2 3 4\n\000OFF\n", 53) +
      std::string(51, '\000') + std::string(60, '\005') + std::string("0 1 \n3 2 3 4\n", 13) +
      std::string(7, '\000') + std::string("4\n", 2) + std::string(8, '\000');
  ASSERT_EQ(bytes.size(), 262u);
  EXPECT_NE(refusal(bytes, "finding.off").find("finding.off: not an OFF file"), std::string::npos);
}

TEST(FuzzFindings, OffKeywordsAreExact) {
  const std::string body = "\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(parseMeshBytes("OFF" + body, "ok.off").triangles.size(), 1u);
  EXPECT_NE(refusal("xOFF" + body, "x.off").find("not an OFF file"), std::string::npos);
  EXPECT_NE(refusal("4OFF" + body, "four.off").find("4D or n-dimensional OFF ('4OFF')"),
            std::string::npos);
  EXPECT_NE(refusal("nOFF 3" + body, "n.off").find("4D or n-dimensional OFF"), std::string::npos);
}

// fuzz_off: OpenMesh reads a face's vertex count as unsigned, so "-34" made it push 4 billion
// vertex handles (a timeout, or 16 GB). Found twice: a "-13" after a 10-vertex face too.
// Two checks guard OFF faces (record lines, then values among the faces); either may refuse
// first, and its message must name the file and quote the bad value.
bool namesFileAndValue(const std::string& message, const std::string& file,
                       const std::string& value) {
  return message.find(file + ": ") != std::string::npos && message.find(value) != std::string::npos;
}

TEST(FuzzFindings, NegativeOffFaceCountIsRefused) {
  const std::string bytes = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n-34\n";
  EXPECT_PRED3(namesFileAndValue, refusal(bytes, "negative.off"), "negative.off", "'-34'");
  const std::string second =
      "OFF\n1 4 0\n0 0 0\n10 1 0\n0 0 1\n3 0 2 1\n3 0 -13\n3 4 3 2\n3 1 2 3\n";
  ASSERT_EQ(second.size(), 61u);
  // Here the record check refuses earlier: "10 1 0" is a face line with too few indices.
  EXPECT_PRED3(namesFileAndValue, refusal(second, "second.off"), "second.off", "10");
  // Third time: a vertex line of 7 values moved where the check thought the faces start, and
  // OpenMesh read the count 2147483648 from "02147483648.5".
  const std::string third =
      "OFF\n5 5 0\n0 0 0\n1 0 0\n1 1 0 0.5 1 0 0\n1 1 0\n0 1 0\n02147483648.5 0.5 1\n"
      "4 0 1 2 3\n1\n40.51 2 31\n4 0 1 2 3\n";
  EXPECT_PRED3(namesFileAndValue, refusal(third, "third.off"), "third.off", "'02147483648.5'");
  // Values larger than any index, colour or count that fits in what follows are refused too;
  // colours after a face are fine.
  EXPECT_PRED3(namesFileAndValue,
               refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n900000 0 1 2\n", "big.off"), "big.off",
               "900000");
  EXPECT_EQ(parseMeshBytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n", "c.off")
                .triangles.size(),
            1u);
}

// fuzz_off: counts on the keyword's line passed the header check, but OpenMesh reads them from
// the next line: here 12147483648, which it clamped and then added vertices for minutes.
TEST(FuzzFindings, OffCountsOnTheKeywordLineAreRefused) {
  const std::string bytes =
      "OFF 0  0 0\n12147483648\n0 0 1\n3 0  3\n3 0  0\n0\n0 1 0\n0  0\n0  4\n";
  ASSERT_EQ(bytes.size(), 61u);
  EXPECT_NE(refusal(bytes, "counts.off").find("counts.off: text after the OFF keyword on its line"),
            std::string::npos);
  // The same count on its own line is checked.
  EXPECT_NE(refusal("OFF\n12147483648 0 0\n0 0 1\n", "big.off").find("12147483648"),
            std::string::npos);
  EXPECT_EQ(parseMeshBytes("OFF # comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "c.off")
                .triangles.size(),
            1u);
}

// fuzz_draco: a POSITION attribute of data type BOOL made Draco's converter load bytes like 63 as
// bool (undefined behaviour; UBSan stops there).
TEST(FuzzFindings, DracoBoolPositionsAreRefused) {
  const std::string bytes =
      std::string(
          "DRACO\002\002\001\001\000\000\000\004\002\000\002\000\000\001\037\377\001\021\001\377"
          "\000\000\001\000\013\003\002\000\000\000\000\377\377\377\200\077",
          41) +
      std::string(9, '\000') +
      std::string(
          "\001\001\000\000\021\001\377\002\001\001\240\240\240\240\240#\356u\000\001\000\000\000",
          23) +
      std::string(31, '\240') +
      std::string(
          "\002\000\214\005\206\000\260`"
          "\000\000\000\000\377\377\377\200\000\000\000\000\000\077\000\000",
          24) +
      std::string(8, '\124') + std::string("\000\000", 2);
  ASSERT_EQ(bytes.size(), 138u);
  EXPECT_NE(refusal(bytes, "bool.drc").find("bool.drc: Draco POSITION attribute has data type 11"),
            std::string::npos);
}

// fuzz_off: BINARY anywhere on the keyword line (here in a comment) makes OpenMesh read binary
// counts that no header check bounds; a 100-byte file allocated for seconds.
TEST(FuzzFindings, BinaryOffIsRefused) {
  std::string bytes = "OFF\t# made by hand BINARY\n";
  bytes += std::string("\x7f\xff\xff\xff\x7f\xff\xff\xff\0\0\0\0", 12);
  EXPECT_PRED3(namesFileAndValue, refusal(bytes, "binary.off"), "binary.off",
               "binary OFF is not supported");
  EXPECT_PRED3(namesFileAndValue, refusal("OFF BINARY\n3 1 0\n", "plain.off"), "plain.off",
               "binary OFF is not supported");
}

// fuzz_draco: a 305-byte file of bitstream 1.0 whose edgebreaker header declares 471,604,252
// faces made Draco allocate 5.6 GB before reading any (libFuzzer out-of-memory). The declared
// count is read for 1.x files too and refused when the file cannot hold it.
TEST(FuzzFindings, DracoHeaderDeclaringMoreFacesThanBytesIsRefused) {
  const std::string bytes = fromHex(
      "445241434f010001010b0000ffff5f1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c0100000000000000"
      "1c1c"
      "1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c01001c1c1c1c1c1c1c1c1c1c1c1c"
      "1cc0"
      "000c2c2a000007631e00b0600000da434f0202010100000000000000000000000000000000000000000000000000"
      "0000"
      "00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
      "0000"
      "000000000000000008f4ffffff010006000003efda01ff2111000003efda01ff211101ff090004aa1c1c1c1c1c1c"
      "1c1c"
      "1c1c1c1c1c1c1c1c1c1c1c1c1c1c661c1c1c1c1c0500000000ffd2008059202dc95d5d5d5d5d5d5d5d5d5d5d5d5d"
      "5d5d"
      "5d5d5d5d5d5d5d5dbf0b000000003a400b");
  ASSERT_EQ(bytes.size(), 305u);
  EXPECT_NE(
      refusal(bytes, "oom.drc").find("oom.drc: Draco header declares 471604252 faces in 305 bytes"),
      std::string::npos);
}

// fuzz_draco, the next minute: the same in bitstream 1.2 with the metadata flag set, which
// Draco ignores before 1.3 (so must the header read).
TEST(FuzzFindings, DracoOldBitstreamIgnoresTheMetadataFlag) {
  const std::string bytes = fromHex(
      "445241434f0102010100ff00040200020000011f1c1c1c1c1c1c1c1c1c1c1c1c1c1c1c591c1c1c1cc0000c2c9100"
      "0007300800000000ff0700000000803f00000000000080bf000000400b");
  ASSERT_EQ(bytes.size(), 75u);
  EXPECT_NE(refusal(bytes, "flag.drc").find("declares 471604252 faces in 75 bytes"),
            std::string::npos);
}

// fuzz_glb: a sparse accessor whose indices are floats (glTF allows only unsigned integers) read a
// NaN index, and converting it to a size was undefined behaviour (UBSan). Refused as not fitting.
TEST(FuzzFindings, GlbSparseFloatIndicesAreRefused) {
  const std::string bytes = fromHex(
      "676c54460200000014030000980200004a534f4e7b226173736574223a207b2276657273696f6e223a2022322e30"
      "227d2c20227363656e65223a20302c20227363656e6573223a205b7b226e6f646573223a205b305d7d5d2c20226e"
      "6f646573223a205b7b226d657368223a20307d5d2c20226d6573686573223a205b7b226e616d65223a2022746574"
      "7261222c20227072696d697469766573223a205b7b2261747472696275746573223a207b22504f534954494f4e22"
      "3a20307d2c2022696e6469636573223a20312c20226d6f6465223a20347d5d7d5d2c202262756666657273223a20"
      "5b7b22627974654c656e677468223a2039367d5d2c20226275666665725669657773223a205b7b22627566666572"
      "223a20302c2022627974654f6666736574223a20302c2022627974654c656e677468223a2034387d2c207b226275"
      "66666572223a20302c2022627974654f6666736574223a2034382c2022627974654c656e677468223a2034387d2c"
      "207b22627566666572223a20302c2022627974654f6666736574223a20302c2022627974654c656e677468223a20"
      "31327d5d2c20226163636573736f7273223a205b7b2259756666657256696577223a20302c2022636f6d706f6e65"
      "6e7454797065223a20353132322c2022636f756e74223a20342c202274797065223a202256454333222c20227370"
      "61727365223a207b22636f756e74223a20322c2022696e6469636573223a207b2262756666657256696577223a20"
      "312c2022636f6d706f6e656e7454797065223a20353132367d2c202276616c756573223a207b2262756666657256"
      "696577223a20327d7d7d2c207b2262756666657256696577223a20312c2022636f6d706f6e656e7454797065223a"
      "20353132352c2022636f756e74223a2031332c202274797065223a20225343414c4152227d5d7d20600000004249"
      "4e000000000000000000000000000000803f0000000000000000000000000000803f000000000000000000000000"
      "0000803f00fbffff0100000001000000000000000100000003000000000000000300000002000000010000000200"
      "000003000000");
  ASSERT_EQ(bytes.size(), 788u);
  EXPECT_NE(refusal(bytes, "sparse.glb").find("has a sparse part that does not fit"),
            std::string::npos);
}

}  // namespace
}  // namespace proxyvis
