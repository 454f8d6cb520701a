// The sweep report (pkmws/report/sweep.hpp) on the toy annulus, whose area is
// π(s² − 9) for the outer stroke s: the rows against the closed form, the CSV
// written and read back (a cut last line left out), shards merged (a design
// twice refused), the rows' JSON and the summary line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pkmws/core/error.hpp"
#include "pkmws/report/sweep.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kPi = std::numbers::pi;

report::SweepReport toy_sweep(const std::filesystem::path& dir) {
  test::write_toy(dir, "toy", 1, 2, 3, 7);
  const auto spec = test::write_text(dir / "sweep.json", R"({
  "base": "toy.json",
  "parameters": [{"name": "outer", "path": "stroke[1]", "values": [5, 7, 9]}],
  "metrics": ["area"]
})");
  report::SweepReport r;
  r.spec = design::load_sweep(spec);
  r.rows = design::run_sweep(r.spec, {0, 1, 2}, 1);
  r.evaluated = 3;
  r.seconds = 0.5;
  r.output = "out.csv";
  return r;
}

TEST(ReportSweep, RowsMatchTheClosedFormAndTheCsvReadsBack) {
  const auto dir = test::fresh_dir();
  const report::SweepReport r = toy_sweep(dir);
  ASSERT_EQ(r.rows.size(), 3u);
  const auto cols = design::metric_columns(r.spec);
  const std::size_t area = static_cast<std::size_t>(std::find(cols.begin(), cols.end(), "area") - cols.begin());
  ASSERT_LT(area, cols.size());
  for (const auto& row : r.rows) {
    ASSERT_EQ(row.status, "ok") << row.reason;
    const double s = row.values[0];
    EXPECT_NEAR(*row.metrics[area], kPi * (s * s - 9), 1e-9 * kPi * s * s);
  }
  const report::SweepCsv csv{design::csv_header(r.spec, false), r.rows, false};
  const std::string text = report::csv_text(csv);
  const report::SweepCsv back = report::read_sweep_csv(test::write_text(dir / "s.csv", text));
  EXPECT_EQ(back.header, csv.header);
  EXPECT_FALSE(back.timing);
  ASSERT_EQ(back.rows.size(), 3u);
  EXPECT_EQ(report::csv_text(back), text);
  // A last line without its line break was cut short: left out.
  const std::string cut = text.substr(0, text.size() - 5);
  EXPECT_EQ(report::read_sweep_csv(test::write_text(dir / "cut.csv", cut)).rows.size(), 2u);
  EXPECT_THROW(report::read_sweep_csv(test::write_text(dir / "bad.csv", "a,b\n")), InputError);
}

TEST(ReportSweep, ShardsMergeByIndexAndADesignTwiceIsRefused) {
  const auto dir = test::fresh_dir();
  const report::SweepReport r = toy_sweep(dir);
  const std::string header = design::csv_header(r.spec, true);
  const auto s0 = test::write_text(dir / "s0.csv", report::csv_text({header, {r.rows[2], r.rows[0]}, true}));
  const auto s1 = test::write_text(dir / "s1.csv", report::csv_text({header, {r.rows[1]}, true}));
  const report::SweepCsv merged = report::merge_sweep_csvs({s1.string(), s0.string()});
  ASSERT_EQ(merged.rows.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(merged.rows[k].index, k);
  EXPECT_TRUE(merged.timing);
  EXPECT_EQ(report::merge_text(merged, 2, "m.csv"), "merged 3 designs from 2 files into m.csv\n");
  try {
    report::merge_sweep_csvs({s0.string(), s0.string()});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), s0.string() + ": design 2 is in two shards");  // its first row
  }
}

TEST(ReportSweep, RowsJsonAndSummary) {
  const auto dir = test::fresh_dir();
  const report::SweepReport r = toy_sweep(dir);
  const std::string text = report::rows_json_text(r);
  EXPECT_EQ(text.back(), '\n');
  const auto j = test::parsed(text);
  EXPECT_EQ(j["parameters"][0]["name"], "outer");
  ASSERT_EQ(j["rows"].size(), 3u);
  EXPECT_EQ(j["rows"][2]["outer"].get<double>(), 9.0);
  EXPECT_NEAR(j["rows"][2]["area"].get<double>(), kPi * 72, 1e-9);
  EXPECT_EQ(j["rows"][0]["status"], "ok");
  EXPECT_EQ(report::to_text(r), "3 designs (3 ok) -> out.csv; 3 evaluated in 0.500 s (6.0 designs/s)\n");
}

}  // namespace
}  // namespace pkmws
