// The batch report (pkmws/report/batch.hpp): a row holds the area report's
// numbers (the toy annulus: 40π, one component) and its figure; a file without
// a planar workspace is a row with the reason and its charts; the summaries
// and the JSON text read back.
#include <gtest/gtest.h>

#include <numbers>

#include "pkmws/report/batch.hpp"
#include "pkmws/report/plot.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kAnnulus = 40 * std::numbers::pi;

TEST(ReportBatch, ARowCarriesTheAreaReportAndItsFigure) {
  const io::MechanismFile f = test::toy_annulus_file();
  const report::BatchRow row = report::batch_row(f);
  ASSERT_TRUE(row.has_area);
  EXPECT_EQ(row.stem, "toy_annulus");
  EXPECT_NEAR(row.area, kAnnulus, 1e-12 * kAnnulus);
  EXPECT_LT(row.area_lower, row.area);
  EXPECT_GT(row.area_upper, row.area);
  EXPECT_EQ(row.method, "exact");
  ASSERT_TRUE(row.components);
  EXPECT_EQ(*row.components, 1u);
  EXPECT_FALSE(row.real);
  EXPECT_TRUE(row.criteria.empty());
  EXPECT_EQ(row.figure, "toy_annulus.svg");
  ASSERT_EQ(row.files.size(), 1u);
  EXPECT_EQ(row.files[0].name, "toy_annulus.svg");
  EXPECT_NE(row.files[0].content.find("Exact workspace area = 125.6637061 mm²"), std::string::npos);
  EXPECT_EQ(report::to_text(row).rfind("toy_annulus", 0), 0u);
  EXPECT_NE(report::to_text(row).find("125.6637061 mm²  exact\n"), std::string::npos);
}

TEST(ReportBatch, AFileWithoutAWorkspaceIsARowWithItsReasonAndCharts) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("pi_joint_prototype"));
  const report::BatchRow row = report::batch_row(f);
  EXPECT_FALSE(row.has_area);
  EXPECT_FALSE(row.note.empty());
  ASSERT_TRUE(row.charts);
  const report::PlotReport plot = report::plot(f, "");
  ASSERT_EQ(row.charts->size(), plot.figures.size());
  ASSERT_EQ(row.files.size(), plot.figures.size());
  EXPECT_EQ(row.files[0].content, plot.figures[0].svg);
  EXPECT_EQ(report::to_text(row), "");
}

TEST(ReportBatch, SummariesAndJsonTextReadBack) {
  report::BatchReport batch;
  batch.output_dir = "out";
  batch.rows.push_back(report::batch_row(test::toy_annulus_file()));
  batch.rows.push_back(report::batch_row(io::load_mechanism(test::dataset("pi_joint_prototype"))));
  const auto summary = test::parsed(report::summary_json(batch));
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_EQ(summary[0]["area"].get<double>(), batch.rows[0].area);
  EXPECT_EQ(summary[0]["components"], 1);
  EXPECT_EQ(summary[0]["figure"], "toy_annulus.svg");
  EXPECT_EQ(summary[1]["note"], batch.rows[1].note);
  EXPECT_FALSE(summary[1].contains("area"));
  const auto j = test::parsed(report::to_json_text(batch));
  EXPECT_EQ(j["output_dir"], "out");
  EXPECT_EQ(j["summary"], "summary.json");
  EXPECT_EQ(j["rows"], summary);
  const std::string md = report::summary_markdown(batch);
  EXPECT_NE(md.find("| toy_annulus | toy annulus | toy_rp | 125.6637061 | exact | mm² | exact | 1 | "),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| pi_joint_prototype | "), std::string::npos);
  EXPECT_EQ(report::to_text(batch),
            "wrote 1 figures and summary.md to out (1 files without a planar workspace are listed with the reason)\n");
}

}  // namespace
}  // namespace pkmws
