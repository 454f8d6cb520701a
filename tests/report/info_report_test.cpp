// The info report (pkmws/report/info.hpp): the toy leg's bounds, joints and
// parameters, a machine's collision pairs, JSON parsed back and text.
#include <gtest/gtest.h>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/info.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

TEST(ReportInfo, ToyLegBoundsJointsAndParameters) {
  const report::InfoReport r = report::info(test::toy_annulus_file());
  ASSERT_TRUE(r.bounds);
  EXPECT_EQ(r.bounds->min.x, -6.0);
  EXPECT_EQ(r.bounds->max.y, 9.0);
  EXPECT_FALSE(r.collision_pairs);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["mechanism"], "toy_rp");
  EXPECT_EQ(j["stroke"], nlohmann::json::array({3.0, 7.0}));  // the validated document
  const auto& d = j["derived"];
  EXPECT_EQ(d["dof"], 2);
  EXPECT_EQ(d["joint_names"], nlohmann::json({"theta", "rho"}));
  EXPECT_EQ(d["bounds"]["min"], nlohmann::json::array({-6.0, -5.0}));
  EXPECT_EQ(d["parameters"].size(), r.parameters.size());
  EXPECT_FALSE(d.contains("collision_pairs"));
  const std::string t = report::to_text(r);
  EXPECT_NE(t.find("dof        2\njoints     theta (deg), rho (mm)\n"), std::string::npos) << t;
  EXPECT_NE(t.find("bounds     x -6 .. 8 mm, y -5 .. 9 mm\n"), std::string::npos) << t;
  EXPECT_EQ(t.find("orientation"), std::string::npos) << "2-DOF: no orientation line";
}

TEST(ReportInfo, AMachineListsItsCollisionPairs) {
  const report::InfoReport r = report::info(io::load_mechanism(test::dataset("machine_moma_m1")));
  ASSERT_TRUE(r.collision_pairs);
  EXPECT_FALSE(r.collision_pairs->empty());
  const auto j = test::parsed(report::to_json_text(r));
  ASSERT_EQ(j["derived"]["collision_pairs"].size(), r.collision_pairs->size());
  EXPECT_EQ(j["derived"]["collision_pairs"][0][0], r.collision_pairs->front().first);
  EXPECT_NE(report::to_text(r).find("collision pairs " + std::to_string(r.collision_pairs->size()) + "\n"),
            std::string::npos);
}

}  // namespace
}  // namespace pkmws
