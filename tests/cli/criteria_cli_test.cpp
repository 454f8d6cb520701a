// The command line on criteria and certified regions: 3-DOF assembly modes,
// certified workspaces and their enclosures, criteria limits in export, grid
// and compare, distances to the type-2 singularity, the bands of a criterion.
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
using pkmws::test::slurp;

}  // namespace

namespace {

TEST_F(Cli, ThreeDofDirectKinematicsGivesEveryAssemblyMode) {
  // 3-RRP of [Mitsi] (reconstructed), joint values (60, 10, 10) deg.
  auto r = run("dk " + dataset("three_rrp_mitsi.json") + " 60 10 10 --json --svg " + (dir_ / "rrp").string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["solutions"].size(), 2u);
  for (const auto& s : j["solutions"]) {
    EXPECT_EQ(s["pose"].size(), 3u);
    EXPECT_EQ(s["platform_points"].size(), 3u);
    EXPECT_TRUE(fs::exists(s["figure"].get<std::string>()));
  }
  EXPECT_EQ(j["elimination"]["nominal_degree"], 8);
  EXPECT_EQ(j["elimination"]["degree"], 4);
  EXPECT_EQ(j["elimination"]["computed_degree"], 8);  // roundoff leftovers of the nominal degree 8 (dropped)
  EXPECT_EQ(j["elimination"]["poses"], 2);
  EXPECT_EQ(j["elimination"]["closed_form_assemblies"], 2);
  EXPECT_LT(j["elimination"]["max_vertex_difference"].get<double>(), 1e-9);
  // Each assembly goes back through `ik` to the same crank angles in one working mode.
  for (const auto& s : j["solutions"]) {
    const auto pose = s["pose"];
    const auto ik = run("ik " + dataset("three_rrp_mitsi.json") + " " + pose[0].dump() + " " + pose[1].dump() + " " +
                        pose[2].dump() + " --json");
    ASSERT_EQ(ik.status, 0) << ik.err;
    const auto k = nlohmann::json::parse(ik.out);
    EXPECT_EQ(k["solutions"].size(), 8u);
    bool found = false;
    for (const auto& m : k["solutions"]) {
      const auto q = m["joints"];
      found = found || (std::abs(q["phi1"].get<double>() - 60) < 1e-7 &&
                        std::abs(q["phi2"].get<double>() - 10) < 1e-7 &&
                        std::abs(q["phi3"].get<double>() - 10) < 1e-7);
    }
    EXPECT_TRUE(found);
  }

  r = run("dk " + dataset("three_prp_example.json") + " 40 40 40 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["solutions"].size(), 2u);

  r = run("dk " + dataset("three_rpr_prismatic.json") + " 1.809 1.142 0.694 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["solutions"].size(), 6u);
  EXPECT_EQ(j["elimination"]["degree"], 6);
  EXPECT_EQ(j["elimination"]["real_roots"].size(), 6u);

  r = run("dk " + dataset("three_rpr_prismatic.json") + " 1.809 1.142");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

}  // namespace

namespace {

TEST_F(Cli, CertifiedWorkspaceReportsBoundsAndExportsEitherEnclosure) {
  const auto r = run("area " + dataset("biglide_real.json") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "certified");
  const double lo = j["area_lower"], hi = j["area_upper"], area = j["area"];
  EXPECT_LT(lo, hi);
  EXPECT_LE(lo, area);
  EXPECT_LE(area, hi);
  EXPECT_LT((hi - lo) / area, 1e-3);
  for (const std::string bound : {"inner", "outer"}) {
    const auto out = dir_ / (bound + ".csv");
    const auto e = run("export " + dataset("biglide_real.json") + " -f csv --bound " + bound + " -o " + out.string());
    ASSERT_EQ(e.status, 0) << e.err;
    EXPECT_TRUE(fs::exists(out));
  }
  expect_bad_input(run("export " + dataset("biglide_real.json") + " -f csv --bound middle -o " +
                       (dir_ / "x.csv").string()),
                   "bound");
}

}  // namespace

namespace {

TEST_F(Cli, ExportHonoursCriteriaLimits) {
  // The criteria-limited region, not the whole workspace: its inner enclosure
  // is smaller than the DexTAR's reachable area (0.4156 m²) and contains the
  // certified lower bound's worth of points.
  const auto r = run("export " + dataset("five_bar_dextar_pm_alpha40.json") + " -f svg -o " + (dir_ / "a.svg").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir_ / "a.svg").find("Workspace with pressure angle \u2264 40\u00b0: certified area in ["),
            std::string::npos);
  const auto w = run("export " + dataset("five_bar_dextar_pm_alpha40.json") + " -f wkt --bound inner -o " +
                     (dir_ / "a.wkt").string());
  ASSERT_EQ(w.status, 0) << w.err;
  const auto area = run("area " + dataset("five_bar_dextar_pm_alpha40.json") + " --json");
  ASSERT_EQ(area.status, 0) << area.err;
  const auto j = nlohmann::json::parse(area.out);
  EXPECT_LT(j["area_upper"].get<double>(), 0.2);  // α <= 40° keeps 0.18125 m² of 0.41558
}

TEST_F(Cli, AreaTakesTheCriteriaTolerance) {
  // --tolerance 1e-9 narrows the default (1e-6) bounds to within 1e-9 of the
  // area, meeting them; out of (0, 1) or not a number: exit 2, one line.
  const std::string file = dataset("three_rpr_paminsa_phi0_r110.json");
  const auto wide = run("area " + file + " --json");
  const auto narrow = run("area " + file + " --tolerance 1e-9 --json");
  ASSERT_EQ(wide.status, 0) << wide.err;
  ASSERT_EQ(narrow.status, 0) << narrow.err;
  const auto w = nlohmann::json::parse(wide.out), n = nlohmann::json::parse(narrow.out);
  const double wl = w["area_lower"], wu = w["area_upper"], nl = n["area_lower"], nu = n["area_upper"];
  EXPECT_GT((wu - wl) / wu, 1e-8);
  EXPECT_LE((nu - nl) / nu, 1e-9);
  EXPECT_LE(std::max(nl, wl), std::min(nu, wu));  // both hold the area: they meet
  expect_bad_input(run("area " + file + " --tolerance 0"), "--tolerance");
  expect_bad_input(run("area " + file + " --tolerance 1.5"), "--tolerance");
  expect_bad_input(run("area " + file + " --tolerance abc"), "--tolerance");
}

}  // namespace

namespace {

TEST_F(Cli, GridAndCompareSampleTheCriteriaLimitedRegion) {
  const std::string file = dataset("five_bar_dextar_pm_alpha40.json");
  const auto g = run("grid " + file + " --cells 1000 --json");
  ASSERT_EQ(g.status, 0) << g.err;
  const double grid_area = nlohmann::json::parse(g.out)["area"];
  const auto a = run("area " + file + " --json");
  ASSERT_EQ(a.status, 0) << a.err;
  const double certified = nlohmann::json::parse(a.out)["area"];
  // α <= 40° keeps 0.18125 m² of the 0.41558 m² workspace; a 1000² grid is
  // within 1e-3 of the certified area (the whole workspace would be 2.3x off).
  EXPECT_NEAR(grid_area, certified, 1e-3 * certified);
  const auto c = run("compare " + file + " --ladder 200 --depths 4 --budget 2 --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["rows"][0]["method"], "certified");
  EXPECT_NEAR(j["exact_area"].get<double>(), certified, 1e-6 * certified);
}

}  // namespace

namespace {

TEST_F(Cli, EvalGivesTheDistanceToTheTypeTwoSingularity) {
  // PAMINSA at phi = 0: the singular circle has radius
  // sqrt(R_b² + R_p² - 2 R_b R_p) = 0.25 m ([Briot]), so from (0.1, 0.05) the
  // distance is 0.25 - |P|. Without a workspace (no leg limits, no window) to
  // the drawn curve, within its chords' sag; with one, certified: the stated
  // bound must hold it.
  {
    const auto r = run("eval " + dataset("three_rpr_paminsa.json") + " 0.1 0.05 0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["distance_to_type2_singularity"].get<double>(), 0.25 - std::hypot(0.1, 0.05), 2e-4);
    EXPECT_FALSE(j.contains("distance_to_type2_singularity_error"));
  }
  {
    const auto r = run("eval " + dataset("three_rpr_paminsa_phi0_r110.json") + " 0.1 0.05 0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double d = j["distance_to_type2_singularity"].get<double>();
    const double err = j["distance_to_type2_singularity_error"].get<double>();
    EXPECT_LT(err, 1e-6);
    EXPECT_NEAR(d, 0.25 - std::hypot(0.1, 0.05), err + 1e-12);
  }
  // The simplified biglide with rods 2000 and 300 mm: the rods align on the
  // line w_1 (y - B) = (y + B) w_2 (a closed form in y alone, bisected here).
  {
    const double b = 500.0, l1 = 2000.0, l2 = 300.0;
    const auto align = [&](double y) {
      return std::sqrt(l1 * l1 - (y + b) * (y + b)) * (y - b) - (y + b) * std::sqrt(l2 * l2 - (y - b) * (y - b));
    };
    double lo = 600.0, hi = 700.0;
    for (int i = 0; i < 200; ++i) (align(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const auto r = run("eval " + dataset("biglide_simplified_dsing20.json") + " 2200 600 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["distance_to_type2_singularity"].get<double>(), 0.5 * (lo + hi) - 600.0,
                j["distance_to_type2_singularity_error"].get<double>() + 1e-9);
    EXPECT_NE(run("eval " + dataset("biglide_simplified_dsing20.json") + " 2200 600").out.find("certified"),
              std::string::npos);
  }
  // MOMA M1: the rods never align inside W: no distance, and the reason.
  {
    const auto r = run("eval " + dataset("moma_m1_g0_l250.json") + " 0 -300 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["distance_to_type2_singularity"].is_null());
    EXPECT_NE(j["distance_to_type2_singularity_reason"].get<std::string>().find("no type-2 singular point"),
              std::string::npos);
  }
}

}  // namespace

namespace {

TEST_F(Cli, ExportWritesTheBandsOfACriterion) {
  const std::string file = dataset("five_bar_dextar_pp.json");
  const auto csv = dir_ / "bands.csv";
  auto r = run("export " + file + " -f csv --criterion pressure_angle --levels 30,60 -o " + csv.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "level,piece,x,y");
  std::set<std::string> levels;
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    levels.insert(line.substr(0, line.find(',')));
    ++rows;
  }
  EXPECT_EQ(levels, (std::set<std::string>{"30", "60"}));
  EXPECT_GT(rows, 1000u);
  r = run("export " + file + " -f svg --criterion pressure_angle --levels 30,60 -o " + (dir_ / "b.svg").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir_ / "b.svg").find("<svg"), std::string::npos);
  expect_bad_input(run("export " + file + " -f dxf --criterion pressure_angle --levels 30 -o " +
                       (dir_ / "c.dxf").string()),
                   "svg");
  expect_bad_input(run("export " + file + " -f svg --criterion pressure_angle -o " + (dir_ / "d.svg").string()),
                   "--levels");
}

}  // namespace

namespace {

// criteria.characteristic_length: a bad value or a 2-DOF mechanism is one line
// naming the field, exit status 2; the 3-RPR's eval states the L it used.
TEST_F(Cli, CharacteristicLengthErrorsAndEval) {
  auto doc = nlohmann::json::parse(slurp(dataset("three_rpr_paminsa_phi0_r200.json")));
  doc["criteria"]["characteristic_length"] = -1.0;
  auto r = run("area " + write("bad_length.json", doc.dump()).string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("criteria.characteristic_length"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  auto five_bar = nlohmann::json::parse(slurp(dataset("five_bar_dextar_pp.json")));
  five_bar["criteria"] = {{"characteristic_length", 0.1}};
  r = run("info " + write("five_bar_length.json", five_bar.dump()).string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("criteria.characteristic_length"), std::string::npos) << r.err;
  doc["criteria"]["characteristic_length"] = 0.25;
  r = run("eval " + write("length.json", doc.dump()).string() + " 0.05 -0.03 0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("characteristic_length"), std::string::npos);
  EXPECT_NE(r.out.find("0.25"), std::string::npos);
}

}  // namespace
