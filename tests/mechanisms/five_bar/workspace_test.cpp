// Five-bar 5R workspace ([Briot], DexTAR): the exact region against closed forms
// (lens, annuli, crank-limited legs), the point test, Π-joint drives.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/LU>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/five_bar/five_bar.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/five_bar.hpp"

using namespace pkmws;
using namespace pkmws::test::five_bar;
using geometry::Point;
using mechanisms::FiveBar;
using mechanisms::FiveBarLeg;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

// Area of the intersection of two disks of radii r1, r2 with centres d apart.
double lens(double r1, double r2, double d) {
  if (r1 <= 0.0 || r2 <= 0.0 || d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) return pi * std::min(r1, r2) * std::min(r1, r2);
  const double a1 = std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1));
  const double a2 = std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
  return r1 * r1 * a1 + r2 * r2 * a2 -
         0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
}

// Two annuli (inner i, outer o) with centres d apart, by inclusion-exclusion.
double annuli(double i1, double o1, double i2, double o2, double d) {
  return lens(o1, o2, d) - lens(i1, o2, d) - lens(o1, i2, d) + lens(i1, i2, d);
}

}  // namespace

TEST(FiveBarWorkspace, DexTARAreaEqualsTheLensClosedForm) {
  // Two disks of radius 2l = 0.46 m with centres 2a = 0.275 m apart.
  const double R = 2 * L, d = 2 * A;
  const double closed = 2 * R * R * std::acos(d / (2 * R)) - 0.5 * d * std::sqrt(4 * R * R - d * d);
  EXPECT_NEAR(closed, lens(R, R, d), 1e-16);
  for (const char* tag : {"pp", "pm", "mp", "mm"}) {
    const auto f = io::load_mechanism(dataset(std::string("five_bar_dextar_") + tag));
    const auto ws = f.model->workspace();
    EXPECT_LE(std::abs(ws.area() - closed), 1e-13 * closed) << tag << " " << ws.area() << " " << closed;
    EXPECT_EQ(ws.components().size(), 1u);
  }
}

TEST(FiveBarWorkspace, UnequalLinksGiveTheIntersectionOfTwoAnnuli) {
  for (const auto& [l1, l2, a] : {std::tuple{0.3, 0.2, 0.1}, {0.2, 0.3, 0.12}, {0.25, 0.1, 0.05}}) {
    const FiveBar m({FiveBarLeg{{-a, 0}, l1, l2, 1, {}, {}}, FiveBarLeg{{a, 0}, l1, l2, -1, {}, {}}});
    const double closed = annuli(std::abs(l1 - l2), l1 + l2, std::abs(l1 - l2), l1 + l2, 2 * a);
    const double area = m.workspace().area();
    EXPECT_LE(std::abs(area - closed), 1e-13 * closed) << l1 << " " << l2 << " " << area << " " << closed;
  }
}

TEST(FiveBarWorkspace, CrankLimitedLegAreaIsSpanTimesTwoL1L2) {
  // In polar coordinates about A the leg covers, at every radius ρ, an angular
  // interval of width Δ = max - min: area = Δ (r_out² - r_in²) / 2 = 2 Δ l1 l2.
  for (const auto& [l1, l2] : {std::pair{0.23, 0.23}, {0.3, 0.2}, {0.17, 0.23}}) {
    for (int s : {1, -1}) {
      for (const auto& [lo, hi] : {std::pair{30.0, 150.0}, {-100.0, 130.0}, {200.0, 215.0}, {-10.0, 300.0}}) {
        FiveBarLeg leg{{-0.1, 0.05}, l1, l2, s, std::array<double, 2>{lo * deg, hi * deg}, {}};
        const FiveBar m({leg, FiveBarLeg{{0.1, 0}, l1, l2, 1, {}, {}}});
        const double closed = 2 * (hi - lo) * deg * l1 * l2;
        const double area = m.leg_workspace(0).area();
        EXPECT_LE(std::abs(area - closed), 1e-12 * closed)
            << l1 << " " << l2 << " s=" << s << " [" << lo << ", " << hi << "] " << area << " vs " << closed;
      }
    }
  }
}

TEST(FiveBarWorkspace, CrankLimitedRegionAgreesWithThePointTest) {
  std::mt19937 rng(5);
  for (const auto& [l1, l2] : {std::pair{0.23, 0.23}, {0.3, 0.2}, {0.17, 0.23}}) {
    FiveBarLeg leg1{{-0.1, 0}, l1, l2, 1, std::array<double, 2>{40 * deg, 170 * deg}, {}};
    FiveBarLeg leg2{{0.1, 0}, l1, l2, -1, std::array<double, 2>{-20 * deg, 140 * deg}, {}};
    const FiveBar m({leg1, leg2});
    const auto ws = m.workspace();
    ASSERT_GT(ws.area(), 0.0);
    const double r = l1 + l2;
    std::uniform_real_distribution<double> ux(-0.1 - r, 0.1 + r), uy(-r, r);
    int inside = 0, checked = 0;
    for (int n = 0; n < 2000; ++n) {
      const Point c{ux(rng), uy(rng)};
      const bool in = m.reachable({c.x, c.y, 0});
      // Skip points within 1e-7 of the boundary (the point test changes nearby).
      bool stable = true;
      for (const Point e : {Point{1e-7, 0}, Point{-1e-7, 0}, Point{0, 1e-7}, Point{0, -1e-7}}) {
        stable = stable && m.reachable({c.x + e.x, c.y + e.y, 0}) == in;
      }
      if (!stable) continue;
      ++checked;
      inside += in;
      EXPECT_EQ(ws.contains(c), in) << c.x << " " << c.y;
    }
    EXPECT_GT(inside, 50);
    EXPECT_GT(checked, 1950);
  }
}

TEST(FiveBarWorkspace, PiJointDrivesLimitTheCranksThroughTheirStroke) {
  const auto f = io::load_mechanism(dataset("five_bar_pi_joint"));
  const auto& m = dynamic_cast<const FiveBar&>(*f.model);
  ASSERT_TRUE(m.legs()[0].pi_joint && m.legs()[1].pi_joint);
  // [Milutinovic] eq. 3-5 at d = 117 and 232 mm with a = 170 mm, k = 0.4.
  const mechanisms::PiJointKinematics kin{170.0, 0.4};
  const double t_lo = *kin.angle(117.0), t_hi = *kin.angle(232.0);
  EXPECT_NEAR(t_lo / deg, -59.08, 0.01);
  EXPECT_NEAR(t_hi / deg, 61.40, 0.01);
  const auto lim1 = *m.crank_limits(0), lim2 = *m.crank_limits(1);
  EXPECT_NEAR(lim1[0], pi / 2 + t_lo, 1e-15);
  EXPECT_NEAR(lim1[1], pi / 2 + t_hi, 1e-15);
  EXPECT_NEAR(lim2[0], pi / 2 - t_hi, 1e-15);
  EXPECT_NEAR(lim2[1], pi / 2 - t_lo, 1e-15);
  EXPECT_EQ(m.joints()[0].name, "d1");
  EXPECT_FALSE(m.joints()[1].angle);

  // Leg 2 mirrors leg 1: the workspace is symmetric about x = 0.
  const auto ws = m.workspace();
  const geometry::Box clip{{-1000, -1000}, {1000, 1000}};
  const double left = ws.intersect(geometry::half_plane({0, 0}, pi, clip)).area();
  const double right = ws.intersect(geometry::half_plane({0, 0}, 0.0, clip)).area();
  EXPECT_NEAR(left, right, 1e-10 * ws.area());
  EXPECT_NEAR(left + right, ws.area(), 1e-10 * ws.area());

  // IK gives d in the stroke; DK from d finds C; dd/dC against finite differences.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> ux(-300, 300), uy(-100, 350);
  int tested = 0;
  for (int n = 0; n < 3000 && tested < 60; ++n) {
    const Point c{ux(rng), uy(rng)};
    if (!m.reachable({c.x, c.y, 0})) continue;
    const auto ik = m.inverse({c.x, c.y, 0});
    ASSERT_TRUE(ik[0].valid);
    for (double d : ik[0].joints) {
      EXPECT_GE(d, 117.0 - 1e-9);
      EXPECT_LE(d, 232.0 + 1e-9);
    }
    int found = 0;
    for (const auto& s : m.direct(ik[0].joints)) found += s.valid && norm(Point{s.pose.x, s.pose.y} - c) < 1e-9;
    EXPECT_EQ(found, 1);
    const auto e = m.evaluate({c.x, c.y, 0}, {}).front();
    if (e.singular || e.condition_number > 1e4) continue;
    const double h = 1e-4;
    Eigen::Matrix2d fd;
    for (int col = 0; col < 2; ++col) {
      const Point dc = col == 0 ? Point{h, 0} : Point{0, h};
      const auto p = m.inverse({c.x + dc.x, c.y + dc.y, 0})[0].joints;
      const auto q = m.inverse({c.x - dc.x, c.y - dc.y, 0})[0].joints;
      fd(0, col) = (p[0] - q[0]) / (2 * h);
      fd(1, col) = (p[1] - q[1]) / (2 * h);
    }
    EXPECT_NEAR(e.jacobian_det, fd.determinant(), 1e-6 * std::abs(fd.determinant()) + 1e-9);
    ++tested;
  }
  EXPECT_GE(tested, 30);
  // Region and point test agree away from the boundary.
  std::mt19937 rng2(10);
  for (int n = 0; n < 2000; ++n) {
    const Point c{ux(rng2), uy(rng2)};
    const bool in = m.reachable({c.x, c.y, 0});
    bool stable = true;
    for (const Point e : {Point{1e-4, 0}, Point{-1e-4, 0}, Point{0, 1e-4}, Point{0, -1e-4}}) {
      stable = stable && m.reachable({c.x + e.x, c.y + e.y, 0}) == in;
    }
    if (stable) {
      EXPECT_EQ(ws.contains(c), in) << c.x << " " << c.y;
    }
  }
}
