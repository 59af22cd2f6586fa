#pragma once
// The one scratch folder of the GoogleTest suites: a fresh empty directory under the system temp
// dir, removed by the destructor. Its name carries the process id because ctest runs every test
// as its own process, possibly two of the same suite at once (-j).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace proxyvis::test {

// A fresh empty folder <temp>/proxyvis_tests/<name>, left in place after the test.
inline std::filesystem::path freshDir(const std::string& name) {
  std::filesystem::path d = std::filesystem::temp_directory_path() / "proxyvis_tests" / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

class ScratchDir {
 public:
  // Named after the running test: one folder per test.
  ScratchDir() : ScratchDir(currentTestName()) {}
  // Named `name`, for tests that need more than one folder.
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("proxyvis_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }
  // Writes `text` to <dir>/<name> (creating sub-folders) and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }

 private:
  static std::string currentTestName() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    if (info == nullptr) return "test";
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      if (c == '/') c = '_';  // parameterized suites: "Data/Suite"
    return name;
  }

  std::filesystem::path path_;
};

}  // namespace proxyvis::test
