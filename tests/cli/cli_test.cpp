// The command line as scripts use it (docs/format.md (command line)): JSON keys, exit codes, and
// every kind of bad input giving one line on stderr, exit 2 and no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_fixture.hpp"

namespace fs = std::filesystem;

namespace {

using pkmws::test::Cli;
using Result = pkmws::test::CliResult;
using pkmws::test::slurp;

const char* kGoodMoma = R"({
  "name": "test MOMA", "mechanism": "moma", "units": "mm",
  "legs": [
    {"reference": [-100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1},
    {"reference": [100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1}
  ]
})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}
}  // namespace

TEST_F(Cli, AreaJsonHasTheContractKeys) {
  const Result r = run("area " + dataset("moma_m1_g0_l250.json") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"area", "area_lower", "area_upper", "method", "components", "time_ms"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["method"], "exact");
  EXPECT_LE(j["area_lower"].get<double>(), j["area"].get<double>());
  EXPECT_GE(j["area_upper"].get<double>(), j["area"].get<double>());
  EXPECT_GT(j["area"].get<double>(), 0.0);
}

TEST_F(Cli, IkDkEvalInfoAnswerInJson) {
  const std::string f = write("m.json", kGoodMoma).string();
  const Result ik = run("ik " + f + " 0 -300 --json");
  ASSERT_EQ(ik.status, 0) << ik.err;
  const auto j = nlohmann::json::parse(ik.out);
  ASSERT_FALSE(j["solutions"].empty());
  bool any_valid = false;
  for (const auto& s : j["solutions"]) any_valid = any_valid || s["valid"].get<bool>();
  EXPECT_TRUE(any_valid);
  const Result dk = run("dk " + f + " 100 100 --json");
  ASSERT_EQ(dk.status, 0) << dk.err;
  EXPECT_FALSE(nlohmann::json::parse(dk.out)["solutions"].empty());
  const Result ev = run("eval " + f + " 0 -300 --json");
  ASSERT_EQ(ev.status, 0) << ev.err;
  const auto e = nlohmann::json::parse(ev.out);
  ASSERT_FALSE(e["modes"].empty());
  for (const char* key : {"mode", "reachable", "joints", "jacobian_det", "condition_number", "singular",
                          "pressure_angle_deg", "reactions_N"}) {
    EXPECT_TRUE(e["modes"][0].contains(key)) << key;
  }
  const Result info = run("info " + f + " --json");
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["derived"]["dof"], 2);
}

TEST_F(Cli, ExportWritesEveryFormat) {
  for (const char* format : {"svg", "dxf", "wkt", "geojson", "csv"}) {
    const fs::path out = dir_ / (std::string("ws.") + format);
    const Result r = run("export " + dataset("moma_m1_g0_l250.json") + " --format " + format + " -o " + out.string());
    EXPECT_EQ(r.status, 0) << format << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << format;
    EXPECT_GT(fs::file_size(out), 100u) << format;
  }
}

TEST_F(Cli, BadInputGivesOneLineAndExitTwo) {
  expect_bad_input(run("area " + (dir_ / "missing.json").string()), "no such file");
  expect_bad_input(run("area " + write("bad.json", "{ \"name\": ").string()), "malformed JSON");
  expect_bad_input(run("area " + write("unknown.json", replace(kGoodMoma, "\"units\"", "\"colour\": 1, \"units\"")).string()),
                   "colour: unknown field");
  expect_bad_input(run("area " + write("neg.json", replace(kGoodMoma, "\"rod_length\": 250", "\"rod_length\": -250")).string()),
                   "legs[0].rod_length");
  expect_bad_input(run("area " + write("stroke.json", replace(kGoodMoma, "[0, 200]", "[200, 0]")).string()),
                   "legs[0].stroke");
  // Impossible geometry: guides so far apart that the rods never meet.
  expect_bad_input(run("area " + write("apart.json", replace(kGoodMoma, "[100, 0]", "[5000, 0]")).string()),
                   "empty");
  expect_bad_input(run("area " + write("type.json", replace(kGoodMoma, "\"mm\"", "\"inch\"")).string()), "units");
  expect_bad_input(run("ik " + write("m.json", kGoodMoma).string() + " zero 1"), "X");
  expect_bad_input(run("frobnicate"), "frobnicate");
}

TEST_F(Cli, FailedExportLeavesNoFile) {
  const fs::path out = dir_ / "never.svg";
  expect_bad_input(run("export " + (dir_ / "missing.json").string() + " --format svg -o " + out.string()),
                   "no such file");
  EXPECT_FALSE(fs::exists(out));
  expect_bad_input(run("export " + dataset("moma_m1_g0_l250.json") + " --format png -o " + out.string()),
                   "png");
  EXPECT_FALSE(fs::exists(out));
  const fs::path nodir = dir_ / "no" / "such" / "dir" / "x.svg";
  expect_bad_input(run("export " + dataset("moma_m1_g0_l250.json") + " --format svg -o " + nodir.string()),
                   "cannot write");
  EXPECT_FALSE(fs::exists(nodir));
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

TEST_F(Cli, BatchWritesFiguresAndSummary) {
  const fs::path out = dir_ / "out";
  const Result r = run("batch " + dataset("moma_m1_g0_l250.json") + " " + dataset("moma_m2_l250.json") +
                    " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "moma_m1_g0_l250.svg"));
  EXPECT_TRUE(fs::exists(out / "summary.md"));
  const auto rows = nlohmann::json::parse(slurp(out / "summary.json"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(rows[0]["area"].get<double>(), 0.0);
}

TEST_F(Cli, PlotWritesThePiJointCurvesAndRefusesOtherMechanisms) {
  const Result r = run("plot " + dataset("pi_joint_prototype.json") + " --out " + dir_.string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* stem : {"pi_joint_fig08_length", "pi_joint_fig15_resolution", "pi_joint_fig16_angular_velocity",
                           "pi_joint_fig17_torque"}) {
    const fs::path svg = dir_ / (std::string(stem) + ".svg");
    ASSERT_TRUE(fs::exists(svg)) << stem;
    EXPECT_NE(slurp(svg).find("<path"), std::string::npos) << stem;  // the curves
  }
  expect_bad_input(run("plot " + dataset("moma_m2_l250.json") + " --out " + dir_.string()), "pi_joint");
  expect_bad_input(run("plot " + dataset("pi_joint_prototype.json") + " --out " + (dir_ / "nope").string()),
                   "no such directory");
}

namespace {

// docs/format.md (output vocabulary): one shape for every mechanism.
TEST_F(Cli, OneVocabularyForEveryMechanism) {
  // Joints keyed by name with their units stated once; modes as one sign per leg.
  auto r = run("ik " + dataset("five_bar_dextar_pm.json") + " 0.05 0.2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["units"], "m");
  EXPECT_EQ(j["joint_names"], nlohmann::json::parse(R"(["theta1", "theta2"])"));
  EXPECT_EQ(j["joint_units"], nlohmann::json::parse(R"({"theta1": "deg", "theta2": "deg"})"));
  EXPECT_EQ(j["solutions"][0]["mode"], "+-");
  EXPECT_TRUE(j["solutions"][0]["joints"].contains("theta1"));
  r = run("ik " + dataset("three_rpr_prismatic.json") + " 0 0 0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["solutions"][0]["mode"], "000");
  EXPECT_EQ(j["joint_units"]["rho1"], "m");
  // Without a load the reactions are null with the reason next to them.
  r = run("eval " + dataset("moma_m1_g0_l250.json") + " 0 -300 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["modes"][0]["reactions_N"].is_null());
  EXPECT_NE(j["modes"][0]["reactions_N_reason"].get<std::string>().find("load"), std::string::npos);
  // info states the same joints.
  r = run("info " + dataset("moma_m1_g0_l250.json") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["derived"]["joint_units"], nlohmann::json::parse(R"({"p1": "mm", "p2": "mm"})"));
}

TEST_F(Cli, ThreeDofPoseDefaultsToTheFilesOrientation) {
  // three_rrp_mitsi.json has orientation_deg 20.
  const auto two = run("eval " + dataset("three_rrp_mitsi.json") + " 70 40 --json");
  const auto three = run("eval " + dataset("three_rrp_mitsi.json") + " 70 40 20 --json");
  ASSERT_EQ(two.status, 0) << two.err;
  ASSERT_EQ(three.status, 0) << three.err;
  EXPECT_EQ(two.out, three.out);
  const auto ik = run("ik " + dataset("three_rrp_mitsi.json") + " 70 40 --json");
  ASSERT_EQ(ik.status, 0) << ik.err;
  EXPECT_EQ(nlohmann::json::parse(ik.out)["pose"][2].get<double>(), 20.0);
}

TEST_F(Cli, ExtraValuesAreAnErrorNamingTheCommand) {
  const std::string moma = dataset("moma_m1_g0_l250.json");
  expect_bad_input(run("ik " + moma + " 0 -300 5"), "ik: expected X Y for a moma file (got 3 values)");
  expect_bad_input(run("eval " + moma + " 0 -300 5"), "eval: expected X Y");
  expect_bad_input(run("dk " + moma + " 10 10 10"), "dk: expected 2 values (p1 p2)");
  expect_bad_input(run("eval " + dataset("three_rrp_mitsi.json") + " 70 40 20 1"), "eval: expected X Y [PHI_DEG]");
  expect_bad_input(run("ik " + dataset("pi_joint_prototype.json") + " 20 30"), "ik: expected THETA_DEG");
  expect_bad_input(run("area " + moma + " 5"), "area: ");
  expect_bad_input(run("info " + moma + " 5"), "info: ");
  expect_bad_input(run("explain " + dataset("machine_moma_m1.json") + " 0 -300 1"), "explain: ");
}

TEST_F(Cli, TextOutputStatesUnits) {
  auto r = run("ik " + dataset("moma_m1_g0_l250.json") + " 0 -300");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("p1 = 70.8712 mm"), std::string::npos) << r.out;
  r = run("dk " + dataset("five_bar_dextar_pm.json") + " 90 90");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("theta1 = 90 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" m, y = "), std::string::npos) << r.out;
  r = run("eval " + dataset("three_rpr_paminsa.json") + " 0.1 0.05");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("phi = 0 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" deg"), std::string::npos) << r.out;
  r = run("info " + dataset("moma_m1_g0_l250.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("p1 (mm)"), std::string::npos) << r.out;
}

}  // namespace
