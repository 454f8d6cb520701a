// The chart report (pkmws/report/chart.hpp) over two one-parameter sweeps
// written here: the Markdown tables' cells (plain values, midpoint ± half-width
// of bounds, marked columns in bold), the figure's panels, the JSON text parsed
// back, and the errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pkmws/core/error.hpp"
#include "pkmws/report/chart.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

struct Sweeps {
  std::string plain, bounds;
};

// plain: m = 10 x; bounds: m in [100 x, 100 x + 4] (midpoint 100 x + 2, half-width 2), x = 3 failed.
Sweeps write_sweeps(const std::filesystem::path& dir) {
  const auto plain = test::write_text(dir / "plain.csv",
                                      "index,x,status,m,reason\n0,1,ok,10,\n1,2,ok,20,\n2,3,ok,30,\n");
  const auto bounds = test::write_text(dir / "bounds.csv",
                                       "index,x,status,m_lower,m_upper,reason\n0,1,ok,100,104,\n1,2,ok,200,204,\n"
                                       "2,3,invalid,,,bad\n");
  return {plain.string(), bounds.string()};
}

TEST(ReportChart, TablesHoldValuesAndBoundsWithMarkedColumnsInBold) {
  const auto dir = test::fresh_dir();
  const Sweeps s = write_sweeps(dir);
  report::ChartOptions o;
  o.csvs = {s.plain + "=P", s.bounds};
  o.x = "x";
  o.ys = {"m"};
  o.y_labels = {"m (mm)"};
  o.marks = "2";
  o.output = "c.svg";
  o.markdown_output = "c.md";
  const report::ChartReport r = report::chart(o);
  EXPECT_EQ(r.markdown,
            "#### m (mm)\n\n"
            "| x | 1 | **2** | 3 |\n"
            "|---|--:|--:|--:|\n"
            "| P | 10 | **20** | 30 |\n"
            "| bounds | 102 \u00b1 3 | **202 \u00b1 3** | \u2013 |\n");
  EXPECT_NE(r.svg.find("<svg"), std::string::npos);
  EXPECT_NE(r.svg.find("m (mm)"), std::string::npos);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["x"], "x");
  EXPECT_EQ(j["metrics"], nlohmann::json::array({"m"}));
  ASSERT_EQ(j["sweeps"].size(), 2u);
  EXPECT_EQ(j["sweeps"][0]["label"], "P");
  EXPECT_EQ(j["sweeps"][1]["label"], "bounds");  // the file's stem
  EXPECT_EQ(j["sweeps"][1]["metrics"], nlohmann::json::array({"m"}));
  EXPECT_EQ(j["figure"], "c.svg");
  EXPECT_EQ(j["markdown"], "c.md");
  EXPECT_EQ(report::to_text(r), "c.svg\nc.md\n");
  o.output.clear();
  const report::ChartReport tables = report::chart(o);
  EXPECT_TRUE(tables.svg.empty());
  const auto k = test::parsed(report::to_json_text(tables));
  EXPECT_TRUE(k["figure"].is_null());
  EXPECT_EQ(k["figure_reason"], "no -o FIG.svg given");
}

TEST(ReportChart, ErrorsNameTheOptionOrTheFile) {
  const auto dir = test::fresh_dir();
  const Sweeps s = write_sweeps(dir);
  const auto message = [](const report::ChartOptions& o) {
    try {
      report::chart(o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  report::ChartOptions o;
  o.csvs = {s.plain};
  o.x = "x";
  o.ys = {"nope"};
  o.output = "c.svg";
  EXPECT_EQ(message(o), "--y: no file has values of 'nope' (or nope_lower/_upper)");
  o.ys = {"m"};
  o.y_labels = {"a", "b"};
  EXPECT_EQ(message(o), "--y-label: give one per --y (1)");
  o.y_labels.clear();
  o.x = "status";
  EXPECT_EQ(message(o), "status: expected a decimal number, got \"ok\"");
  o.x = "x";
  const auto twice = test::write_text(dir / "twice.csv", "index,x,status,m,reason\n0,1,ok,1,\n1,1,ok,2,\n");
  o.csvs = {twice.string()};
  EXPECT_EQ(message(o), twice.string() + ": a second design at x = 1 (chart reads one-parameter sweeps; filter the rows)");
}

}  // namespace
}  // namespace pkmws
