// Feasible boxes of a grid sweep against a closed form: on a 5 x 4 grid with
// the metric m = x + y, the cells whose corners all have m <= 4 are the cells
// (i, j) with i + j <= 2, merged greedily along x first.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pkmws/design/feasible.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::design {
namespace {

namespace fs = std::filesystem;

fs::path write_csv(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

TEST(Feasible, BoxesOfAThresholdOnALinearMetric) {
  std::string csv = "index,x,y,status,m,reason\n";
  int index = 0;
  for (int x = 0; x <= 4; ++x) {
    for (int y = 0; y <= 3; ++y) {
      csv += std::to_string(index++) + "," + std::to_string(x) + "," + std::to_string(y) + ",ok," +
             std::to_string(x + y) + ",\n";
    }
  }
  const fs::path p = write_csv("pkmws_feasible_linear.csv", csv);
  const FeasibleSet s = feasible_set(p, {"m <= 4"});
  EXPECT_EQ(s.designs, 20u);
  EXPECT_EQ(s.feasible_designs, 14u);  // x + y <= 4
  EXPECT_EQ(s.cells, 12u);
  EXPECT_EQ(s.feasible_cells, 6u);
  ASSERT_EQ(s.boxes.size(), 3u);
  EXPECT_EQ(s.boxes[0].min, (std::vector<double>{0, 0}));
  EXPECT_EQ(s.boxes[0].max, (std::vector<double>{3, 1}));
  EXPECT_EQ(s.boxes[0].cells, 3u);
  EXPECT_EQ(s.boxes[1].min, (std::vector<double>{0, 1}));
  EXPECT_EQ(s.boxes[1].max, (std::vector<double>{2, 2}));
  EXPECT_EQ(s.boxes[2].min, (std::vector<double>{0, 2}));
  EXPECT_EQ(s.boxes[2].max, (std::vector<double>{1, 3}));
  // A condition on a parameter column, and one no design meets.
  EXPECT_EQ(feasible_set(p, {"x >= 2"}).boxes.size(), 1u);
  EXPECT_EQ(feasible_set(p, {"x >= 2"}).boxes[0].min, (std::vector<double>{2, 0}));
  EXPECT_TRUE(feasible_set(p, {"m >= 100"}).boxes.empty());
  EXPECT_NE(feasible_csv(s).find("box,cells,x_min,x_max,y_min,y_max\n0,3,0,3,0,1\n"), std::string::npos);
  EXPECT_NE(feasible_figure(s).find("<svg"), std::string::npos);
  fs::remove(p);
}

TEST(Feasible, DesignsThatAreNotOkAndOneValueParameters) {
  // 1-D with a degenerate second parameter; design 2 failed.
  const fs::path p = write_csv("pkmws_feasible_1d.csv",
                               "index,a,b,status,m,reason\n0,0,7,ok,1,\n1,1,7,ok,1,\n2,2,7,invalid,,bad\n3,3,7,ok,1,\n"
                               "4,4,7,ok,1,\n");
  const FeasibleSet s = feasible_set(p, {"m >= 0"});
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].min, (std::vector<double>{0, 7}));
  EXPECT_EQ(s.boxes[0].max, (std::vector<double>{1, 7}));
  EXPECT_EQ(s.boxes[1].min, (std::vector<double>{3, 7}));
  EXPECT_EQ(s.boxes[1].max, (std::vector<double>{4, 7}));
  EXPECT_THROW(feasible_set(p, {"q >= 0"}), io::InputError);
  EXPECT_THROW(feasible_set(p, {"m => 0"}), io::InputError);
  fs::remove(p);
  const fs::path holes = write_csv("pkmws_feasible_holes.csv", "index,a,b,status,m,reason\n0,0,0,ok,1,\n1,1,1,ok,1,\n");
  EXPECT_THROW(feasible_set(holes, {"m >= 0"}), io::InputError);  // not a full grid
  fs::remove(holes);
}

}  // namespace
}  // namespace pkmws::design
