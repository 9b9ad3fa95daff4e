#pragma once
// The command-line tests' fixture: a fresh temporary folder per test and the dymesh command run in it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "process.h"

namespace dymesh::testing {

class CliFixture : public ::testing::Test {
 protected:
  // `prefix` names the folder: <temp>/<prefix><test name>
  explicit CliFixture(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // writes `text` to dir_/name and returns its path
  std::string Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  // runs dymesh with `args`, killed after `seconds`
  ProcessResult Dymesh(const std::vector<std::string>& args, double seconds = 300.0) const {
    std::vector<std::string> argv = {DYMESH_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    return RunProcess(argv, dir_ / "process", seconds);
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace dymesh::testing
