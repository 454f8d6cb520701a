// The compare report (pkmws/report/compare.hpp) against the closed form of the
// toy annulus (40π): the exact row, each grid row's error recomputed from its
// area, the CSV and JSON texts read back, the text form and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pkmws/core/error.hpp"
#include "pkmws/report/compare.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kAnnulus = 40 * std::numbers::pi;

report::CompareReport small_compare(const io::MechanismFile& f) {
  report::CompareOptions o;
  o.ladder = {16, 32};
  o.depths = {1, 2};
  o.budget_s = 1000;
  o.threads = 1;
  return report::compare(f, o);
}

TEST(ReportCompare, RowsMeasureTheirErrorAgainstTheClosedForm) {
  const report::CompareReport r = small_compare(test::toy_annulus_file());
  EXPECT_FALSE(r.limited);
  EXPECT_EQ(r.exact_runs, 21);
  EXPECT_NEAR(r.result.exact_area, kAnnulus, 1e-12 * kAnnulus);
  ASSERT_EQ(r.result.rows.size(), 5u);  // exact, 2 Cartesian, 2 adaptive
  EXPECT_EQ(r.result.rows[0].method, "exact");
  std::size_t cartesian = 0, adaptive = 0;
  for (const auto& row : r.result.rows) {
    cartesian += row.method == "cartesian";
    adaptive += row.method == "adaptive";
    EXPECT_NEAR(row.rel_error, std::abs(row.area - kAnnulus) / kAnnulus, 1e-12) << row.method;
    if (row.method == "cartesian") {
      EXPECT_TRUE(row.cells_per_side == 16 || row.cells_per_side == 32);
    } else if (row.method == "adaptive") {
      EXPECT_EQ(row.cells_per_side, 32u << row.depth);
    }
  }
  EXPECT_EQ(cartesian, 2u);
  EXPECT_EQ(adaptive, 2u);
}

TEST(ReportCompare, CsvJsonAndTextCarryTheRows) {
  const report::CompareReport r = small_compare(test::toy_annulus_file());
  const auto lines = test::lines_of(report::to_csv(r));
  ASSERT_EQ(lines.size(), r.result.rows.size() + 1);
  EXPECT_EQ(lines[0].rfind("method,cells_per_side,depth,points,area,rel_error,", 0), 0u);
  for (std::size_t k = 0; k < r.result.rows.size(); ++k) {
    const std::string& line = lines[k + 1];
    EXPECT_EQ(line.rfind(r.result.rows[k].method + ",", 0), 0u);
    // The area column: %.17g reads back as the same double.
    std::size_t at = 0;
    for (int c = 0; c < 4; ++c) at = line.find(',', at) + 1;
    EXPECT_EQ(std::stod(line.substr(at)), r.result.rows[k].area);
  }
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["name"], "toy annulus");
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["exact_area"].get<double>(), r.result.exact_area);
  ASSERT_EQ(j["rows"].size(), r.result.rows.size());
  EXPECT_EQ(j["rows"][1]["area"].get<double>(), r.result.rows[1].area);
  EXPECT_FALSE(j["rows"][0].contains("depth"));
  const std::string text = report::to_text(r);
  EXPECT_EQ(text.rfind("toy annulus (toy_rp)\nexact area 125.663706143592 mm²", 0), 0u) << text;
  EXPECT_NE(text.find("median of 21 runs (build + area)"), std::string::npos);
  EXPECT_NE(text.find("depth 2 (128/side)"), std::string::npos);
}

TEST(ReportCompare, AFileWithoutAWorkspaceIsRefusedWithTheMechanismsReason) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("pi_joint_prototype"));
  try {
    small_compare(f);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()).rfind("pi_joint: a lone \u03a0-joint has one degree of freedom", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace pkmws
