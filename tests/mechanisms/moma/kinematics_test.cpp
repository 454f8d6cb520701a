// MOMA kinematics ([Vasilic], docs/theory/moma.md): IK/DK round trips, working
// and assembly modes, the paper's closed form (eq. 9-12) against the robust DK.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/moma/moma.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/moma.hpp"

using namespace pkmws;
using namespace pkmws::test::moma;
using geometry::Point;
using mechanisms::Moma;
using mechanisms::MomaLeg;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;

}  // namespace

TEST(MomaKinematics, InverseLegSolvesEq3OnTheBranchSide) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-400, 400);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int k = 0; k < 50; ++k) {
      const Point p{u(rng), u(rng)};
      for (int i = 0; i < 2; ++i) {
        for (int branch : {-1, 1}) {
          const auto q = m.inverse_leg(i, p, branch);
          const double l = m.legs()[i].rod_length;
          const Point a = m.guide_direction(i), w = p - m.legs()[i].reference;
          if (!q) {
            EXPECT_GT(std::abs(cross(a, w)), l * (1 - 1e-12));  // out of the rod's reach
            continue;
          }
          // [Vasilic] eq. 3: p^2 - 2 p a.w + |w|^2 - l^2 = 0, i.e. |P - S| = l.
          const Point s = m.slider(i, *q);
          EXPECT_NEAR(distance(p, s), l, 1e-12 * (l + norm(w)));
          // Branch -1 (eq. 5): P ahead of the slider, a.(P - S) >= 0; +1 behind.
          EXPECT_GE(-branch * dot(a, p - s), -1e-12 * (l + norm(w)));
        }
      }
    }
  }
}

TEST(MomaKinematics, InverseThenDirectRoundTripInEveryConfiguration) {
  std::mt19937 rng(2024);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    const auto poses = reachable_samples(m, rng, 40);
    ASSERT_GE(poses.size(), 20u) << f;
    for (const Point p : poses) {
      const auto ik = m.inverse({p.x, p.y, 0});
      ASSERT_EQ(ik.size(), 4u);
      ASSERT_TRUE(ik[0].valid) << f << ": " << ik[0].reason;  // the file's working mode
      int found = 0;
      for (const auto& s : m.direct(ik[0].joints)) {
        if (distance({s.pose.x, s.pose.y}, p) < 1e-9 * 250) {
          ++found;
          EXPECT_TRUE(s.valid) << f << ": " << s.reason;
        }
      }
      EXPECT_EQ(found, 1) << f << " at " << p.x << ", " << p.y;
    }
  }
}

TEST(MomaKinematics, DirectThenInverseRoundTripInEveryConfiguration) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    int checked = 0;
    for (int k = 0; k < 300 && checked < 40; ++k) {
      const std::vector<double> q{u(rng), u(rng)};
      for (const auto& s : m.direct(q)) {
        // Every assembly mode lies on both rod circles ...
        for (int i = 0; i < 2; ++i) {
          EXPECT_NEAR(distance({s.pose.x, s.pose.y}, m.slider(i, q[i])), m.legs()[i].rod_length, 1e-9 * 250);
        }
        if (!s.valid) continue;
        // ... and the valid ones give back the joints through the file's branches.
        const auto ik = m.inverse(s.pose);
        ASSERT_TRUE(ik[0].valid) << f << ": " << ik[0].reason;
        EXPECT_NEAR(ik[0].joints[0], q[0], 1e-9 * 250) << f;
        EXPECT_NEAR(ik[0].joints[1], q[1], 1e-9 * 250) << f;
        EXPECT_TRUE(m.reachable(s.pose) || std::min({q[0], q[1], 200 - q[0], 200 - q[1]}) < 1e-9) << f;
        ++checked;
      }
    }
    EXPECT_GE(checked, 10) << f;
  }
}

TEST(MomaKinematics, EveryWorkingModeIsAnAssemblyModeOfItsJoints) {
  std::mt19937 rng(5);
  for (const char* stem : {"moma_m1_g0_l250", "moma_m2_l195", "moma_m3_l180", "moma_m5_gp5_gm5_l195"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    const auto box = m.bounds();
    std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
      const Point p{x(rng), y(rng)};
      for (const auto& s : m.inverse({p.x, p.y, 0})) {
        if (s.joints.size() != 2) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& a : m.direct_all(s.joints[0], s.joints[1])) best = std::min(best, distance(a.platform, p));
        EXPECT_LT(best, 1e-7) << stem << " " << s.mode << " at " << p.x << ", " << p.y;
        ++checked;
      }
    }
    EXPECT_GT(checked, 200) << stem;
  }
}

TEST(MomaKinematics, InverseListsTheFilesWorkingModeFirst) {
  const Moma m = m1();
  // A pose well inside the workspace: only the file's mode (-1,-1) is valid;
  // the other roots are either outside the stroke or another working mode.
  const auto ik = m.inverse({0, -300, 0});
  ASSERT_EQ(ik.size(), 4u);
  EXPECT_EQ(ik[0].mode, "--");
  EXPECT_TRUE(ik[0].valid);
  EXPECT_TRUE(ik[0].reason.empty());
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_FALSE(ik[k].valid) << ik[k].mode;
    EXPECT_FALSE(ik[k].reason.empty());
  }
  std::vector<std::string> modes;
  for (const auto& s : ik) modes.push_back(s.mode);
  std::sort(modes.begin(), modes.end());
  EXPECT_EQ(modes, (std::vector<std::string>{"++", "+-", "-+", "--"}));
  // With a long stroke the other roots fall inside it: flagged as another working mode.
  const Moma long_stroke = m1(250, 0, 1000);
  for (const auto& s : long_stroke.inverse({0, -300, 0})) {
    if (s.mode == "--") continue;
    EXPECT_FALSE(s.valid);
    EXPECT_NE(s.reason.find("working mode"), std::string::npos) << s.reason;
  }
  // Out of the stroke: the reason says which joint.
  const auto far = m.inverse({0, -480, 0});
  EXPECT_FALSE(far[0].valid);
  EXPECT_NE(far[0].reason.find("outside stroke"), std::string::npos) << far[0].reason;
  // Out of the rods' reach: no joints.
  const auto none = m.inverse({1000, 0, 0});
  for (const auto& s : none) {
    EXPECT_FALSE(s.valid);
    EXPECT_TRUE(s.joints.empty());
  }
}

TEST(MomaKinematics, DirectFlagsTheAssemblyModeOnTheWrongSide) {
  const Moma m = m1();
  const std::vector<double> q{50, 80};
  const auto sols = m.direct(q);
  ASSERT_EQ(sols.size(), 2u);
  for (const auto& s : sols) {
    // Branch -1 with guides pointing down: P must lie below both sliders.
    const bool below = s.pose.y < -50 && s.pose.y < -80;
    EXPECT_EQ(s.valid, below) << s.mode << " " << s.reason;
    if (!below) {
      EXPECT_NE(s.reason.find("branch"), std::string::npos);
    }
    // Assembly mode sign = sign of cross(S2 - S1, P - S1).
    const double side = cross(m.slider(1, q[1]) - m.slider(0, q[0]), Point{s.pose.x, s.pose.y} - m.slider(0, q[0]));
    EXPECT_EQ(s.mode, side > 0 ? "+" : "-");
  }
  // Joints outside the stroke: every assembly mode invalid.
  for (const auto& s : m.direct(std::vector<double>{50, 210})) {
    EXPECT_FALSE(s.valid);
    EXPECT_NE(s.reason.find("stroke"), std::string::npos);
  }
  EXPECT_THROW(m.direct(std::vector<double>{1.0}), std::invalid_argument);
}

TEST(MomaKinematics, CircleIntersectionDegenerateCases) {
  // Tangent circles (rods aligned): |S1S2| = l1 + l2 = 500 with S1 = (-100, 0),
  // S2 = (100, -p2), p2 = sqrt(500^2 - 200^2).
  const Moma m = m1(250, 0, 1000);
  const double p2 = std::sqrt(500.0 * 500.0 - 200.0 * 200.0);
  const auto tangent = m.direct_all(0, p2);
  ASSERT_EQ(tangent.size(), 1u);
  EXPECT_EQ(tangent[0].sign, 0);
  EXPECT_NEAR(distance(tangent[0].platform, {0, -p2 / 2}), 0.0, 1e-9);
  EXPECT_EQ(m.direct_all(0, p2 - 1).size(), 2u);
  EXPECT_EQ(m.direct_all(0, p2 + 1).size(), 0u);
  // Internally tangent: l1 = 300, l2 = 100, |S1S2| = 200 (p1 = p2 = 0).
  const Moma unequal({MomaLeg{{-100, 0}, 1.5 * pi, 0, 200, 300, -1}, MomaLeg{{100, 0}, 1.5 * pi, 0, 200, 100, -1}});
  const auto inner = unequal.direct_all(0, 0);
  ASSERT_EQ(inner.size(), 1u);
  EXPECT_NEAR(distance(inner[0].platform, {200, 0}), 0.0, 1e-9);
  // Coincident centres: no isolated assembly mode (no division by zero either).
  const Moma crossing({MomaLeg{{0, 0}, 0.0, 0, 200, 100, -1}, MomaLeg{{100, -100}, 0.5 * pi, 0, 200, 100, -1}});
  EXPECT_TRUE(crossing.direct_all(100, 100).empty());  // both sliders at (100, 0)
  // One circle inside the other (|S1S2| = 10 < l1 - l2 = 70), or concentric with
  // different radii: none.
  const Moma nested({MomaLeg{{0, 0}, 0.0, 0, 200, 100, -1}, MomaLeg{{100, -100}, 0.5 * pi, 0, 200, 30, -1}});
  EXPECT_TRUE(nested.direct_all(100, 90).empty());
  EXPECT_TRUE(nested.direct_all(100, 100).empty());
  EXPECT_EQ(nested.direct_all(100, 30).size(), 1u);  // internally tangent: |S1S2| = 70
}

TEST(MomaKinematics, ClosedFormAgreesWithTheRobustDkWhereDefined) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  int compared = 0;
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int k = 0; k < 40; ++k) {
      const double p1 = u(rng), p2 = u(rng);
      const auto all = m.direct_all(p1, p2);
      for (int sign : {-1, 1}) {
        const auto cf = m.direct_closed_form(p1, p2, sign);
        if (!cf) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& a : all) best = std::min(best, distance(a.platform, *cf));
        EXPECT_LE(best, 1e-9 * (norm(*cf) + 250)) << f << " p = " << p1 << ", " << p2;
        ++compared;
      }
      // Where the DK has two assembly modes and eq. 12 is defined, eq. 10's two
      // signs give both of them.
      if (all.size() == 2 && m.direct_closed_form(p1, p2, 1) && m.direct_closed_form(p1, p2, -1)) {
        EXPECT_GT(distance(*m.direct_closed_form(p1, p2, 1), *m.direct_closed_form(p1, p2, -1)), 1e-6);
      }
    }
  }
  EXPECT_GT(compared, 2000);
}

TEST(MomaKinematics, M2AtP2Equal50DefeatsTheClosedFormButNotTheRobustDk) {
  const auto mech = io::load_mechanism(dataset("moma_m2_l250"));
  const Moma& m = as_moma(mech);
  // Slider 1 at (50, p1), slider 2 at (p2, 50): at p2 = 50 both have x = 50 and
  // v4 = v1 in [Vasilic] eq. 12. The rods' circles meet at y = (p1 + 50) / 2,
  // x = 50 +- sqrt(250^2 - ((p1 - 50) / 2)^2); branch -1 needs P above slider 1
  // (p1 <= 50) and right of slider 2 (the + root): one valid mode for p1 < 50,
  // none for p1 > 50 (coincident sliders at p1 = 50: no isolated solution).
  for (double p1 : {0.0, 10.0, 40.0, 120.0, 200.0}) {
    EXPECT_FALSE(m.direct_closed_form(p1, 50.0, 1).has_value());
    EXPECT_FALSE(m.direct_closed_form(p1, 50.0, -1).has_value());
    const auto sols = m.direct(std::vector<double>{p1, 50.0});
    int valid = 0;
    for (const auto& s : sols) {
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(distance({s.pose.x, s.pose.y}, m.slider(i, i == 0 ? p1 : 50.0)), 250.0, 1e-9);
      }
      if (!s.valid) continue;
      ++valid;
      EXPECT_NEAR(s.pose.x, 50 + std::sqrt(250.0 * 250.0 - (p1 - 50) * (p1 - 50) / 4), 1e-9);
      EXPECT_NEAR(s.pose.y, (p1 + 50) / 2, 1e-9);
      const auto ik = m.inverse(s.pose);
      EXPECT_NEAR(ik[0].joints[0], p1, 1e-9);
      EXPECT_NEAR(ik[0].joints[1], 50.0, 1e-9);
    }
    EXPECT_EQ(sols.size(), 2u);
    EXPECT_EQ(valid, p1 < 50 ? 1 : 0) << "p1 = " << p1;
  }
  EXPECT_TRUE(m.direct(std::vector<double>{50.0, 50.0}).empty());
  // The robust DK is continuous through p2 = 50 (the platform moves by about dp2).
  const auto at = m.direct(std::vector<double>{10.0, 50.0});
  for (double dp : {-1e-9, 1e-9}) {
    const auto moved = m.direct(std::vector<double>{10.0, 50.0 + dp});
    ASSERT_EQ(moved.size(), at.size());
    for (std::size_t k = 0; k < at.size(); ++k) {
      EXPECT_EQ(moved[k].mode, at[k].mode);
      EXPECT_LT(distance({moved[k].pose.x, moved[k].pose.y}, {at[k].pose.x, at[k].pose.y}), 1e-7);
    }
  }
}

TEST(MomaKinematics, ThePapersFixedSignOfEq10PicksTheWrongModeInM2AboveP2Equal50) {
  // [Vasilic] eq. 10 uses "+" for M2. Just above p2 = 50 the line S1S2 tilts the
  // other way and the valid platform (right of slider 2, above slider 1) is the
  // intersection with the smaller y: p1 = 10, p2 = 52 gives P ~ (299.9, 17.6).
  const auto mech = io::load_mechanism(dataset("moma_m2_l250"));
  const Moma& m = as_moma(mech);
  const std::vector<double> q{10.0, 52.0};
  const auto sols = m.direct(q);
  const auto valid = std::find_if(sols.begin(), sols.end(), [](const auto& s) { return s.valid; });
  ASSERT_NE(valid, sols.end());
  EXPECT_NEAR(valid->pose.x, 299.9, 0.1);
  EXPECT_NEAR(valid->pose.y, 17.6, 0.1);
  const auto paper = m.direct_closed_form(q[0], q[1], +1);
  const auto other = m.direct_closed_form(q[0], q[1], -1);
  ASSERT_TRUE(paper && other);
  EXPECT_GT(distance(*paper, {valid->pose.x, valid->pose.y}), 100.0);
  EXPECT_LT(distance(*other, {valid->pose.x, valid->pose.y}), 1e-9 * 300);
  // Below p2 = 50 the paper's sign is the valid mode.
  const auto below = m.direct(std::vector<double>{10.0, 48.0});
  const auto valid_below = std::find_if(below.begin(), below.end(), [](const auto& s) { return s.valid; });
  ASSERT_NE(valid_below, below.end());
  EXPECT_LT(distance(*m.direct_closed_form(10.0, 48.0, +1), {valid_below->pose.x, valid_below->pose.y}), 1e-9 * 300);
}
