// pkmws area with criteria (method certified) and pkmws levels (band table,
// figure, bad input): the contract of issue 5.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace fs = std::filesystem;

namespace {

using Result = pkmws::test::CliResult;
using pkmws::test::slurp;

Result run(const std::string& args, const fs::path& dir) { return pkmws::test::run_cli(args, dir); }

std::string dataset(const std::string& name) { return std::string(PKMWS_SOURCE_DIR) + "/datasets/" + name; }

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("pkmws-levels-" + std::to_string(::getpid()) + "-" + name);
  fs::create_directories(d);
  return d;
}

TEST(LevelsCli, AreaWithPressureAngleLimitIsCertified) {
  const fs::path d = temp_dir("area");
  const Result r = run("area " + dataset("five_bar_dextar_pp_alpha40.json") + " --json", d);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "certified");
  const double lo = j["area_lower"], hi = j["area_upper"];
  EXPECT_LE(lo, hi);
  EXPECT_LE(hi - lo, 1e-6 * hi);
  // Inside the cell baseline's bounds, far inside the reachable lens (0.41558 m²).
  EXPECT_GT(lo, 0.2246);
  EXPECT_LT(hi, 0.2247);
  EXPECT_TRUE(j.contains("time_ms"));
  EXPECT_TRUE(j.contains("components"));
  fs::remove_all(d);
}

TEST(LevelsCli, BandTableFigureAndBadInput) {
  const fs::path d = temp_dir("bands");
  const fs::path svg = d / "bands.svg";
  const Result r = run("levels " + dataset("five_bar_dextar_pm.json") +
                           " --criterion pressure_angle --levels 30,60 --tolerance 1e-4 --json --svg " + svg.string(),
                       d);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["bands"].size(), 2u);
  const double a0 = j["bands"][0]["sublevel_area_lower"], a1 = j["bands"][1]["sublevel_area_upper"];
  EXPECT_LT(a0, a1);
  // Band bounds add up to the sub-level bounds of the last level.
  const double sum_lo = j["bands"][0]["area_lower"].get<double>() + j["bands"][1]["area_lower"].get<double>();
  EXPECT_LE(sum_lo, j["bands"][1]["sublevel_area_upper"].get<double>());
  const std::string fig = slurp(svg);
  EXPECT_NE(fig.find("<svg"), std::string::npos);
  EXPECT_NE(fig.find("stroke-dasharray"), std::string::npos);  // singular curves dashed
  // Bad input: one line, exit 2.
  const Result bad = run("levels " + dataset("five_bar_dextar_pm.json") + " --criterion speed --levels 1", d);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("unknown criterion"), std::string::npos) << bad.err;
  const Result bad2 = run("levels " + dataset("five_bar_dextar_pm.json") + " --criterion pressure_angle --levels 60,30", d);
  EXPECT_EQ(bad2.status, 2);
  EXPECT_NE(bad2.err.find("--levels"), std::string::npos) << bad2.err;
  fs::remove_all(d);
}

}  // namespace
