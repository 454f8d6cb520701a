// Runs the pkmws program as scripts do (docs/format.md (command line)) and captures its exit status,
// standard output and standard error. Shared by the command-line tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/fixtures.hpp"

namespace pkmws::test {

struct CliResult {
  int status = -1;
  std::string out, err;
};

/// `pkmws ARGS`, its output captured through files in `dir` (created, and the
/// capture files removed afterwards).
inline CliResult run_cli(const std::string& args, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = std::string(PKMWS_CLI) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// A scratch directory unique to this process and `tag`.
inline std::filesystem::path scratch_dir(const std::string& tag) {
  return std::filesystem::temp_directory_path() / ("pkmws-" + tag + "-" + std::to_string(::getpid()));
}

}  // namespace pkmws::test
