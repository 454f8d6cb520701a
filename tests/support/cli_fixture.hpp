// The fixture of the command-line tests: a scratch directory per test, `pkmws
// ARGS` run in it, files written into it, the bad-input contract.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"
#include "support/fixtures.hpp"

namespace pkmws::test {

class Cli : public ::testing::Test {
 protected:
  using Result = CliResult;

  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("pkmws-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Result run(const std::string& args) { return run_cli(args, dir_); }

  std::filesystem::path write(const std::string& name, const std::string& content) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p) << content;
    return p;
  }

  static std::string dataset(const std::string& name) {
    return (datasets_dir() / name).string();
  }

  // One line on stderr, exit 2, nothing on stdout.
  void expect_bad_input(const Result& r, const std::string& needle) {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }

  std::filesystem::path dir_;
};

}  // namespace pkmws::test
