// The optimize report (pkmws/report/optimize.hpp) on the toy annulus, whose
// area is π(s² − 9) for the outer stroke s: the optimum's objective matches
// the closed form at its parameter and respects the constraint; the JSON text,
// the report file, the history and the design file read back; the text form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pkmws/core/error.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/optimize.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kPi = std::numbers::pi;

std::filesystem::path toy_spec(const std::filesystem::path& dir) {
  test::write_toy(dir, "toy", 1, 2, 3, 7);
  return test::write_text(dir / "spec.json", R"({
  "base": "toy.json",
  "parameters": [{"name": "outer", "path": "stroke[1]", "from": 5, "to": 9}],
  "objective": {"maximize": "area"},
  "constraints": ["area <= 100"],
  "max_evaluations": 30
})");
}

TEST(ReportOptimize, TheOptimumMatchesTheClosedFormAndItsConstraint) {
  const auto dir = test::fresh_dir();
  const report::OptimizeReport r = report::optimize(toy_spec(dir), false);
  ASSERT_TRUE(r.result.feasible) << r.result.status;
  ASSERT_TRUE(r.result.objective);
  ASSERT_EQ(r.result.best.values.size(), 1u);
  const double s = r.result.best.values[0];
  EXPECT_NEAR(*r.result.objective, kPi * (s * s - 9), 1e-9 * *r.result.objective);
  EXPECT_LE(*r.result.objective, 100 + 1e-6);
  EXPECT_GT(*r.result.objective, 90);  // the area grows with s: the bound is nearly reached
  ASSERT_EQ(r.result.constraints.size(), 1u);
  EXPECT_NEAR(*r.result.constraints[0].margin, 100 - *r.result.objective, 1e-9);
}

TEST(ReportOptimize, TextsReadBack) {
  const auto dir = test::fresh_dir();
  const report::OptimizeReport r = report::optimize(toy_spec(dir), false);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["objective"]["value"].get<double>(), *r.result.objective);
  EXPECT_EQ(j["parameters"][0]["value"].get<double>(), r.result.best.values[0]);
  EXPECT_EQ(j["evaluations"].get<std::size_t>(), r.result.evaluations);
  EXPECT_FALSE(j.contains("time_ms"));  // timing false
  const std::string file = report::report_file_text(r);
  ASSERT_FALSE(file.empty());
  EXPECT_EQ(file.back(), '\n');
  EXPECT_EQ(test::parsed(file)["objective"], j["objective"]);
  const auto history = test::lines_of(report::history_csv(r));
  EXPECT_EQ(history.size(), r.result.history.size() + 1);
  EXPECT_EQ(history[0].rfind("index,outer,status,", 0), 0u);
  // The design file loads, with the optimum's stroke.
  const auto design = test::write_text(dir / "best.json", report::design_file_text(r));
  EXPECT_NO_THROW(io::load_mechanism(design));
  EXPECT_EQ(test::parsed(report::design_file_text(r))["stroke"][1].get<double>(), r.result.best.values[0]);
  const std::string text = report::to_text(r);
  EXPECT_EQ(text.rfind("optimize: maximize area over 1 parameter(s): ", 0), 0u) << text;
  char line[80];
  std::snprintf(line, sizeof line, "\noptimum: %.10g\n  outer = %.10g\n", *r.result.objective, r.result.best.values[0]);
  EXPECT_NE(text.find(line), std::string::npos) << text;
}

TEST(ReportOptimize, AMissingSpecIsRefusedNamingIt) {
  EXPECT_THROW(report::optimize("/nonexistent/spec.json"), InputError);
}

}  // namespace
}  // namespace pkmws
