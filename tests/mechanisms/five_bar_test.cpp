// Five-bar 5R ([Briot], DexTAR): IK/DK round trips in every working and
// assembly mode, Jacobians against finite differences, the mirror symmetries of
// the four working modes, pressure angle and reactions against statics, the
// type-2 curves, the exact workspace against closed forms (lens, annuli,
// crank-limited legs), Π-joint drives and loader errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/LU>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "../support/load_error.hpp"
#include "mechanisms/five_bar/five_bar.hpp"

using namespace pkmws;
using geometry::Point;
using mechanisms::FiveBar;
using mechanisms::FiveBarLeg;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;
constexpr double L = 0.23, A = 0.1375;  // DexTAR ([Briot])

std::string dataset(const std::string& stem) { return std::string(PKMWS_SOURCE_DIR) + "/datasets/" + stem + ".json"; }

FiveBar dextar(int s1, int s2) {
  return FiveBar({FiveBarLeg{{-A, 0}, L, L, s1, {}, {}}, FiveBarLeg{{A, 0}, L, L, s2, {}, {}}});
}

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

Point random_in_lens(std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(-0.32, 0.32), uy(-0.42, 0.42);
  for (;;) {
    const Point c{ux(rng), uy(rng)};
    if (norm(c - Point{-A, 0}) < 2 * L - 1e-3 && norm(c - Point{A, 0}) < 2 * L - 1e-3 &&
        norm(c - Point{-A, 0}) > 1e-3 && norm(c - Point{A, 0}) > 1e-3) {
      return c;
    }
  }
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * pi)); }

io::MechanismFile parse(const nlohmann::json& doc) { return io::parse_mechanism(doc, "test"); }

nlohmann::json dextar_doc() {
  return {{"name", "t"},
          {"mechanism", "five_bar"},
          {"units", "m"},
          {"base", {{-A, 0.0}, {A, 0.0}}},
          {"proximal", {L, L}},
          {"distal", {L, L}},
          {"working_mode", {1, -1}}};
}

using pkmws::test::load_error;

}  // namespace

TEST(FiveBarKinematics, DexTARDatasetsCarryTheirWorkingModes) {
  for (const auto& [tag, s1, s2] : {std::tuple{"pp", 1, 1}, {"pm", 1, -1}, {"mp", -1, 1}, {"mm", -1, -1}}) {
    const auto f = io::load_mechanism(dataset(std::string("five_bar_dextar_") + tag));
    const auto& m = dynamic_cast<const FiveBar&>(*f.model);
    EXPECT_EQ(m.legs()[0].working_mode, s1);
    EXPECT_EQ(m.legs()[1].working_mode, s2);
    EXPECT_EQ(m.legs()[0].proximal, L);
    EXPECT_EQ(m.legs()[1].base.x, A);
    EXPECT_NE(f.source.dump().find("[Briot]"), std::string::npos);
    // The file's working mode comes first and is the valid one.
    const auto sol = m.inverse({0.05, 0.2, 0.0});
    ASSERT_EQ(sol.size(), 4u);
    EXPECT_TRUE(sol[0].valid);
    EXPECT_EQ(sol[0].mode, std::string(1, s1 > 0 ? '+' : '-') + (s2 > 0 ? '+' : '-'));
    for (std::size_t k = 1; k < 4; ++k) EXPECT_FALSE(sol[k].valid) << sol[k].reason;
  }
}

TEST(FiveBarKinematics, InverseThenDirectRoundTripInEveryWorkingAndAssemblyMode) {
  std::mt19937 rng(4);
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      for (int n = 0; n < 200; ++n) {
        const Point c = random_in_lens(rng);
        const auto q1 = m.inverse_leg(0, c, s1), q2 = m.inverse_leg(1, c, s2);
        ASSERT_TRUE(q1 && q2);
        // The elbows are where the working mode says.
        EXPECT_EQ(FiveBar::working_mode_sign({-A, 0}, m.elbow(0, *q1), c), s1);
        EXPECT_EQ(FiveBar::working_mode_sign({A, 0}, m.elbow(1, *q2), c), s2);
        EXPECT_NEAR(norm(c - m.elbow(0, *q1)), L, 1e-14);
        EXPECT_NEAR(norm(c - m.elbow(1, *q2)), L, 1e-14);
        // DK gives both assembly modes; one is C, and every assembly maps back
        // to the same joints through IK in its own working mode.
        const auto assemblies = m.direct_all(*q1, *q2);
        double best = 1.0;
        for (const auto& a : assemblies) {
          best = std::min(best, norm(a.tool - c));
          const int t1 = FiveBar::working_mode_sign({-A, 0}, a.elbows[0], a.tool);
          const int t2 = FiveBar::working_mode_sign({A, 0}, a.elbows[1], a.tool);
          const auto r1 = m.inverse_leg(0, a.tool, t1), r2 = m.inverse_leg(1, a.tool, t2);
          ASSERT_TRUE(r1 && r2);
          EXPECT_LT(angle_diff(*r1, *q1), 1e-9);
          EXPECT_LT(angle_diff(*r2, *q2), 1e-9);
        }
        EXPECT_LT(best, 1e-12);
        // Through the Mechanism interface: the file's mode is valid and DK finds C.
        const auto ik = m.inverse({c.x, c.y, 0.0});
        ASSERT_TRUE(ik[0].valid) << ik[0].reason;
        const auto dk = m.direct(ik[0].joints);
        int valid_at_c = 0;
        for (const auto& s : dk) valid_at_c += s.valid && norm(Point{s.pose.x, s.pose.y} - c) < 1e-12;
        EXPECT_EQ(valid_at_c, 1);
      }
    }
  }
}

TEST(FiveBarKinematics, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(7);
  const double h = 1e-6;
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      int tested = 0;
      for (int n = 0; n < 50; ++n) {
        const Point c = random_in_lens(rng);
        const double q1 = *m.inverse_leg(0, c, s1), q2 = *m.inverse_leg(1, c, s2);
        const auto j = m.jacobians(c, q1, q2);
        // Away from singularities (|sin| of the link angles above ~0.2).
        if (std::abs(j.B(0, 0)) < 0.01 || std::abs(j.B(1, 1)) < 0.01 || std::abs(j.A.determinant()) < 0.01) continue;
        const Eigen::Matrix2d jq = j.B.inverse() * j.A;
        Eigen::Matrix2d fd;
        for (int col = 0; col < 2; ++col) {
          const Point e = col == 0 ? Point{h, 0} : Point{0, h};
          for (int leg = 0; leg < 2; ++leg) {
            const int s = leg == 0 ? s1 : s2;
            const double qp = *m.inverse_leg(leg, c + e, s), qm = *m.inverse_leg(leg, c - e, s);
            fd(leg, col) = std::remainder(qp - qm, 2 * pi) / (2 * h);
          }
        }
        EXPECT_LT((jq - fd).norm(), 1e-6 * std::max(1.0, jq.norm())) << jq << "\n" << fd;
        // The A matrix alone: A (dC/dq) = B for the DK (columns: moving one crank).
        Eigen::Matrix2d dc;
        for (int col = 0; col < 2; ++col) {
          const double dq1 = col == 0 ? h : 0.0, dq2 = col == 1 ? h : 0.0;
          Point cp, cm;
          for (const auto& a : m.direct_all(q1 + dq1, q2 + dq2)) if (norm(a.tool - c) < 1e-4) cp = a.tool;
          for (const auto& a : m.direct_all(q1 - dq1, q2 - dq2)) if (norm(a.tool - c) < 1e-4) cm = a.tool;
          dc(0, col) = (cp.x - cm.x) / (2 * h);
          dc(1, col) = (cp.y - cm.y) / (2 * h);
        }
        EXPECT_LT((j.A * dc - j.B).norm(), 1e-7 * j.B.norm());
        // evaluate() reports the same determinant.
        const auto ev = m.evaluate({c.x, c.y, 0.0}, {});
        EXPECT_NEAR(ev[0].jacobian_det, fd.determinant(), 1e-5 * std::abs(fd.determinant()) + 1e-9);
        ++tested;
      }
      EXPECT_GE(tested, 20);
    }
  }
}

TEST(FiveBarKinematics, WorkingModesObeyTheMirrorSymmetries) {
  // DexTAR is symmetric about x = 0 (the mirror swaps the legs and flips the
  // working modes: (s1, s2) -> (-s2, -s1), q1' = π - q2) and about y = 0
  // ((s1, s2) -> (-s1, -s2), q' = -q).
  std::mt19937 rng(11);
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      const FiveBar mx = dextar(-s2, -s1), my = dextar(-s1, -s2);
      for (int n = 0; n < 100; ++n) {
        const Point c = random_in_lens(rng);
        const Point cx{-c.x, c.y}, cy{c.x, -c.y};
        const double q1 = *m.inverse_leg(0, c, s1), q2 = *m.inverse_leg(1, c, s2);
        EXPECT_LT(angle_diff(*mx.inverse_leg(0, cx, -s2), pi - q2), 1e-12);
        EXPECT_LT(angle_diff(*mx.inverse_leg(1, cx, -s1), pi - q1), 1e-12);
        EXPECT_LT(angle_diff(*my.inverse_leg(0, cy, -s1), -q1), 1e-12);
        EXPECT_LT(angle_diff(*my.inverse_leg(1, cy, -s2), -q2), 1e-12);
        const auto e = m.evaluate({c.x, c.y, 0}, {}).front();
        const auto ex = mx.evaluate({cx.x, cx.y, 0}, {}).front();
        const auto ey = my.evaluate({cy.x, cy.y, 0}, {}).front();
        EXPECT_NEAR(e.pressure_angle_deg[0], ex.pressure_angle_deg[0], 1e-9);
        EXPECT_NEAR(e.pressure_angle_deg[0], ey.pressure_angle_deg[0], 1e-9);
        if (std::isfinite(e.condition_number) && e.condition_number < 1e6) {
          EXPECT_NEAR(e.condition_number, ex.condition_number, 1e-7 * e.condition_number);
          EXPECT_NEAR(e.condition_number, ey.condition_number, 1e-7 * e.condition_number);
        }
      }
    }
  }
}

TEST(FiveBarKinematics, PressureAngleAndReactionsAgreeWithStatics) {
  // [Briot]: A^T = [R1 R2] (unit distal directions), cos α = |sin(ψ2 - ψ1)|;
  // R = A^-T w for a load w at C; R_i,max = f / |sin ε| (docs/theory/three_dof.md).
  std::mt19937 rng(3);
  const FiveBar m = dextar(1, -1);
  mechanisms::Criteria crit;
  crit.load = mechanisms::Load{100.0, 5.0};
  for (int n = 0; n < 100; ++n) {
    const Point c = random_in_lens(rng);
    const double q1 = *m.inverse_leg(0, c, 1), q2 = *m.inverse_leg(1, c, -1);
    const Point r1 = (1 / L) * (c - m.elbow(0, q1)), r2 = (1 / L) * (c - m.elbow(1, q2));
    const double psi1 = std::atan2(r1.y, r1.x), psi2 = std::atan2(r2.y, r2.x);
    const auto e = m.evaluate({c.x, c.y, 0}, crit).front();
    const double alpha = std::acos(std::abs(std::sin(psi2 - psi1))) / deg;
    EXPECT_NEAR(e.pressure_angle_deg[0], alpha, 1e-9);
    EXPECT_NEAR(e.pressure_angle_deg[1], alpha, 1e-9);
    Eigen::Matrix2d at;
    at << r1.x, r2.x, r1.y, r2.y;
    if (std::abs(at.determinant()) < 1e-3) continue;
    double worst = 0.0;
    for (int k = 0; k < 3600; ++k) {
      const Eigen::Vector2d w(100.0 * std::cos(2 * pi * k / 3600), 100.0 * std::sin(2 * pi * k / 3600));
      worst = std::max(worst, std::abs((at.inverse() * w)(0)));
    }
    EXPECT_NEAR(e.reactions_N[0], worst, 1e-4 * worst);  // the moment does not reach C
    EXPECT_GE(e.reactions_N[0], worst * (1 - 1e-12));
  }
}

TEST(FiveBarKinematics, SingularitiesAreFlagged) {
  const FiveBar m = dextar(1, -1);
  // Type 1: C on the outer circle of leg 1 (proximal and distal aligned).
  const double phi = 70 * deg;
  const Point c1 = Point{-A, 0} + 2 * L * Point{std::cos(phi), std::sin(phi)};
  const auto e1 = m.evaluate({c1.x, c1.y, 0}, {}).front();
  EXPECT_TRUE(e1.singular);
  EXPECT_TRUE(e1.singularity == "type1" || e1.singularity == "both");
  // Type 2: distal links aligned, C the midpoint of B and D with |B - D| = 2L.
  const double q1 = 120 * deg;
  const Point b = m.elbow(0, q1);
  // D on circle(E, L) at distance 2L from B.
  const Point e{A, 0};
  const double dist = norm(b - e);
  const Point u = (1 / dist) * (e - b);
  const double along = (4 * L * L - L * L + dist * dist) / (2 * dist);
  const Point d = b + along * u + std::sqrt(4 * L * L - along * along) * Point{-u.y, u.x};
  const Point c2 = 0.5 * (b + d);
  int type2 = 0;
  for (const auto& ev : m.evaluate({c2.x, c2.y, 0}, {})) {
    if (ev.joints.size() == 2 && (ev.singularity == "type2" || ev.singularity == "both")) {
      ++type2;
      EXPECT_NEAR(ev.pressure_angle_deg[0], 90.0, 1e-3);
    }
  }
  EXPECT_GE(type2, 1);
}

TEST(FiveBarKinematics, TypeTwoCurvesHaveAlignedDistalLinks) {
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      const auto curves = mechanisms::type2_singularity_curves(m, false, 512);
      std::size_t points = 0;
      for (const auto& curve : curves) {
        for (const Point& c : curve) {
          ++points;
          // In the file's working mode the distal links are aligned at C.
          const auto q1 = m.inverse_leg(0, c, s1), q2 = m.inverse_leg(1, c, s2);
          ASSERT_TRUE(q1 && q2);
          const double sin_eps = std::sin(m.transmission_angle(c, *q1, *q2));
          EXPECT_LT(std::abs(sin_eps), 1e-6) << c.x << " " << c.y;
        }
      }
      EXPECT_GT(points, 100u);
      // Every mode's curves together cover the full locus.
      const auto all = mechanisms::type2_singularity_curves(m, true, 512);
      std::size_t all_points = 0;
      for (const auto& curve : all) all_points += curve.size();
      EXPECT_GT(all_points, points);
    }
  }
}

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

TEST(FiveBarFile, ErrorsNameTheField) {
  auto doc = dextar_doc();
  EXPECT_NO_THROW(parse(doc));
  {
    auto d = doc;
    d["working_mode"] = {1, 0};
    EXPECT_EQ(load_error(d), "working_mode[1]: expected -1 or 1");
  }
  {
    auto d = doc;
    d["proximal"] = {-0.23, 0.23};
    EXPECT_EQ(load_error(d), "proximal[0]: must be positive");
  }
  {
    auto d = doc;
    d["distal"] = {0.23};
    EXPECT_NE(load_error(d).find("distal: expected an array of 2 numbers"), std::string::npos);
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, {150, 30}};
    EXPECT_EQ(load_error(d), "actuator_limits_deg[1]: expected [min, max] with min < max");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {nullptr, {0, 400}};
    EXPECT_EQ(load_error(d), "actuator_limits_deg[1]: the range must not exceed 360 degrees");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, nullptr};
    const auto f = parse(d);
    const auto& m = dynamic_cast<const FiveBar&>(*f.model);
    EXPECT_TRUE(m.crank_limits(0).has_value());
    EXPECT_FALSE(m.crank_limits(1).has_value());
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.1, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"sense", -1}}};
    EXPECT_EQ(load_error(d).rfind("pi_joints[0].stroke: must lie strictly inside", 0), 0u) << load_error(d);
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"sense", 2}}};
    EXPECT_EQ(load_error(d), "pi_joints[1].sense: expected -1 or 1");
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"lead", 2}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}}};
    EXPECT_EQ(load_error(d), "pi_joints[0].lead: unknown field (expected one of: k, stroke, base_angle_deg, sense)");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, {30, 150}};
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}}};
    EXPECT_EQ(load_error(d).rfind("pi_joints: give either", 0), 0u) << load_error(d);
  }
  {
    auto d = doc;
    d["elbows"] = 2;
    EXPECT_EQ(load_error(d).rfind("elbows: unknown field (expected one of: name, ", 0), 0u) << load_error(d);
  }
}

namespace {

TEST(FiveBarStatics, ActuatorTorqueIsTheWorstMomentOfTheLoad) {
  // [Briot] Table 2 (chain R̲RR): the worst actuator torque over force
  // directions of norm f at C is f |∂C/∂q_i| (virtual work), with ∂C/∂q_i
  // taken here by finite differences of the direct kinematics.
  const double f = 100.0;
  pkmws::mechanisms::Criteria criteria;
  criteria.load = pkmws::mechanisms::Load{f, 0.0};
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> ux(-0.25, 0.25), uy(0.05, 0.4);
  int checked = 0;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      for (int n = 0; n < 40; ++n) {
        const pkmws::mechanisms::Pose pose{ux(rng), uy(rng), 0.0};
        for (const auto& e : m.evaluate(pose, criteria)) {
          if (!e.reachable || e.singular || e.reactions_N.size() != 2) continue;
          for (int i = 0; i < 2; ++i) {
            const double h = 1e-7;
            std::vector<double> qp = e.joints, qm = e.joints;
            qp[static_cast<std::size_t>(i)] += h;
            qm[static_cast<std::size_t>(i)] -= h;
            auto nearest = [&](const std::vector<double>& q) {
              Point best{1e300, 1e300};
              for (const auto& s : m.direct(q))
                if (std::hypot(s.pose.x - pose.x, s.pose.y - pose.y) < std::hypot(best.x - pose.x, best.y - pose.y))
                  best = {s.pose.x, s.pose.y};
              return best;
            };
            const Point cp = nearest(qp), cm = nearest(qm);
            const double expected = f * std::hypot(cp.x - cm.x, cp.y - cm.y) / (2 * h);
            double torque = -1.0;
            for (const auto& [k, v] : e.extra)
              if (k == "actuator_torque" + std::to_string(i + 1)) torque = v;
            EXPECT_NEAR(torque, expected, 1e-5 * expected + 1e-9);
            ++checked;
          }
        }
      }
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
