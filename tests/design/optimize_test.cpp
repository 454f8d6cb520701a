// Design synthesis against closed forms: the shortest MOMA rods that reach a
// task rectangle with a margin (the farthest corner from the slider at the
// end of its stroke), designs the loader rejects as infeasible points,
// determinism of the seeded search, and the spec's one-line errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "pkmws/design/optimize.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

namespace pkmws::design {
namespace {

// MOMA M1: guides at x = -100 and x = 100 pointing down from y = 0, strokes
// [0, h], rods l, branch -1 (P below the slider). The rectangle centred at
// (0, -300), 80 x 40, is deeper than the stroke: each leg reaches it when
// every corner is within l of the slider at p = h, i.e. |corner - (±100, -h)|
// <= l; with a clearance m the rounded rectangle must be, so l >= d_max + m
// (the rectangle is far from the other boundaries: |P - R_i| >= 286 > l + m).
double shortest_rod(double h, double m) {
  double d = 0;
  for (double sx : {-100.0, 100.0}) {
    for (double cx : {-40.0, 40.0}) {
      for (double cy : {-320.0, -280.0}) d = std::max(d, std::hypot(cx - sx, cy + h));
    }
  }
  return d + m;
}

std::string spec_text(const std::string& extra, double from = 150, double to = 250) {
  return R"({"base": ")" + test::dataset("moma_m1_g0_l250") + R"(",
    "parameters": [{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"], "from": )" +
         std::to_string(from) + R"(, "to": )" + std::to_string(to) + R"(}],
    "objective": {"minimize": "rod"},
    "task": {"center": [0, -300], "size": [80, 40]})" +
         extra + "}";
}

TEST(Optimize, ShortestRodsReachingATaskWithMarginMatchTheClosedForm) {
  for (double m : {0.0, 5.0, 20.0}) {
    const OptimizeSpec spec = parse_optimize(
        spec_text(R"(, "constraints": ["task_margin >= )" + std::to_string(m) + R"("], "max_evaluations": 150)"), "",
        "spec");
    const OptimizeResult r = optimize(spec);
    ASSERT_TRUE(r.feasible) << r.status;
    EXPECT_EQ(r.status, "converged");
    EXPECT_NEAR(r.best.values[0], shortest_rod(200, m), 1e-6 * shortest_rod(200, m)) << m;
    ASSERT_EQ(r.constraints.size(), 1u);
    EXPECT_TRUE(r.constraints[0].satisfied);
    EXPECT_GE(*r.constraints[0].margin, 0.0);
    EXPECT_LE(r.evaluations, 150u);
    EXPECT_EQ(r.history.size(), r.evaluations);
  }
}

TEST(Optimize, DesignsTheLoaderRejectsAreInfeasiblePointsNotErrors) {
  // Rods from -100: a third of the box is invalid (rod_length must be positive).
  const OptimizeSpec spec =
      parse_optimize(spec_text(R"(, "constraints": ["task_margin >= 5"], "max_evaluations": 150)", -100, 250), "",
                     "spec");
  const OptimizeResult r = optimize(spec);
  std::size_t invalid = 0;
  for (const auto& row : r.history) invalid += row.status == "invalid" ? 1 : 0;
  EXPECT_GT(invalid, 0u);
  ASSERT_TRUE(r.feasible);
  EXPECT_NEAR(r.best.values[0], shortest_rod(200, 5), 1e-6 * shortest_rod(200, 5));
}

TEST(Optimize, NoFeasibleDesignIsAStatusWithTheLeastInfeasibleDesign) {
  const OptimizeSpec spec =
      parse_optimize(spec_text(R"(, "constraints": ["task_margin >= 500"], "max_evaluations": 40)"), "", "spec");
  const OptimizeResult r = optimize(spec);
  EXPECT_FALSE(r.feasible);
  EXPECT_EQ(r.status, "infeasible");
  EXPECT_EQ(r.feasible_evaluations, 0u);
  EXPECT_EQ(r.best.status, "ok");
  ASSERT_TRUE(r.constraints[0].margin);
  EXPECT_LT(*r.constraints[0].margin, 0.0);
}

TEST(Optimize, TheSameSeedRepeatsTheSearch) {
  const std::string extra = R"(, "constraints": ["task_margin >= 5"], "global": "crs2_lm", "max_evaluations": 80)";
  const OptimizeSpec a = parse_optimize(spec_text(extra + R"(, "seed": 3)"), "", "spec");
  const OptimizeResult r1 = optimize(a), r2 = optimize(a);
  ASSERT_EQ(r1.history.size(), r2.history.size());
  for (std::size_t i = 0; i < r1.history.size(); ++i) EXPECT_EQ(r1.history[i].values, r2.history[i].values) << i;
  EXPECT_EQ(optimize_report(a, r1, false), optimize_report(a, r2, false));
}

TEST(Optimize, AWeightedSumObjectiveWithCobylaAndWithBobyqa) {
  // Two parameters, the size 1 rod + 0.001 stroke: for a stroke h the
  // shortest rods are shortest_rod(h, 5), which falls by about 0.65 per mm of
  // h, so the best h is the top of its range and the rods follow from it.
  const std::string text = R"({"base": ")" + test::dataset("moma_m1_g0_l250") + R"(",
    "parameters": [{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"], "from": 150, "to": 250},
                   {"name": "stroke", "path": ["legs[0].stroke[1]", "legs[1].stroke[1]"], "from": 190, "to": 200}],
    "objective": {"minimize": {"rod": 1, "stroke": 0}},
    "constraints": ["task_margin >= 5"], "task": {"center": [0, -300], "size": [80, 40]},
    "max_evaluations": 200)";
  EXPECT_THROW(parse_optimize(text + "}", "", "spec"), io::InputError);  // a zero weight
  std::string ok = text;
  ok.replace(ok.find("\"stroke\": 0}"), 12, "\"stroke\": 1e-3}");
  const double best = shortest_rod(200, 5) + 0.2;
  {
    const OptimizeResult r = optimize(parse_optimize(ok + "}", "", "spec"));
    ASSERT_TRUE(r.feasible);
    EXPECT_NEAR(r.best.values[1], 200, 1e-3);
    EXPECT_NEAR(r.best.values[0], shortest_rod(r.best.values[1], 5), 1e-6 * best);
    EXPECT_NEAR(*r.objective, best, 1e-5 * best);
  }
  {
    // BOBYQA on the penalised objective: feasible and no worse than the
    // global phase alone (the penalty's kink at an active constraint stalls
    // its quadratic model short of the optimum; COBYLA is the default).
    const OptimizeResult r = optimize(parse_optimize(ok + R"(, "local": "bobyqa", "global_evaluations": 100})", "", "spec"));
    const OptimizeResult g = optimize(parse_optimize(ok + R"(, "local": "none", "max_evaluations": 100})", "", "spec"));
    ASSERT_TRUE(r.feasible && g.feasible);
    EXPECT_EQ(r.phases.back().method, "LN_BOBYQA");
    EXPECT_EQ(g.evaluations, 100u);
    EXPECT_EQ(g.status, "budget_exhausted");
    EXPECT_GE(*r.objective, best - 1e-6 * best);
    EXPECT_LE(*r.objective, *g.objective);
  }
}

TEST(Optimize, ParseConstraint) {
  const Constraint c = parse_constraint(" task_margin>= 5.5 ", "c");
  EXPECT_EQ(c.column, "task_margin");
  EXPECT_TRUE(c.at_least);
  EXPECT_EQ(c.bound, 5.5);
  const Constraint d = parse_constraint("legs[1].rod_length <= -2e2", "c");
  EXPECT_EQ(d.column, "legs[1].rod_length");
  EXPECT_FALSE(d.at_least);
  EXPECT_EQ(d.bound, -200);
  for (const char* bad : {"task_margin > 5", "task_margin >= ", ">= 5", "a >= 5 <= 3", "a >= five", "a >= nan",
                          "a b >= 1", "a >= 0x10"}) {
    EXPECT_THROW(parse_constraint(bad, "c"), io::InputError) << bad;
  }
}

TEST(Optimize, SpecErrorsNameTheField) {
  const auto message = [](const std::string& text) {
    try {
      parse_optimize(text, "", "spec");
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string constraint = R"(, "constraints": ["task_margin >= 5"])";
  EXPECT_NE(message(spec_text(constraint + R"(, "seeed": 1)")).find("seeed: unknown field"), std::string::npos);
  EXPECT_NE(message(spec_text(R"(, "constraints": ["limited_task_margin >= 0"])")).find("needs a base file with criteria"),
            std::string::npos);
  EXPECT_NE(message(spec_text(R"(, "constraints": ["volume >= 0"])")).find("constraints[0]: 'volume' is neither"),
            std::string::npos);
  EXPECT_NE(message(spec_text(constraint, 250, 150)).find("parameters[0].to: must be greater than from"),
            std::string::npos);
  EXPECT_NE(message(spec_text(constraint + R"(, "local": "bobyqa")")).find("local: bobyqa needs at least 2"),
            std::string::npos);
  EXPECT_NE(message(spec_text(constraint + R"(, "global": "none", "local": "none")")).find("nothing searches"),
            std::string::npos);
  EXPECT_NE(message(spec_text(constraint + R"(, "max_evaluations": 0)")).find("max_evaluations: must be"),
            std::string::npos);
  std::string no_task = spec_text(constraint);
  no_task.erase(no_task.find(",\n    \"task\""), no_task.find("}", no_task.find("\"task\"")) - no_task.find(",\n    \"task\"") + 1);
  EXPECT_NE(message(no_task).find("task: is required"), std::string::npos) << no_task;
}

}  // namespace
}  // namespace pkmws::design
