// The feasible report (pkmws/report/feasible.hpp) over a 3 x 3 grid sweep
// written here (m = a + b): designs and cells counted independently, the box,
// the JSON text and the report file read back, the figure and its refusal.
#include <gtest/gtest.h>

#include "pkmws/core/error.hpp"
#include "pkmws/report/feasible.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

std::string sweep_csv(int params) {
  std::string csv = params == 2 ? "index,a,b,status,m,reason\n" : "index,a,status,m,reason\n";
  int i = 0;
  for (int b = 1; b <= (params == 2 ? 3 : 1); ++b) {
    for (int a = 1; a <= 3; ++a) {
      csv += std::to_string(i++) + "," + std::to_string(a) + (params == 2 ? "," + std::to_string(b) : "") + ",ok," +
             std::to_string(a + (params == 2 ? b : 0)) + ",\n";
    }
  }
  return csv;
}

TEST(ReportFeasible, CountsDesignsAndCellsWhoseCornersHold) {
  const auto dir = test::fresh_dir();
  const std::string csv = test::write_text(dir / "s.csv", sweep_csv(2)).string();
  const report::FeasibleReport r = report::feasible(csv, {"m >= 4"});
  std::size_t designs = 0, cells = 0;
  const auto ok = [](int a, int b) { return a + b >= 4; };
  for (int a = 1; a <= 3; ++a) {
    for (int b = 1; b <= 3; ++b) designs += ok(a, b);
  }
  for (int a = 1; a < 3; ++a) {
    for (int b = 1; b < 3; ++b) cells += ok(a, b) && ok(a + 1, b) && ok(a, b + 1) && ok(a + 1, b + 1);
  }
  EXPECT_EQ(r.set.designs, 9u);
  EXPECT_EQ(r.set.feasible_designs, designs);
  EXPECT_EQ(r.set.cells, 4u);
  EXPECT_EQ(r.set.feasible_cells, cells);
  ASSERT_EQ(r.set.boxes.size(), 1u);
  EXPECT_EQ(r.set.boxes[0].min, (std::vector<double>{2, 2}));
  EXPECT_EQ(r.set.boxes[0].max, (std::vector<double>{3, 3}));
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(test::parsed(report::report_file_text(r)), j);
  EXPECT_EQ(report::report_file_text(r).back(), '\n');
  EXPECT_EQ(report::to_text(r),
            "feasible: 6 of 9 designs, 1 of 4 cells (every corner feasible), 1 box(es)\n"
            "  box 0 (1 cells): a in [2, 3], b in [2, 3]\n"
            "sampled at the grid's designs, not certified between them\n");
  EXPECT_NE(report::figure(r).find("<svg"), std::string::npos);
  const auto boxes = test::lines_of(report::boxes_csv(r));
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0], "box,cells,a_min,a_max,b_min,b_max");
}

TEST(ReportFeasible, TheFigureNeedsTwoParameters) {
  const auto dir = test::fresh_dir();
  const std::string csv = test::write_text(dir / "s.csv", sweep_csv(1)).string();
  const report::FeasibleReport r = report::feasible(csv, {"m >= 2"});
  EXPECT_EQ(r.set.feasible_designs, 2u);
  try {
    report::figure(r);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--svg: draws a sweep over two parameters (" + csv + " has 1)");
  }
}

}  // namespace
}  // namespace pkmws
