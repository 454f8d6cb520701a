// `pkmws grid` and `pkmws compare` as scripts use them (docs/format.md (command line)): JSON keys,
// certified bounds around the exact area, CSV output, bad input -> exit 2.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace fs = std::filesystem;

namespace {

using CliRun = pkmws::test::CliResult;
using pkmws::test::slurp;

fs::path scratch() {
  const fs::path dir = pkmws::test::scratch_dir("grid-cli");
  fs::create_directories(dir);
  return dir;
}

CliRun run(const std::string& args) { return pkmws::test::run_cli(args, scratch()); }

using pkmws::test::dataset;

double exact_area(const std::string& stem) {
  const CliRun r = run("area " + dataset(stem) + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out)["area"].get<double>();
}

}  // namespace

TEST(GridCli, CartesianJsonHasTheContractKeysAndCertifiedBounds) {
  const double exact = exact_area("moma_m1_g0_l250");
  const CliRun r = run("grid " + dataset("moma_m1_g0_l250") + " --cells 500 --json --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"area", "area_lower", "area_upper", "method", "cells", "points_per_second", "time_ms"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["method"], "grid");
  EXPECT_EQ(j["sampler"], "cartesian");
  EXPECT_EQ(j["cells"], 250000);
  EXPECT_EQ(j["threads"], 1);
  EXPECT_LE(j["area_lower"].get<double>(), exact);
  EXPECT_GE(j["area_upper"].get<double>(), exact);
  EXPECT_LT(std::abs(j["area"].get<double>() - exact) / exact, 1e-3);
  EXPECT_GT(j["points_per_second"].get<double>(), 0.0);
}

TEST(GridCli, PolarAdaptiveAndSweep) {
  const double exact = exact_area("moma_m5_gp5_gm5_l195");
  for (const std::string mode : {"--polar", "--adaptive 8", "--sweep"}) {
    const CliRun r = run("grid " + dataset("moma_m5_gp5_gm5_l195") + " --cells 64 --json " + mode);
    ASSERT_EQ(r.status, 0) << mode << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_LT(std::abs(j["area"].get<double>() - exact) / exact, 0.05) << mode;
    if (mode == "--sweep") {
      EXPECT_FALSE(j.contains("area_lower"));  // the raster bracket is not a guarantee
      EXPECT_TRUE(j.contains("area_lower_if_resolved"));
    } else {
      EXPECT_LE(j["area_lower"].get<double>(), exact) << mode;
      EXPECT_GE(j["area_upper"].get<double>(), exact) << mode;
    }
  }
}

TEST(GridCli, GenericMechanismHasNoCertifiedBounds) {
  const CliRun r = run("grid " + dataset("five_bar_dextar_pp") + " --cells 100 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("area_lower"));
  EXPECT_EQ(j["kernel"], "generic");
  EXPECT_NE(j["bounds"].get<std::string>().find("no certified"), std::string::npos);
}

TEST(GridCli, BadInputIsOneLineAndExitTwo) {
  for (const std::string& args :
       {"grid " + dataset("moma_m1_g0_l250"),                                   // --cells missing
        "grid " + dataset("moma_m1_g0_l250") + " --cells 0",                    // out of range
        "grid " + dataset("moma_m1_g0_l250") + " --cells 10 --polar --sweep",   // two samplers
        "grid " + dataset("moma_m1_g0_l250") + " --cells 10 --isa sse9",        // unknown isa
        std::string("grid /nonexistent.json --cells 10"),                                     // missing file
        std::string("compare /nonexistent.json")}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

TEST(GridCli, ComparePrintsTheLadderAndWritesCsv) {
  const fs::path csv = scratch() / "ladder.csv";
  const CliRun r = run("compare " + dataset("moma_m1_g0_l250") + " --ladder 100 200 400 --depths 2 4 6 --csv " +
                    csv.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("exact area 36202.1833253"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cartesian  400^2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("adaptive   depth 6"), std::string::npos) << r.out;
  const std::string text = slurp(csv);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 1 + 3 + 3);  // header, exact, 3 + 3 rows
  EXPECT_EQ(text.rfind("method,cells_per_side,depth,points,area,rel_error", 0), 0u);
  const CliRun j = run("compare " + dataset("moma_m1_g0_l250") + " --ladder 100 --depths 2 --json");
  ASSERT_EQ(j.status, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["rows"].size(), 3u);
  EXPECT_GT(doc["exact_time_ms"].get<double>(), 0.0);
  fs::remove_all(scratch());
}
