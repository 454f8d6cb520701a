// The plot report (pkmws/report/plot.hpp): the Π-joint's charts as SVG
// documents named as the capability names them, the JSON text parsed back,
// the text form, and the refusal of a mechanism without charts.
#include <gtest/gtest.h>

#include <set>

#include "pkmws/core/error.hpp"
#include "pkmws/io/plot.hpp"
#include "pkmws/report/plot.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

TEST(ReportPlot, EveryChartOfThePiJointIsAnSvgDocument) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("pi_joint_prototype"));
  const report::PlotReport r = report::plot(f, "figs");
  const auto charts = f.model->capability<io::Charts>();
  ASSERT_TRUE(charts);
  const auto named = charts->charts();
  ASSERT_EQ(r.figures.size(), named.size());
  ASSERT_FALSE(r.figures.empty());
  std::set<std::string> names;
  for (std::size_t k = 0; k < named.size(); ++k) {
    EXPECT_EQ(r.figures[k].file, named[k].stem + ".svg");
    EXPECT_NE(r.figures[k].svg.find("<svg"), std::string::npos);
    EXPECT_NE(r.figures[k].svg.find("</svg>"), std::string::npos);
    names.insert(r.figures[k].file);
  }
  EXPECT_EQ(names.size(), r.figures.size());
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["mechanism"], "pi_joint");
  EXPECT_EQ(j["output_dir"], "figs");
  ASSERT_EQ(j["figures"].size(), r.figures.size());
  EXPECT_EQ(j["figures"][0], r.figures[0].file);
  const auto lines = test::lines_of(report::to_text(r));
  ASSERT_EQ(lines.size(), r.figures.size());
  EXPECT_EQ(lines.back(), "figs/" + r.figures.back().file);
}

TEST(ReportPlot, AMechanismWithoutChartsIsRefusedWithTheReason) {
  const io::MechanismFile f = test::toy_annulus_file();
  try {
    report::plot(f, ".");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("toy_annulus.json: `plot` draws the curves of a pi_joint file (", 0), 0u) << m;
    EXPECT_NE(m.find("use `export` for the workspace of a toy_rp"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace pkmws
