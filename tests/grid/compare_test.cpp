// Exact vs grid comparison: the log-log interpolation on synthetic power laws,
// and a short comparison run on MOMA M1 whose rows must be consistent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pkmws/grid/compare.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

using namespace pkmws;

TEST(GridCompare, TimeAtAccuracyFollowsAPowerLaw) {
  // error = 10 / t^2: runs at t = 1, 10, 100 ms.
  const std::vector<std::pair<double, double>> runs{{1.0, 10.0}, {10.0, 0.1}, {100.0, 1e-3}};
  const auto t = grid::time_at_accuracy(runs, 1e-2);
  ASSERT_TRUE(t.time_ms);
  EXPECT_NEAR(*t.time_ms, std::sqrt(1000.0), 1e-9);  // 10 / t^2 = 1e-2
  EXPECT_FALSE(t.extrapolated);
  const auto far = grid::time_at_accuracy(runs, 1e-5);
  ASSERT_TRUE(far.time_ms);
  EXPECT_TRUE(far.extrapolated);
  EXPECT_NEAR(*far.time_ms, 1000.0, 1e-6);
  const auto c = grid::accuracy_at_time(runs, 3.0);
  ASSERT_TRUE(c.rel_error);
  EXPECT_NEAR(*c.rel_error, 10.0 / 9.0, 1e-12);
  EXPECT_EQ(c.note, "interpolated");
}

TEST(GridCompare, LuckyCoarseRunsDoNotCount) {
  // The run at 2 ms is lucky (1e-6) but the one at 4 ms is back at 1e-4: 1e-5
  // is reached between 4 and 8 ms, at 4 * 2^(1/3) on the power law.
  const std::vector<std::pair<double, double>> runs{{1.0, 1e-3}, {2.0, 1e-6}, {4.0, 1e-4}, {8.0, 1e-7}};
  const auto t = grid::time_at_accuracy(runs, 1e-5);
  ASSERT_TRUE(t.time_ms);
  EXPECT_NEAR(*t.time_ms, 4.0 * std::cbrt(2.0), 1e-9);
  const auto c = grid::accuracy_at_time(runs, 3.0);  // between 1 ms (1e-3) and 4 ms (1e-4)
  ASSERT_TRUE(c.rel_error);
  EXPECT_NEAR(*c.rel_error, 1e-3 * std::pow(10.0, -std::log(3.0) / std::log(4.0)), 1e-15);
  const auto single = grid::time_at_accuracy({{5.0, 1.0}}, 1e-3);
  EXPECT_FALSE(single.time_ms);
}

TEST(GridCompare, ShortRunOnMomaM1) {
  const auto m = io::load_mechanism(pkmws::test::dataset("moma_m1_g0_l250"));
  grid::CompareOptions o;
  o.ladder = {50, 100, 200, 400};
  o.depths = {2, 4, 6, 8};
  o.exact_runs = 3;
  const auto r = grid::compare(*m.model, o);
  EXPECT_NEAR(r.exact_area, m.model->workspace().area(), 0.0);
  EXPECT_GT(r.exact_time_ms, 0.0);
  ASSERT_EQ(r.rows.size(), 1u + 4u + 4u);
  EXPECT_EQ(r.rows[0].method, "exact");
  for (const auto& row : r.rows) {
    if (row.method == "exact") continue;
    EXPECT_NEAR(row.rel_error, std::abs(row.area - r.exact_area) / r.exact_area, 1e-15);
    ASSERT_TRUE(row.guaranteed_rel_error) << row.method;
    EXPECT_GE(*row.guaranteed_rel_error, row.rel_error) << row.method << " " << row.cells_per_side;
    EXPECT_NEAR(row.ratio_to_exact, row.time_ms / r.exact_time_ms, 1e-12);
  }
  // The adaptive bound halves per level; the uniform grid's with each doubling.
  EXPECT_LT(*r.rows[8].guaranteed_rel_error, *r.rows[5].guaranteed_rel_error / 4.0);
  EXPECT_LT(*r.rows[4].guaranteed_rel_error, *r.rows[1].guaranteed_rel_error / 4.0);
  EXPECT_EQ(r.at_accuracy.size(), 16u);  // 2 methods x 2 notions x 4 targets
  EXPECT_EQ(r.crossovers.size(), 4u);
}

TEST(GridCompare, BudgetStopsTheLadder) {
  const auto m = io::load_mechanism(pkmws::test::dataset("moma_m1_g0_l250"));
  grid::CompareOptions o;
  o.ladder = {100, 200, 400};
  o.depths = {2, 4};
  o.exact_runs = 1;
  o.time_budget_ms = 0.0;  // every step is over budget
  const auto r = grid::compare(*m.model, o);
  ASSERT_EQ(r.rows.size(), 3u);  // exact, first ladder step, first depth
  ASSERT_EQ(r.notes.size(), 2u);
  EXPECT_NE(r.notes[0].find("stopped after 100^2"), std::string::npos) << r.notes[0];
}
