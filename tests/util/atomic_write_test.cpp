#include "util/atomic_write.h"
#include "util/input_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/scratch_dir.h"
#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis {
namespace {
namespace fs = std::filesystem;

using test::freshDir;

TEST(AtomicWrite, WritesAndLeavesNoTemporary) {
  fs::path d = freshDir("atomic_ok");
  writeTextAtomically(d / "a.txt", "hello");
  EXPECT_EQ(readTextFile(d / "a.txt"), "hello");
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
}

TEST(AtomicWrite, FailureLeavesNothing) {
  fs::path d = freshDir("atomic_fail");
  EXPECT_THROW(writeAtomically(d / "b.txt",
                               [](const fs::path& tmp) {
                                 writeTextAtomically(tmp, "partial");
                                 throw Error("b.txt", "simulated failure");
                               }),
               Error);
  EXPECT_TRUE(fs::is_empty(d));
}

TEST(AtomicWrite, MissingDirectoryIsWriteError) {
  fs::path d = freshDir("atomic_missing");
  try {
    writeTextAtomically(d / "missing" / "c.txt", "x");
    FAIL() << "expected WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.exitCode(), kExitCannotWrite);
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
  EXPECT_TRUE(fs::is_empty(d));
}

TEST(AtomicWrite, UnwritableDirectoryIsWriteError) {
  fs::path d = freshDir("atomic_nodir");
  writeTextAtomically(d / "a_file", "x");
  try {
    writeTextAtomically(d / "a_file" / "c.txt", "x");
    FAIL() << "expected WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.exitCode(), kExitCannotWrite);
    EXPECT_NE(std::string(e.what()).find("a_file"), std::string::npos);
  }
}

TEST(ReadTextFile, MissingFileNamesThePath) {
  try {
    readTextFile("/nonexistent/proxyvis.txt");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/proxyvis.txt"), std::string::npos);
    EXPECT_EQ(e.exitCode(), kExitBadInput);
  }
}

}  // namespace
}  // namespace proxyvis
