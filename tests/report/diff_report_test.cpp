// The diff report (pkmws/report/diff.hpp) of two concentric toy annuli,
// A: 3 <= r <= 7 and B: 5 <= r <= 9, against closed forms: A ∩ B = 24π,
// A − B = 16π, B − A = 32π, A ∪ B = 72π, the area change 16π; the JSON text
// parsed back, the text form, the figure and the refusal of mixed units.
#include <gtest/gtest.h>

#include <numbers>

#include "pkmws/core/error.hpp"
#include "pkmws/report/diff.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ReportDiff, BooleanPiecesOfTwoAnnuliMatchTheirClosedForms) {
  const auto dir = test::fresh_dir();
  const io::MechanismFile a = io::load_mechanism(test::write_toy(dir, "a", 1, 2, 3, 7));
  const io::MechanismFile b = io::load_mechanism(test::write_toy(dir, "b", 1, 2, 5, 9));
  report::DiffOptions o;
  o.figure = "fig.svg";
  const report::DiffReport r = report::diff(a, b, o);
  EXPECT_TRUE(r.exact);
  EXPECT_NEAR(r.a_and_b.area, 24 * kPi, 1e-9);
  EXPECT_NEAR(r.a_minus_b.area, 16 * kPi, 1e-9);
  EXPECT_NEAR(r.b_minus_a.area, 32 * kPi, 1e-9);
  EXPECT_NEAR(r.a_or_b.area, 72 * kPi, 1e-9);
  EXPECT_LT(r.a_or_b.area_lower, r.a_or_b.area);
  EXPECT_GT(r.a_or_b.area_upper, r.a_or_b.area);
  ASSERT_EQ(r.metrics.size(), 9u);
  const report::DiffMetric& area = r.metrics[0];
  EXPECT_EQ(area.metric, "area");
  EXPECT_NEAR(*area.a, 40 * kPi, 1e-9);
  EXPECT_NEAR(*area.b, 56 * kPi, 1e-9);
  EXPECT_NEAR(*area.change, 16 * kPi, 1e-9);
  EXPECT_NEAR(*area.relative_change, 0.4, 1e-12);
  const report::DiffMetric& limited = r.metrics[6];
  EXPECT_EQ(limited.metric, "limited_area");
  EXPECT_FALSE(limited.a);
  EXPECT_EQ(limited.a_reason, a.path + " has no criteria");
  EXPECT_EQ(limited.change_reason, "the metric is missing for A");

  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["method"], "exact");
  EXPECT_EQ(j["area_units"], "mm²");
  EXPECT_EQ(j["regions"]["a_and_b"]["area"].get<double>(), r.a_and_b.area);
  EXPECT_EQ(j["metrics"][0]["change"].get<double>(), *area.change);
  EXPECT_TRUE(j["metrics"][6]["a"].is_null());
  EXPECT_EQ(j["metrics"][6]["a_reason"], limited.a_reason);
  EXPECT_EQ(j["figure"], "fig.svg");
  const std::string text = report::to_text(r);
  char line[96];
  std::snprintf(line, sizeof line, "  A \u2229 B   %.15g mm²\n", r.a_and_b.area);
  EXPECT_NE(text.find(line), std::string::npos) << text;
  EXPECT_NE(text.find("  limited_area n/a for A: " + limited.a_reason + "\n"), std::string::npos);
  EXPECT_NE(r.svg.find("A only: "), std::string::npos);
  EXPECT_NE(r.svg.find("class=\"a-and-b\""), std::string::npos);
}

TEST(ReportDiff, FilesInDifferentUnitsAreRefused) {
  const auto dir = test::fresh_dir();
  const io::MechanismFile a = io::load_mechanism(test::write_toy(dir, "a", 1, 2, 3, 7));
  const io::MechanismFile b = io::load_mechanism(test::write_toy(dir, "b", 0, 0, 0.003, 0.007, "m"));
  try {
    report::diff(a, b);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), b.path + ": units: \"m\" differs from \"mm\" of " + a.path +
                                         " (diff compares files in one length unit; convert one)");
  }
  EXPECT_TRUE(report::diff(a, a).svg.empty());  // no figure asked
}

}  // namespace
}  // namespace pkmws
