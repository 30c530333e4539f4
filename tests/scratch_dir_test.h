#pragma once
// A GoogleTest fixture with a fresh scratch directory per test (removed afterwards), named after
// the suite, the test and this process, so parallel test processes never share one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace touchdown::testing_scratch {

// The whole of a file, byte for byte.
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("touchdown_" + std::string(test->test_suite_name()) + "_" + std::to_string(::getpid()) + "_" + test->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes `text` to `name` in the scratch directory; returns its path.
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  // The path of `name` in the scratch directory.
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string Slurp(const std::filesystem::path& p) { return testing_scratch::Slurp(p); }

  std::filesystem::path dir_;
};

}  // namespace touchdown::testing_scratch
