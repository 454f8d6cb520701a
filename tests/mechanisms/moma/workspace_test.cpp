// MOMA workspace ([Vasilic], docs/theory/moma.md): the exact area against an
// independent numerical integration and closed forms, membership, bounds, the
// drawing.
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

namespace {

using LD = long double;

// Adaptive Gauss-Kronrod (7/15) in long double: an interval is accepted when
// |K15 - G7| <= tol (a pessimistic bound on the K15 error), else bisected.
LD gauss_kronrod(const std::function<LD(LD)>& f, LD a, LD b, LD tol, int depth = 0) {
  static const LD xk[8] = {0.991455371120812639206854697526329L, 0.949107912342758524526189684047851L,
                           0.864864423359769072789712788640926L, 0.741531185599394439863864773280788L,
                           0.586087235467691130294144845693013L, 0.405845151377397166906606412076961L,
                           0.207784955007898467600689403773245L, 0.0L};
  static const LD wk[8] = {0.022935322010529224963732008058970L, 0.063092092629978553290700663189204L,
                           0.104790010322250183839876322541518L, 0.140653259715525918745189590510238L,
                           0.169004726639267902826583426598550L, 0.190350578064785409913256402421014L,
                           0.204432940075298892414161999234649L, 0.209482141084727828012999174891714L};
  static const LD wg[4] = {0.129484966168869693270611432679082L, 0.279705391489276667901467771423780L,
                           0.381830050505118944950369775488975L, 0.417959183673469387755102040816327L};
  const LD c = (a + b) / 2, h = (b - a) / 2;
  LD kronrod = wk[7] * f(c), gauss = wg[3] * f(c);
  for (int i = 0; i < 7; ++i) {
    const LD s = f(c - h * xk[i]) + f(c + h * xk[i]);
    kronrod += wk[i] * s;
    if (i % 2 == 1) gauss += wg[i / 2] * s;
  }
  kronrod *= h;
  gauss *= h;
  if (std::abs(kronrod - gauss) <= tol || depth >= 60) return kronrod;
  return gauss_kronrod(f, a, c, tol, depth + 1) + gauss_kronrod(f, c, b, tol, depth + 1);
}

struct Interval {
  LD lo, hi;
};

// The x-slice at height y of one M1 leg band (gamma = 0, guide pointing down
// from (c, 0), stroke [0, h], rod l, branch -1: P below its slider). With
// s = a . (P - S) = -(y + p) in [0, l] and p in [0, h]:
// s in [max(0, -y - h), min(l, -y)] and |x - c| = sqrt(l^2 - s^2).
std::vector<Interval> m1_slice(LD c, LD y, LD l, LD h) {
  const LD s_lo = std::max<LD>(0, -y - h), s_hi = std::min<LD>(l, -y);
  if (s_lo > s_hi) return {};
  const LD inner = std::sqrt(std::max<LD>(0, (l - s_hi) * (l + s_hi)));
  const LD outer = std::sqrt(std::max<LD>(0, (l - s_lo) * (l + s_lo)));
  return {{c - outer, c - inner}, {c + inner, c + outer}};
}

}  // namespace

TEST(MomaWorkspace, TheIntegratorIsAccurate) {
  // Half disk with its sqrt end singularities: pi l^2 / 2.
  const LD l = 250;
  const LD half_disk = gauss_kronrod([&](LD x) { return std::sqrt(std::max<LD>(0, l * l - x * x)); }, -l, l, 1e-13L);
  EXPECT_NEAR(static_cast<double>(half_disk / (std::numbers::pi_v<long double> * l * l / 2) - 1), 0.0, 1e-14);
}

TEST(MomaWorkspace, SingleBandAreaIsTwiceRodTimesStroke) {
  // Cavalieri: each line parallel to the guide cuts the band in a chord of length h.
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int i = 0; i < 2; ++i) {
      const MomaLeg& leg = m.legs()[i];
      for (int side : {-1, 1}) {
        const auto band = geometry::band(m.slider(i, leg.stroke_min), leg.guide_angle,
                                         leg.stroke_max - leg.stroke_min, leg.rod_length, side);
        const double expected = 2 * leg.rod_length * (leg.stroke_max - leg.stroke_min);
        EXPECT_NEAR(band.area(), expected, 1e-12 * expected) << f;
      }
    }
  }
}

TEST(MomaWorkspace, M1AreaAgainstIndependentIntegrationAndClosedForm) {
  const double exact = io::load_mechanism(dataset("moma_m1_g0_l250")).model->workspace().area();
  const LD l = 250, h = 200;
  // (1) Numerical integration in y of the length of the x-slice of band 1 and band 2.
  auto overlap = [&](LD y) {
    LD total = 0;
    for (const Interval& u : m1_slice(-100, y, l, h)) {
      for (const Interval& v : m1_slice(100, y, l, h)) {
        total += std::max<LD>(0, std::min(u.hi, v.hi) - std::max(u.lo, v.lo));
      }
    }
    return total;
  };
  const LD by_y = gauss_kronrod(overlap, -(h + l), 0, 1e-13L);
  // (2) Closed form in x: for |x| < x* the vertical slices [-h - s_i, -s_i],
  // s_i = sqrt(l^2 - (x -+ 100)^2), overlap in 200 - |s1 - s2|; x* solves
  // s2 - s1 = h; F is an antiderivative of sqrt(l^2 - u^2) (docs/theory/moma.md).
  auto F = [&](LD u) { return (u * std::sqrt(l * l - u * u) + l * l * std::asin(u / l)) / 2; };
  auto gap = [&](LD x) { return std::sqrt(l * l - (x - 100) * (x - 100)) - std::sqrt(l * l - (x + 100) * (x + 100)) - h; };
  LD lo = 0, hi = 150;
  for (int k = 0; k < 200; ++k) {
    const LD mid = (lo + hi) / 2;
    (gap(mid) < 0 ? lo : hi) = mid;
  }
  const LD xs = (lo + hi) / 2;
  const LD closed = 2 * (h * xs + (F(xs + 100) - F(100)) - (F(xs - 100) - F(-100)));
  std::printf("  M1 (gamma = 0, l = 250): exact %.17g, integral in y %.17Lg (rel. diff %.2Le),\n"
              "  closed form in x %.17Lg (rel. diff %.2Le)\n",
              exact, by_y, (by_y - exact) / exact, closed, (closed - exact) / exact);
  EXPECT_NEAR(exact, static_cast<double>(by_y), 1e-10 * exact);
  EXPECT_NEAR(exact, static_cast<double>(closed), 1e-12 * exact);
}

TEST(MomaWorkspace, MembershipAgreesWithTheExactRegionAwayFromTheBoundary) {
  std::mt19937 rng(9);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    const auto ws = m.workspace();
    const auto b = m.bounds();
    std::uniform_real_distribution<double> x(b.min.x, b.max.x), y(b.min.y, b.max.y);
    int inside = 0, compared = 0;
    for (int k = 0; k < 400; ++k) {
      const Point p{x(rng), y(rng)};
      // Distance (in joint or rod terms) from each leg's limits: skip near-boundary points.
      bool near = false;
      for (int i = 0; i < 2; ++i) {
        const MomaLeg& leg = m.legs()[i];
        const double across = std::abs(cross(m.guide_direction(i), p - leg.reference));
        const auto q = m.inverse_leg(i, p, leg.branch);
        near = near || std::abs(leg.rod_length - across) < 1e-6 * leg.rod_length;
        if (q) near = near || std::min(std::abs(*q - leg.stroke_min), std::abs(*q - leg.stroke_max)) < 1e-6 * leg.stroke_max;
      }
      if (near) continue;
      const bool exact = ws.contains(p);
      inside += exact;
      ++compared;
      EXPECT_EQ(m.reachable({p.x, p.y, 0}), exact) << f << " at " << p.x << ", " << p.y;
    }
    EXPECT_GT(compared, 390) << f;
    EXPECT_GT(inside, 20) << f;
  }
}

TEST(MomaWorkspace, BoundsContainTheWorkspaceAndEmptyIntersectionsAreEmpty) {
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const auto box = mech.model->bounds();
    const auto ws_box = mech.model->workspace().bbox();
    EXPECT_TRUE(box.contains(ws_box.min) && box.contains(ws_box.max)) << f;
  }
  // Guides 1000 apart, rods 100: the two bands never meet. Not an error: area 0.
  const Moma apart({MomaLeg{{-500, 0}, 1.5 * pi, 0, 200, 100, -1}, MomaLeg{{500, 0}, 1.5 * pi, 0, 200, 100, -1}});
  EXPECT_TRUE(apart.workspace().empty());
  EXPECT_EQ(apart.workspace().area(), 0.0);
  EXPECT_FALSE(apart.reachable({0, -100, 0}));
  EXPECT_FALSE(apart.bounds().empty());
}

TEST(MomaWorkspace, DrawingShowsGuidesSlidersAndRods) {
  const Moma m = m1(195, -5);
  const Point p{10, -280};
  ASSERT_TRUE(m.reachable({p.x, p.y, 0}));
  const auto d = m.draw({p.x, p.y, 0});
  ASSERT_EQ(d.guides.size(), 2u);
  ASSERT_EQ(d.sliders.size(), 2u);
  ASSERT_EQ(d.links.size(), 2u);
  EXPECT_EQ(d.tool, p);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(distance(d.guides[i].a, m.slider(i, 0)), 0.0, 1e-12);
    EXPECT_NEAR(distance(d.guides[i].b, m.slider(i, 200)), 0.0, 1e-12);
    // The slider lies on its guide and the rod has its length.
    EXPECT_NEAR(cross(d.guides[i].b - d.guides[i].a, d.sliders[i] - d.guides[i].a), 0.0, 1e-9);
    EXPECT_NEAR(distance(d.links[i].a, d.links[i].b), 195.0, 1e-9);
  }
}
