// MOMA (seed 000): IK/DK round trips in every bundled configuration, the
// paper's closed form against the robust DK, Jacobians against finite
// differences, singularities, and the exact workspace against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include <Eigen/LU>
#include <Eigen/QR>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/mechanisms/moma.hpp"

using namespace pkmws;
using mechanisms::Moma;
using mechanisms::MomaLeg;

namespace {

std::vector<std::filesystem::path> moma_datasets() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PKMWS_SOURCE_DIR) + "/datasets")) {
    if (e.path().extension() == ".json" && e.path().filename().string().rfind("moma_", 0) == 0) {
      out.push_back(e.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

const Moma& as_moma(const io::MechanismFile& f) { return dynamic_cast<const Moma&>(*f.model); }

Moma m1(double l = 250.0, double gamma_deg = 0.0) {
  const double a = 1.5 * std::numbers::pi + gamma_deg * std::numbers::pi / 180.0;
  return Moma({MomaLeg{{-100, 0}, a, 0, 200, l, -1}, MomaLeg{{100, 0}, a, 0, 200, l, -1}});
}

// Antiderivative of sqrt(l^2 - u^2).
double F(double u, double l) { return 0.5 * (u * std::sqrt(l * l - u * u) + l * l * std::asin(u / l)); }

}  // namespace

TEST(MomaCore, ThirtyThreeDatasetsLoad) {
  const auto files = moma_datasets();
  ASSERT_EQ(files.size(), 33u);
  for (const auto& f : files) {
    const auto mech = io::load_mechanism(f);
    EXPECT_EQ(mech.mechanism, "moma");
    EXPECT_TRUE(mech.source.contains("figure")) << f;
    EXPECT_GT(mech.model->workspace().area(), 0.0) << f;
  }
}

TEST(MomaCore, InverseThenDirectRoundTripInEveryConfiguration) {
  std::mt19937 rng(2024);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int checked = 0;
    for (int k = 0; k < 400 && checked < 60; ++k) {
      // Random joint values -> every DK pose -> IK of the file's branches -> same joints.
      const double p1 = 200 * u(rng), p2 = 200 * u(rng);
      for (const auto& s : m.direct(std::vector<double>{p1, p2})) {
        if (!s.valid) continue;
        const auto ik = m.inverse(s.pose);
        ASSERT_TRUE(ik[0].valid) << f << " " << ik[0].reason;
        EXPECT_NEAR(ik[0].joints[0], p1, 1e-9 * 250) << f;
        EXPECT_NEAR(ik[0].joints[1], p2, 1e-9 * 250) << f;
        EXPECT_TRUE(m.reachable(s.pose));
        ++checked;
      }
    }
    EXPECT_GT(checked, 10) << f;
  }
}

TEST(MomaCore, DirectThenInverseForEveryWorkingMode) {
  const Moma m = m1();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-150, 150), y(-450, -230);
  for (int k = 0; k < 500; ++k) {
    const mechanisms::Pose pose{x(rng), y(rng), 0};
    for (const auto& s : m.inverse(pose)) {
      if (s.joints.size() != 2) continue;
      bool found = false;
      for (const auto& a : m.direct_all(s.joints[0], s.joints[1])) {
        found = found || std::hypot(a.platform.x - pose.x, a.platform.y - pose.y) < 1e-8;
      }
      EXPECT_TRUE(found) << s.mode << " at " << pose.x << ", " << pose.y;
    }
  }
}

TEST(MomaCore, ClosedFormAgreesWhereDefined) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  int compared = 0;
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int k = 0; k < 50; ++k) {
      const double p1 = u(rng), p2 = u(rng);
      for (int sign : {-1, 1}) {
        const auto cf = m.direct_closed_form(p1, p2, sign);
        if (!cf) continue;
        // The closed-form point solves both rod equations (seed 000 eq. 7-8) ...
        for (int i = 0; i < 2; ++i) {
          const auto s = m.slider(i, i == 0 ? p1 : p2);
          EXPECT_NEAR(std::hypot(cf->x - s.x, cf->y - s.y), m.legs()[i].rod_length, 1e-8);
        }
        // ... and is one of the robust DK's assembly modes.
        double best = 1e300;
        for (const auto& a : m.direct_all(p1, p2)) best = std::min(best, std::hypot(a.platform.x - cf->x, a.platform.y - cf->y));
        EXPECT_LT(best, 1e-8 * 250) << f;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(MomaCore, ClosedFormDividesByZeroInM2ButRobustDkWorks) {
  const auto mech = io::load_mechanism(std::string(PKMWS_SOURCE_DIR) + "/datasets/moma_m2_l250.json");
  const Moma& m = as_moma(mech);
  // M2: slider 2 runs along y = 50 from x = 0, slider 1 along x = 50 from y = 0;
  // at p2 = 50 both sliders have x = 50, so v4 = v1 in eq. 12.
  EXPECT_FALSE(m.direct_closed_form(10.0, 50.0, 1).has_value());
  const auto sols = m.direct(std::vector<double>{10.0, 50.0});
  ASSERT_EQ(sols.size(), 2u);
  bool one_valid = false;
  for (const auto& s : sols) {
    for (int i = 0; i < 2; ++i) {
      const auto sl = m.slider(i, i == 0 ? 10.0 : 50.0);
      EXPECT_NEAR(std::hypot(s.pose.x - sl.x, s.pose.y - sl.y), 250.0, 1e-9);
    }
    one_valid = one_valid || s.valid;
  }
  EXPECT_TRUE(one_valid);
}

TEST(MomaCore, JacobianMatchesFiniteDifferences) {
  const Moma m = m1(195, -5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-100, 100), y(-380, -260);
  for (int k = 0; k < 100; ++k) {
    const mechanisms::Pose p{x(rng), y(rng), 0};
    const auto ev = m.evaluate(p, {});
    const auto& e = ev[0];
    if (!e.reachable || e.singular) continue;
    const double h = 1e-5;
    auto q = [&](double dx, double dy, int i) {
      return *m.inverse_leg(i, {p.x + dx, p.y + dy}, -1);
    };
    Eigen::Matrix2d fd;
    for (int i = 0; i < 2; ++i) {
      fd(i, 0) = (q(h, 0, i) - q(-h, 0, i)) / (2 * h);
      fd(i, 1) = (q(0, h, i) - q(0, -h, i)) / (2 * h);
    }
    const auto j = m.jacobians({p.x, p.y}, e.joints[0], e.joints[1]);
    const Eigen::Matrix2d jq = j.B.inverse() * j.A;
    EXPECT_LT((jq - fd).norm(), 1e-6 * (1 + jq.norm()));
    EXPECT_NEAR(e.jacobian_det, jq.determinant(), 1e-9 * (1 + std::abs(jq.determinant())));
  }
}

TEST(MomaCore, SingularitiesAreDetected) {
  const Moma m = m1();
  // Type 2: rods aligned. Sliders at p1 = p2 = 0 are (-100, 0), (100, 0), 200 apart;
  // with rods of 250 the DK poses are never aligned, so build the pose directly:
  // P on the line through both sliders needs |S1S2| = l1 + l2 -> not in M1. Use a
  // custom mechanism with l1 + l2 = 200: P = (0, 0) at p = 0.
  const Moma touching({MomaLeg{{-100, 0}, 1.5 * std::numbers::pi, 0, 200, 100, -1},
                       MomaLeg{{100, 0}, 1.5 * std::numbers::pi, 0, 200, 100, -1}});
  const auto e2 = touching.evaluate({0, 0, 0}, {});
  EXPECT_TRUE(e2[0].singular);
  EXPECT_NE(e2[0].singularity.find("type2") == std::string::npos ? e2[0].singularity : "type2", "");
  // Type 1: rod perpendicular to its guide (P level with slider 1): p = 0, P = (150, 0)? rod 250 from (-100,0).
  const auto e1 = m.evaluate({150, 0, 0}, {});
  EXPECT_TRUE(e1[0].singular);
  EXPECT_TRUE(e1[0].singularity == "type1" || e1[0].singularity == "both");
  // A regular pose.
  EXPECT_FALSE(m.evaluate({0, -300, 0}, {})[0].singular);
}

TEST(MomaCore, PressureAngleAndReactions) {
  const Moma m = m1();
  mechanisms::Criteria c;
  c.load = mechanisms::Load{100.0, 5.0};
  const auto e = m.evaluate({0, -300, 0}, c)[0];
  // Symmetric pose: rods from (-100, -p) and (100, -p) to (0, -300), |dx| = 100.
  const double half = std::asin(100.0 / 250.0);  // each rod's angle from the vertical
  const double eps = 2 * half;                    // angle between the rods
  EXPECT_NEAR(e.pressure_angle_deg[0], std::acos(std::sin(eps)) * 180 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(e.reactions_N[0], 100.0 / std::sin(eps), 1e-9);
  // Reactions against a direct linear solve of the statics for random loads.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> ang(0, 2 * std::numbers::pi);
  double worst = 0;
  const double p = e.joints[0];
  const Eigen::Vector2d z1 = Eigen::Vector2d(0 - (-100), -300 - (-p)).normalized();
  const Eigen::Vector2d z2 = Eigen::Vector2d(0 - 100, -300 - (-p)).normalized();
  Eigen::Matrix2d Z;
  Z << z1, z2;
  for (int k = 0; k < 2000; ++k) {
    const double t = ang(rng);
    const Eigen::Vector2d w(100 * std::cos(t), 100 * std::sin(t));
    worst = std::max(worst, std::abs(Z.colPivHouseholderQr().solve(-w)(0)));
  }
  EXPECT_LE(worst, e.reactions_N[0] * (1 + 1e-12));
  EXPECT_GE(worst, e.reactions_N[0] * (1 - 1e-4));
}

TEST(MomaCore, SingleBandAreaAndM1AreaInClosedForm) {
  // One band: 2 l h exactly, at any guide angle (rational direction).
  for (double gamma : {-5.0, 0.0, 5.0}) {
    const Moma m = m1(250, gamma);
    const auto band = geometry::band(m.slider(0, 0), m.legs()[0].guide_angle, 200, 250, 1);
    EXPECT_NEAR(band.area(), 2 * 250 * 200, 1e-10 * 2 * 250 * 200);
  }
  // M1, gamma = 0: for x in (-x*, x*) the two bands overlap in a vertical chord
  // of length 200 - |s1 - s2|, s_i = sqrt(l^2 - (x -+ 100)^2); by symmetry
  // A = 2 [200 x* + (F(x*+100) - F(100)) - (F(x*-100) - F(-100))], where x* solves
  // s2 - s1 = 200 (docs/theory/moma.md).
  const double l = 250;
  auto g = [&](double x) { return std::sqrt(l * l - (x - 100) * (x - 100)) - std::sqrt(l * l - (x + 100) * (x + 100)) - 200; };
  double lo = 0, hi = 150;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  const double xs = 0.5 * (lo + hi);
  const double closed = 2 * (200 * xs + (F(xs + 100, l) - F(100, l)) - (F(xs - 100, l) - F(-100, l)));
  const double exact = m1().workspace().area();
  EXPECT_NEAR(exact, closed, 1e-12 * closed);
  EXPECT_NEAR(exact, 36202.1833253496, 1e-9);
}

TEST(MomaCore, MembershipAgreesWithTheExactRegion) {
  std::mt19937 rng(9);
  for (const char* name : {"moma_m1_g0_l250.json", "moma_m3_l195.json", "moma_m5_gp5_gm5_l195.json"}) {
    const auto mech = io::load_mechanism(std::string(PKMWS_SOURCE_DIR) + "/datasets/" + name);
    const auto ws = mech.model->workspace();
    const auto b = ws.bbox();
    std::uniform_real_distribution<double> x(b.min.x, b.max.x), y(b.min.y, b.max.y);
    int inside = 0;
    for (int k = 0; k < 1500; ++k) {
      const mechanisms::Pose p{x(rng), y(rng), 0};
      const bool exact = ws.contains({p.x, p.y});
      inside += exact;
      EXPECT_EQ(mech.model->reachable(p), exact) << name << " at " << p.x << ", " << p.y;
    }
    EXPECT_GT(inside, 100) << name;
  }
}

TEST(MomaCore, M3WorkspaceLiesMostlyInQuadrantThree) {
  const auto mech = io::load_mechanism(std::string(PKMWS_SOURCE_DIR) + "/datasets/moma_m3_l250.json");
  const auto ws = mech.model->workspace();
  const double q3 = ws.intersect(geometry::rectangle({{-1000, -1000}, {0, 0}})).area();
  EXPECT_GT(q3, 0.7 * ws.area());  // 74.7 % for l = 250
  const auto m2 = io::load_mechanism(std::string(PKMWS_SOURCE_DIR) + "/datasets/moma_m2_l250.json");
  const auto ws2 = m2.model->workspace();
  EXPECT_GT(ws2.intersect(geometry::rectangle({{0, 0}, {1000, 1000}})).area(), 0.75 * ws2.area());
}

TEST(MomaCore, LoaderErrorsNameTheField) {
  const std::string good = R"({"name": "t", "mechanism": "moma", "units": "mm", "legs": [
    {"reference": [-100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1},
    {"reference": [100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1}]})";
  EXPECT_NO_THROW(io::parse_mechanism(nlohmann::json::parse(good), "t"));
  auto expect_error = [&](const std::string& from, const std::string& to, const std::string& needle) {
    std::string bad = good;
    bad.replace(bad.find(from), from.size(), to);
    try {
      io::parse_mechanism(nlohmann::json::parse(bad), "t");
      ADD_FAILURE() << "no error for " << to;
    } catch (const io::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error("\"rod_length\": 250, \"branch\": -1}]", "\"rod_length\": -250, \"branch\": -1}]", "legs[1].rod_length");
  expect_error("\"branch\": -1}]", "\"branch\": 2}]", "legs[1].branch");
  expect_error("\"stroke\": [0, 200]", "\"stroke\": [200, 0]", "legs[0].stroke");
  expect_error("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 270, \"foo\": 1", "legs[0].foo: unknown field");
  expect_error("\"units\": \"mm\"", "\"units\": \"ft\"", "units");
  expect_error("\"legs\": [", "\"legz\": [", "legs: missing");
  expect_error("\"reference\": [-100, 0]", "\"reference\": [-100]", "legs[0].reference");
  expect_error("\"mechanism\": \"moma\"", "\"mechanism\": \"hexapod\"", "mechanism");
}
