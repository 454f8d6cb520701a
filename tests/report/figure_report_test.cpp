// The figures of a file (pkmws/report/figure.hpp): the caption states the
// area report's numbers; a machine's figure hatches each interference region
// and outlines the real workspace.
#include <gtest/gtest.h>

#include <string>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/figure.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

TEST(ReportFigure, CaptionStatesTheExactArea) {
  const io::MechanismFile f = test::toy_annulus_file();
  const report::AreaReport r = report::area(f);
  const std::string svg = report::area_figure(f, r);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  // 40π = 125.66370614359...
  EXPECT_NE(svg.find("Exact workspace area = 125.6637061 mm² (1 component)."), std::string::npos);
}

TEST(ReportFigure, AMachineShowsItsInterferenceAndRealWorkspace) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("machine_moma_m1"));
  report::AreaOptions o;
  o.interference_depth = 3;
  const report::AreaReport r = report::area(f, o);
  ASSERT_TRUE(r.real);
  std::size_t drawn = 0;
  for (const auto& i : r.real->interference) drawn += i.region.outer.empty() ? 0 : 1;
  EXPECT_GT(drawn, 0u);
  const std::string svg = report::area_figure(f, r);
  EXPECT_EQ(test::count_of(svg, "class=\"interference\""), drawn);
  EXPECT_EQ(test::count_of(svg, "class=\"real\""), 1u);
  EXPECT_NE(svg.find("Reachable workspace "), std::string::npos);
  const std::string real = report::real_workspace_figure(f, r.real->real.inner);
  EXPECT_NE(real.find("Inner enclosure of the real workspace"), std::string::npos);
}

}  // namespace
}  // namespace pkmws
