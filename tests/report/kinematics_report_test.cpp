// The ik / dk / eval reports (pkmws/report/kinematics.hpp) on the toy RP leg,
// whose kinematics are closed forms (theta = atan2, rho = |P - base|), their
// JSON text parsed back and their text form; dk's eliminant and figures.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/kinematics.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(ReportKinematics, IkOfTheToyLegIsItsClosedForm) {
  const io::MechanismFile f = test::toy_annulus_file();
  // P = base + 5 (cos 30°, sin 30°): theta = 30°, rho = 5.
  const mechanisms::Pose pose{1.0 + 5.0 * std::cos(30 * kDeg), 2.0 + 5.0 * std::sin(30 * kDeg), 0.0};
  const report::IkReport r = report::ik(f, pose);
  EXPECT_EQ(r.header.dof, 2);
  ASSERT_EQ(r.header.joints.size(), 2u);
  ASSERT_EQ(r.solutions.size(), 1u);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["joint_names"], nlohmann::json({"theta", "rho"}));
  EXPECT_EQ(j["joint_units"]["theta"], "deg");
  EXPECT_EQ(j["joint_units"]["rho"], "mm");
  EXPECT_EQ(j["pose"][0].get<double>(), pose.x);
  const auto& s = j["solutions"][0];
  EXPECT_EQ(s["mode"], "+");
  EXPECT_TRUE(s["valid"].get<bool>());
  EXPECT_FALSE(s.contains("reason"));
  EXPECT_NEAR(s["joints"]["theta"].get<double>(), 30.0, 1e-12);
  EXPECT_NEAR(s["joints"]["rho"].get<double>(), 5.0, 1e-12);
  EXPECT_EQ(report::to_text(r),
            "toy annulus (toy_rp): lengths in mm, angles in deg\n"
            "pose x = 5.33013 mm, y = 4.5 mm\n"
            "working mode +    valid    theta = 30 deg, rho = 5 mm\n");
  // Outside the stroke: invalid with its reason, in JSON and text.
  const report::IkReport out = report::ik(f, {1.0, 12.0, 0.0});
  const auto jo = test::parsed(report::to_json_text(out));
  EXPECT_FALSE(jo["solutions"][0]["valid"].get<bool>());
  EXPECT_EQ(jo["solutions"][0]["reason"], "rho outside stroke");
  EXPECT_NE(report::to_text(out).find("invalid  theta = 90 deg, rho = 10 mm; rho outside stroke\n"), std::string::npos);
}

TEST(ReportKinematics, DkOfTheToyLegAndItsFigure) {
  const io::MechanismFile f = test::toy_annulus_file();
  const report::DkReport r = report::dk(f, {90 * kDeg, 4.0}, "/tmp/prefix");
  ASSERT_EQ(r.solutions.size(), 1u);
  EXPECT_NEAR(r.solutions[0].pose.x, 1.0, 1e-12);
  EXPECT_NEAR(r.solutions[0].pose.y, 6.0, 1e-12);
  EXPECT_FALSE(r.elimination) << "the toy has no eliminant";
  ASSERT_EQ(r.figures.size(), 1u);
  EXPECT_EQ(r.figures[0], "/tmp/prefix_1.svg");
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_NEAR(j["joints"]["theta"].get<double>(), 90.0, 1e-12);
  EXPECT_EQ(j["joints"]["rho"].get<double>(), 4.0);
  EXPECT_EQ(j["solutions"][0]["figure"], "/tmp/prefix_1.svg");
  EXPECT_FALSE(j.contains("elimination"));
  const std::string svg = report::dk_figure(f, r, 0);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("Assembly mode 1 of 1 (+)"), std::string::npos);
  // No prefix: no figure named.
  EXPECT_EQ(report::dk(f, {0.0, 4.0}).figures, std::vector<std::string>{""});
}

TEST(ReportKinematics, DkNamesTheEliminantWhereTheMechanismHasOne) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("three_rrp_mitsi"));
  const report::DkReport r = report::dk(f, {20 * kDeg, -171.69959246679778 * kDeg, -100 * kDeg});
  ASSERT_TRUE(r.elimination);
  EXPECT_EQ(r.elimination->poses, r.solutions.size());
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["elimination"]["method"], r.elimination->method);
  EXPECT_EQ(j["elimination"]["poses"].get<std::size_t>(), r.solutions.size());
  EXPECT_NE(report::to_text(r).find("elimination: " + r.elimination->method), std::string::npos);
}

TEST(ReportKinematics, EvalGivesEveryNullItsReason) {
  const io::MechanismFile f = test::toy_annulus_file();
  const report::EvalReport r = report::eval(f, {1.0, 7.0, 0.0});  // rho = 5
  EXPECT_FALSE(r.distance_to_type2_singularity) << "the toy draws no singularity curve";
  EXPECT_FALSE(r.bodies);
  ASSERT_EQ(r.modes.size(), 1u);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_TRUE(j["distance_to_type2_singularity"].is_null());
  EXPECT_EQ(j["distance_to_type2_singularity_reason"], r.distance_reason);
  const auto& m = j["modes"][0];
  EXPECT_DOUBLE_EQ(m["jacobian_det"].get<double>(), -1.0 / 5.0);
  EXPECT_DOUBLE_EQ(m["condition_number"].get<double>(), 5.0);
  EXPECT_EQ(m["pressure_angle_deg"], nlohmann::json::array({0.0}));
  EXPECT_TRUE(m["reactions_N"].is_null());
  EXPECT_EQ(m["reactions_N_reason"], "no load: the file's criteria have no `load`");
  EXPECT_TRUE(m["velocity_ratio"].is_null());
  EXPECT_EQ(m["velocity_ratio_reason"], "not defined for this mechanism");
  const std::string t = report::to_text(r);
  EXPECT_NE(t.find("working mode +: reachable\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  jacobian_det          -0.2\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  pressure_angle        [0] deg\n"), std::string::npos) << t;
}

}  // namespace
}  // namespace pkmws
