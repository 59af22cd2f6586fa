// Where outputs go and what they may replace: symbolic links written through, devices and FIFOs
// written in place, outputs that are inputs refused, temporaries removed on signals and when
// stale, related outputs committed as a unit.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <string>
#include <thread>

#include "tests/support/scratch_dir.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/sha256.h"
#include "util/staged_folder.h"
#include "util/temp_files.h"

namespace proxyvis {
namespace {
namespace fs = std::filesystem;

using test::freshDir;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

size_t entries(const fs::path& d) {
  return size_t(std::distance(fs::directory_iterator(d), fs::directory_iterator()));
}

// A pid that certainly belonged to a process that has ended: a child that exited at once.
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

TEST(OutputTarget, SymlinkIsWrittenThroughAndStaysALink) {
  const fs::path d = freshDir("out_symlink");
  std::ofstream(d / "real.txt") << "old";
  fs::create_symlink("real.txt", d / "link.txt");
  writeTextAtomically(d / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(d / "link.txt")));
  EXPECT_EQ(slurp(d / "real.txt"), "new");
  EXPECT_EQ(entries(d), 2u);
}

TEST(OutputTarget, DanglingSymlinkCreatesItsTarget) {
  const fs::path d = freshDir("out_dangling");
  fs::create_directories(d / "sub");
  fs::create_symlink("sub/missing.txt", d / "link.txt");
  writeTextAtomically(d / "link.txt", "made");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(d / "link.txt")));
  EXPECT_EQ(slurp(d / "sub" / "missing.txt"), "made");
}

TEST(OutputTarget, FifoIsWrittenInPlace) {
  const fs::path d = freshDir("out_fifo");
  const fs::path fifo = d / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::future<std::string> reader = std::async(std::launch::async, [&] { return slurp(fifo); });
  writeTextAtomically(fifo, "through the pipe");
  EXPECT_EQ(reader.get(), "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(entries(d), 1u);
}

TEST(OutputTarget, DevNullStaysADevice) {
  writeTextAtomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file(fs::symlink_status("/dev/null")));
}

TEST(OutputTarget, DevFullIsAWriteErrorWithTheSystemsReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    writeTextAtomically("/dev/full", "does not fit");
    FAIL() << "expected WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.exitCode(), kExitCannotWrite);
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_character_file(fs::symlink_status("/dev/full")));
}

TEST(OutputTarget, StandardStreamsAreDescriptors) {
  for (const char* p : {"-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"}) {
    const OutputTarget t = resolveOutputTarget(p);
    EXPECT_EQ(t.kind, OutputTarget::Kind::kStream) << p;
    EXPECT_EQ(t.fd, 1) << p;
  }
  EXPECT_EQ(resolveOutputTarget("/dev/stderr").fd, 2);
}

TEST(OutputTarget, FolderIsAWriteError) {
  const fs::path d = freshDir("out_folder_target");
  fs::create_directories(d / "a_folder");
  EXPECT_THROW(writeTextAtomically(d / "a_folder", "x"), WriteError);
  EXPECT_TRUE(fs::is_directory(d / "a_folder"));
}

TEST(OutputTarget, MissingParentsAreCreatedOnlyWhenAsked) {
  const fs::path d = freshDir("out_parents");
  EXPECT_THROW(writeTextAtomically(d / "new" / "deeper" / "c.txt", "x"), WriteError);
  EXPECT_TRUE(fs::is_empty(d));
  OutputSet set(MissingFolders::kCreate);
  set.addText(d / "new" / "deeper" / "c.txt", "x");
  set.commit();
  EXPECT_EQ(slurp(d / "new" / "deeper" / "c.txt"), "x");
}

TEST(OutputTarget, ParentThatIsAFileIsAWriteError) {
  const fs::path d = freshDir("out_parent_file");
  std::ofstream(d / "a_file") << "x";
  try {
    writeTextAtomically(d / "a_file" / "c.txt", "x");
    FAIL() << "expected WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.exitCode(), kExitCannotWrite);
    EXPECT_EQ(std::string(e.what()).find("Success"), std::string::npos) << e.what();
  }
}

TEST(CheckOutputs, OutputThatIsAnInputIsRefusedUnderAnySpelling) {
  const fs::path d = freshDir("check_same");
  std::ofstream(d / "in.ply") << "ply";
  fs::create_symlink("in.ply", d / "link.ply");
  fs::create_hard_link(d / "in.ply", d / "hard.ply");
  const std::string in = (d / "in.ply").string();
  for (const fs::path& out : {d / "in.ply", d / "link.ply", d / "hard.ply", d / "." / "in.ply",
                              d / ".." / d.filename() / "in.ply"}) {
    try {
      checkOutputs({in}, {{"-o", out.string()}});
      ADD_FAILURE() << out << " was accepted";
    } catch (const WriteError& e) {
      ADD_FAILURE() << out << ": a WriteError, expected a usage Error: " << e.what();
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), kExitBadInput);
      EXPECT_NE(std::string(e.what()).find("-o names the input"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(slurp(d / "in.ply"), "ply");
  EXPECT_NO_THROW(checkOutputs({in}, {{"-o", (d / "out.ply").string()}, {"--json", "-"}}));
}

TEST(CheckOutputs, TwoOutputsNamingOneFileAreRefused) {
  const fs::path d = freshDir("check_twice");
  const std::string out = (d / "x.json").string();
  EXPECT_THROW(checkOutputs({}, {{"--json", out}, {"--dump-errors", out}}), Error);
  EXPECT_THROW(checkOutputs({}, {{"--json", "-"}, {"--dump-errors", "/dev/stdout"}}), Error);
}

TEST(CheckOutputs, FolderOutputMayNotContainAnInput) {
  const fs::path d = freshDir("check_folder");
  fs::create_directories(d / "scenes");
  std::ofstream(d / "scenes" / "s.json") << "{}";
  EXPECT_THROW(checkOutputs({(d / "scenes" / "s.json").string()},
                            {{"--out", (d / "scenes").string(), true}}),
               Error);
  EXPECT_NO_THROW(checkOutputs({(d / "scenes" / "s.json").string()},
                               {{"--out", (d / "report").string(), true}}));
}

TEST(CheckOutputs, UnwritableFolderIsAWriteErrorAndNothingIsCreated) {
  const fs::path d = freshDir("check_unwritable");
  std::ofstream(d / "a_file") << "x";
  EXPECT_THROW(checkOutputs({}, {{"--json", (d / "a_file" / "sub" / "o.json").string()}}),
               WriteError);
  EXPECT_NO_THROW(checkOutputs({}, {{"--json", (d / "missing" / "sub" / "o.json").string()}}));
  EXPECT_FALSE(fs::exists(d / "missing"));  // created when written, not when checked
  if (::geteuid() != 0) {
    fs::create_directories(d / "read_only");
    fs::permissions(d / "read_only", fs::perms::owner_read | fs::perms::owner_exec);
    try {
      checkOutputs({}, {{"--json", (d / "read_only" / "o.json").string()}});
      ADD_FAILURE() << "a read-only folder was accepted";
    } catch (const WriteError& e) {
      EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos) << e.what();
    }
    fs::permissions(d / "read_only", fs::perms::owner_all);
  }
  EXPECT_EQ(entries(d), 1u);
}

TEST(TemporaryFiles, OwnerIsReadFromTheName) {
  EXPECT_EQ(temporaryOwner(".report.tmp123_4.json"), pid_t(123));
  EXPECT_EQ(temporaryOwner(".reference-ab.tmp5_0.exr.exr"), pid_t(5));
  EXPECT_EQ(temporaryOwner(".out.tmp77_1"), pid_t(77));
  EXPECT_EQ(temporaryOwner("report.json"), std::nullopt);
  EXPECT_EQ(temporaryOwner("a.tmp12_3.json"), std::nullopt);  // not hidden: not ours
  EXPECT_EQ(temporaryOwner(".a.tmp12_x"), std::nullopt);
  EXPECT_EQ(temporaryOwner(".a.tmp_3.json"), std::nullopt);
  const fs::path t = temporaryPathFor("/x/y/proxy.ply");
  EXPECT_EQ(t.parent_path(), fs::path("/x/y"));
  EXPECT_EQ(t.extension(), ".ply");
  EXPECT_EQ(temporaryOwner(t.filename().string()), ::getpid());
}

TEST(TemporaryFiles, StaleOnesAreRemovedByTheNextWrite) {
  const fs::path d = freshDir("stale");
  const std::string dead = std::to_string(deadPid());
  const std::string alive = std::to_string(::getpid());
  std::ofstream(d / (".report.tmp" + dead + "_0.json")) << "stale";
  fs::create_directories(d / (".out.tmp" + dead + "_3"));
  std::ofstream(d / (".out.tmp" + dead + "_3") / "roulette_4.png") << "stale";
  std::ofstream(d / (".live.tmp" + alive + "_999.json")) << "being written";
  std::ofstream(d / ".notes.tmp") << "the user's";
  writeTextAtomically(d / "report.json", "{}");
  EXPECT_FALSE(fs::exists(d / (".report.tmp" + dead + "_0.json")));
  EXPECT_FALSE(fs::exists(d / (".out.tmp" + dead + "_3")));
  EXPECT_TRUE(fs::exists(d / (".live.tmp" + alive + "_999.json")));
  EXPECT_TRUE(fs::exists(d / ".notes.tmp"));
  EXPECT_EQ(slurp(d / "report.json"), "{}");
  EXPECT_EQ(entries(d), 3u);
}

TEST(TemporaryFiles, LiveOnesAreRemovedByTheHandler) {
  const fs::path d = freshDir("live");
  std::ofstream(d / ".a.tmp1_0.json") << "x";
  fs::create_directories(d / ".f.tmp1_1");
  std::ofstream(d / ".f.tmp1_1" / "img.png") << "x";
  std::ofstream(d / "kept.json") << "x";
  LiveTemporary file(d / ".a.tmp1_0.json", false), folder(d / ".f.tmp1_1", true),
      released(d / "kept.json", false);
  released.release();
  removeLiveTemporariesForTesting();
  EXPECT_FALSE(fs::exists(d / ".a.tmp1_0.json"));
  EXPECT_FALSE(fs::exists(d / ".f.tmp1_1"));
  EXPECT_FALSE(fs::exists(d / ".f.tmp1_1.gone"));
  EXPECT_TRUE(fs::exists(d / "kept.json"));
}

// The handler runs while the other threads go on: a writer that keeps creating files in the folder
// must not make its removal fail.
TEST(TemporaryFiles, FolderIsRemovedWhileAnotherThreadWritesIntoIt) {
  const fs::path d = freshDir("busy");
  const fs::path folder = d / ".b.tmp1_0";
  fs::create_directories(folder);
  LiveTemporary live(folder, true);
  std::atomic<bool> stop{false};
  std::atomic<int> written{0};
  std::thread writer([&] {
    for (int i = 0; !stop.load(); ++i) {
      std::ofstream(folder / (std::to_string(i % 64) + ".png")) << "x";
      written.fetch_add(1);
    }
  });
  while (written.load() < 200) std::this_thread::yield();
  removeLiveTemporariesForTesting();
  const bool folder_left = fs::exists(folder), moved_left = fs::exists(d / ".b.tmp1_0.gone");
  stop = true;
  writer.join();
  live.release();
  EXPECT_FALSE(folder_left);
  EXPECT_FALSE(moved_left);
}

// timeout(1) signals the process and then its whole group: a second SIGTERM right after the first,
// delivered to another thread. It must not end the process before the first one's removal is done.
TEST(TemporaryFiles, SecondSignalWaitsForTheRemoval) {
  // Many files make the removal long enough to be caught in it; tmpfs creates them quickly.
  const fs::path shm = "/dev/shm";
  const fs::path d = fs::is_directory(shm)
                         ? shm / ("proxyvis_double_signal_" + std::to_string(::getpid()))
                         : freshDir("double_signal");
  fs::remove_all(d);
  fs::create_directories(d);
  const fs::path folder = d / ".big.tmp1_0";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(ready[0]);
    removeTemporariesOnTerminatingSignals();
    fs::create_directories(folder);
    for (int i = 0; i < 20000; ++i) std::ofstream(folder / (std::to_string(i) + ".f"));
    LiveTemporary live(folder, true);
    std::thread other([] { ::pause(); });  // a thread that takes the second signal
    ::write(ready[1], "x", 1);
    other.join();
    ::_exit(0);  // not reached
  }
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  // The second one while the first one's handler removes the 20,000 files.
  ::kill(child, SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(child, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(entries(d), 0u);
  fs::remove_all(d);
}

TEST(TemporaryFiles, TerminatingSignalRemovesThemAndStillKills) {
  const fs::path d = freshDir("signal");
  const pid_t child = ::fork();
  if (child == 0) {
    removeTemporariesOnTerminatingSignals();
    try {
      writeAtomically(d / "out.json", [](const fs::path& tmp) {
        std::ofstream(tmp) << "partial";
        ::raise(SIGTERM);
      });
    } catch (...) {
    }
    ::_exit(0);  // not reached: SIGTERM ends the process
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(entries(d), 0u);
}

TEST(OutputSet, CommitsInOrderAndRecordsHashes) {
  const fs::path d = freshDir("set_ok");
  OutputSet set;
  set.addText(d / "proxy.ply", "mesh bytes");
  EXPECT_FALSE(fs::exists(d / "proxy.ply"));  // staged, not yet in place
  EXPECT_EQ(set.sha256Of(d / "proxy.ply"), sha256Hex("mesh bytes"));
  set.addText(d / "report.json", "{}");
  set.commit();
  EXPECT_EQ(slurp(d / "proxy.ply"), "mesh bytes");
  EXPECT_EQ(slurp(d / "report.json"), "{}");
  EXPECT_EQ(entries(d), 2u);
}

TEST(OutputSet, UncommittedLeavesNothing) {
  const fs::path d = freshDir("set_abandoned");
  std::ofstream(d / "report.json") << "previous";
  {
    OutputSet set;
    set.addText(d / "proxy.ply", "mesh bytes");
    set.addText(d / "report.json", "new");
  }
  EXPECT_EQ(slurp(d / "report.json"), "previous");
  EXPECT_EQ(entries(d), 1u);
}

TEST(OutputSet, WriterErrorsNameTheOutputNotTheTemporary) {
  const fs::path d = freshDir("set_error_name");
  OutputSet set;
  try {
    set.add(d / "proxy.ply", [](const fs::path& tmp) {
      throw WriteError(tmp.string(), "cannot write output", "cannot create '" + tmp.string() + "'");
    });
    FAIL() << "expected WriteError";
  } catch (const WriteError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find(".tmp"), std::string::npos) << what;
    EXPECT_EQ(what.rfind((d / "proxy.ply").string() + ": cannot write output", 0), 0u) << what;
  }
  EXPECT_TRUE(fs::is_empty(d));
}

TEST(StagedFolder, ReplacesThePreviousReportAsAWhole) {
  const fs::path d = freshDir("staged_replace");
  for (const char* run : {"first", "second"}) {
    StagedFolder folder(d / "report", "test-program");
    EXPECT_NE(folder.path(), d / "report");
    std::ofstream(folder.path() / (std::string(run) + ".txt")) << run;
    folder.commit();
  }
  EXPECT_TRUE(fs::exists(d / "report" / "second.txt"));
  EXPECT_FALSE(fs::exists(d / "report" / "first.txt"));
  const std::string manifest = slurp(d / "report" / StagedFolder::kManifestName);
  EXPECT_NE(manifest.find(sha256Hex("second")), std::string::npos) << manifest;
  EXPECT_EQ(entries(d), 1u);
}

TEST(StagedFolder, UncommittedLeavesThePreviousIntact) {
  const fs::path d = freshDir("staged_abandon");
  {
    StagedFolder folder(d / "report", "test-program");
    std::ofstream(folder.path() / "kept.txt") << "kept";
    folder.commit();
  }
  {
    StagedFolder folder(d / "report", "test-program");
    std::ofstream(folder.path() / "lost.txt") << "lost";
  }
  EXPECT_TRUE(fs::exists(d / "report" / "kept.txt"));
  EXPECT_FALSE(fs::exists(d / "report" / "lost.txt"));
  EXPECT_EQ(entries(d), 1u);
}

TEST(StagedFolder, RefusesAFolderOfOtherFiles) {
  const fs::path d = freshDir("staged_foreign");
  std::ofstream(d / "thesis.tex") << "years of work";
  EXPECT_THROW(StagedFolder(d, "test-program"), Error);
  EXPECT_EQ(slurp(d / "thesis.tex"), "years of work");
  EXPECT_EQ(entries(d), 1u);
}

TEST(ErrorText, NonPrintableBytesAreEscaped) {
  const Error e(std::string("bad\x01name\xff.ply"), "unexpected \x7f byte", "line\nbreak");
  const std::string what = e.what();
  for (const unsigned char c : what) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << int(c);
  EXPECT_NE(what.find("bad\\x01name\\xff.ply"), std::string::npos) << what;
  EXPECT_NE(what.find("line\\x0abreak"), std::string::npos) << what;
}

}  // namespace
}  // namespace proxyvis
