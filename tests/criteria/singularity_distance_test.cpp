// The distance to the type-2 singularity as a criterion (min_singularity_distance,
// docs/theory/level_sets.md): the certified bounds of W ∩ {d >= δ} against
// closed forms (PAMINSA's singular circle, a biglide whose rods align on a
// horizontal line), the real-scheme biglide against finite differences of its
// inverse kinematics, and against an independent sampling of S (bisection of a
// determinant written here from the poses, on grid lines) with brute-force
// distances (DexTAR, a random five-bar, PAMINSA at 25°, a random 3-RPR); the
// enclosure inner ⊆ outer with area(inner) <= lower <= upper <= area(outer);
// bad values of the file field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/cli_runner.hpp"
#include "support/fixtures.hpp"
#include "support/limited.hpp"
#include "support/load_error.hpp"

namespace {

using namespace pkmws;
using geometry::Point;
using Json = nlohmann::json;

criteria::LimitedWorkspace limited(const io::MechanismFile& f, double tol = 1e-6) {
  certified::LevelSetOptions o;
  o.relative_tolerance = tol;
  return criteria::limited_workspace(f, criteria::file_limits(f), o);
}

io::MechanismFile from_json(const Json& doc) { return io::parse_mechanism(doc, "test"); }

Json dataset_json(const std::string& stem) { return Json::parse(test::slurp(test::dataset(stem))); }

// PAMINSA ([Briot] fig. 12) in its analysis window with a distance limit.
Json paminsa(double phi_deg, double delta) {
  Json doc = dataset_json("three_rpr_paminsa_phi0_r110");
  doc["orientation_deg"] = phi_deg;
  doc["criteria"] = {{"min_singularity_distance", delta}};
  return doc;
}

// inner ⊆ outer, area(inner) <= lower <= upper <= area(outer).
void expect_enclosure(const certified::CertifiedRegion& r) {
  const double scale = std::max(r.area_upper, 1e-300);
  EXPECT_LE(r.inner.subtract(r.outer).area(), 1e-12 * scale);
  EXPECT_LE(r.inner.area(), r.area_lower + 1e-12 * scale);
  EXPECT_LE(r.area_lower, r.area_upper);
  EXPECT_LE(r.area_upper, r.outer.area() + 1e-12 * scale);
}

TEST(SingularityDistance, PaminsaCircleAgainstTheClosedForm) {
  // S at fixed φ is the circle |P| = sqrt(R_b² + R_p² - 2 R_b R_p cos φ)
  // (docs/theory/three_dof.md): W ∩ {d >= δ} is the window minus an annulus.
  struct Case {
    double phi_deg, delta, tol;
  };
  for (const Case& k : {Case{0.0, 0.02, 1e-6}, Case{25.0, 0.04, 1e-5}}) {
    const io::MechanismFile f = from_json(paminsa(k.phi_deg, k.delta));
    const double phi = k.phi_deg * std::numbers::pi / 180.0;
    const double radius = std::sqrt(0.35 * 0.35 + 0.1 * 0.1 - 2 * 0.35 * 0.1 * std::cos(phi));
    const double exact = 0.64 * 0.64 - 4.0 * std::numbers::pi * radius * k.delta;
    const criteria::LimitedWorkspace lw = limited(f, k.tol);
    SCOPED_TRACE(k.phi_deg);
    EXPECT_LE(lw.region.area_lower, exact);
    EXPECT_GE(lw.region.area_upper, exact);
    EXPECT_LE(lw.region.width(), k.tol * exact);
    EXPECT_GT(lw.singular_error, 0.0);
    expect_enclosure(lw.region);
  }
}

TEST(SingularityDistance, DatasetReadsTheLimit) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("biglide_simplified_dsing20"));
  ASSERT_TRUE(f.criteria.min_singularity_distance);
  const auto limits = criteria::file_limits(f);
  ASSERT_EQ(limits.size(), 1u);
  EXPECT_EQ(limits[0].name, "singularity_distance");
  EXPECT_EQ(limits[0].threshold, 20.0);
}

// The simplified biglide (rods l1, l2, guides at y = -B and +B): the rods
// u_1 = (w_1, y + B), u_2 = (w_2, y - B) align where w_1 (y - B) = (y + B) w_2,
// a horizontal line y = y* (everything depends on y only); S is that line's
// part in W, so W ∩ {d >= δ} = W minus the stadium around it. The bundled
// dataset (l1 = 2000, l2 = 300, B = 500 mm, δ = 20 mm) and a design of other
// rods, guides, strokes and δ.
TEST(SingularityDistance, BiglideAlignmentLineAgainstTheExactStadium) {
  Json other = dataset_json("biglide_simplified_dsing20");
  other["rods"] = {1800.0, 400.0};
  other["half_width"] = 450.0;
  other["stroke"] = {{100.0, 2200.0}, {0.0, 2400.0}};
  other["criteria"] = {{"min_singularity_distance", 12.0}};
  for (const Json& doc : {dataset_json("biglide_simplified_dsing20"), other}) {
    const io::MechanismFile f = from_json(doc);
    const double b = doc["half_width"], l1 = doc["rods"][0], l2 = doc["rods"][1];
    const double delta = doc["criteria"]["min_singularity_distance"];
    const auto align = [&](double y) {
      return std::sqrt(l1 * l1 - (y + b) * (y + b)) * (y - b) - (y + b) * std::sqrt(l2 * l2 - (y - b) * (y - b));
    };
    double lo = b + 1.0, hi = std::min(b + l2, l1 - b) - 1e-9;
    ASSERT_LT(align(lo), 0.0);
    ASSERT_GT(align(hi), 0.0);
    for (int i = 0; i < 200; ++i) (align(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const double ystar = 0.5 * (lo + hi);
    // The line's section of W, in closed form: q_i = x - w_i with
    // w_i = sqrt(l_i² - (y* ± B)²) in the strokes (reachable() admits 1e-9
    // of the stroke beyond them, 2.5e-6 mm: more than the bounds' width).
    const double w1 = std::sqrt(l1 * l1 - (ystar + b) * (ystar + b)), w2 = std::sqrt(l2 * l2 - (ystar - b) * (ystar - b));
    const Json& st = doc["stroke"];
    const double xa = std::max(st[0][0].get<double>() + w1, st[1][0].get<double>() + w2);
    const double xb = std::min(st[0][1].get<double>() + w1, st[1][1].get<double>() + w2);
    ASSERT_LT(xa, xb);
    const geometry::Region w = f.model->workspace();
    for (int i = 1; i < 100; ++i) ASSERT_TRUE(f.model->reachable({xa + (xb - xa) * i / 100.0, ystar, 0.0}));
    const double exact = w.subtract(geometry::stadium({xa, ystar}, {xb, ystar}, delta)).area();
    std::printf("[ exact    ] y* = %.17g, %.17g\n", ystar, exact);
    // At 1e-9 the boxes where S meets W's boundary are traced deeper and the
    // small pieces grouped on a finer grid (before, the width stopped at 5.3e-8).
    for (const double tol : {1e-6, 1e-9}) {
      SCOPED_TRACE(tol);
      const criteria::LimitedWorkspace lw = limited(f, tol);
      std::printf("[ bounds   ] %.17g %.17g\n", lw.region.area_lower, lw.region.area_upper);
      EXPECT_LE(lw.region.area_lower, exact * (1 + 1e-15));
      EXPECT_GE(lw.region.area_upper, exact * (1 - 1e-15));
      EXPECT_LE(lw.region.width(), tol * exact);
      expect_enclosure(lw.region);
      // The traced chords lie on the line (within their bound).
      for (const auto& c : lw.singular_curves) {
        for (const Point& p : c) EXPECT_NEAR(p.y, ystar, lw.singular_error + 1e-9);
      }
    }
  }
}

// The real-scheme biglide (tool on link 1's triangle) with unequal rods, so
// that rod 2 can align with rod 1 inside the workspace. Its singular
// determinant (BiglideRealSingular) against det(dq/dP) by central finite
// differences of the module's inverse kinematics (paper's branch): the same
// sign wherever the difference quotient is clear of zero, and the same zeros
// along vertical lines.
// J's singular locus is a horizontal line and T = S_1 + M (J - S_1) turns it
// into one, y = y*; the certified W ∩ {d >= 20} must contain an 800² grid
// estimate of it (reachable points at least 20 from that segment of the line).
TEST(SingularityDistance, RealBiglideAgainstFiniteDifferencesOfItsInverseKinematics) {
  Json doc = dataset_json("biglide_real");
  doc["rods"] = {2000.0, 300.0};
  doc["stroke"] = {{0.0, 2500.0}, {0.0, 2500.0}};
  doc["tool"] = {{"l3", 1950.0}, {"l4", 100.0}};
  const double delta = 20.0;
  doc["criteria"] = {{"min_singularity_distance", delta}};
  const io::MechanismFile f = from_json(doc);
  const auto fields = f.model->capability<criteria::CriterionFields>();
  ASSERT_TRUE(fields);
  const criteria::CriterionField det = fields->singular_determinant(f.criteria);
  const auto q = [&](double x, double y) {
    const auto s = f.model->inverse({x, y, 0.0});
    return s.front().joints;
  };
  const auto fd_det = [&](double x, double y) {  // det(dq/dP), h = 1e-4 mm
    const double h = 1e-4;
    const auto qxp = q(x + h, y), qxm = q(x - h, y), qyp = q(x, y + h), qym = q(x, y - h);
    if (qxp.size() != 2 || qxm.size() != 2 || qyp.size() != 2 || qym.size() != 2) return std::nan("");
    const double a = (qxp[0] - qxm[0]) / (2 * h), b = (qyp[0] - qym[0]) / (2 * h);
    const double c = (qxp[1] - qxm[1]) / (2 * h), d = (qyp[1] - qym[1]) / (2 * h);
    return a * d - b * c;
  };
  const geometry::Box box = f.model->bounds();
  std::vector<double> zeros;
  int compared = 0, positive = 0;
  for (int i = 1; i < 40; ++i) {
    const double x = box.min.x + box.width() * i / 40.0;
    std::vector<double> ys;
    for (int j = 0; j <= 400; ++j) ys.push_back(box.min.y + box.height() * j / 400.0);
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      if (!f.model->reachable({x, ys[j], 0.0}) || !f.model->reachable({x, ys[j + 1], 0.0})) continue;
      const double g0 = det.value({x, ys[j]}), g1 = det.value({x, ys[j + 1]});
      const double r0 = fd_det(x, ys[j]);
      if (std::abs(r0) > 1e-6) {
        ++compared;
        positive += (g0 > 0) == (r0 > 0);  // the field is w_1 w_2 (∂q_2/∂y - ∂q_1/∂y) = w_1 w_2 det(dq/dP)
      }
      if ((g0 < 0) == (g1 < 0)) continue;
      double lo = ys[j], hi = ys[j + 1];
      for (int k = 0; k < 100; ++k) ((det.value({x, 0.5 * (lo + hi)}) < 0) == (g0 < 0) ? lo : hi) = 0.5 * (lo + hi);
      const double y_field = 0.5 * (lo + hi);
      lo = ys[j];
      hi = ys[j + 1];
      const bool r_neg = fd_det(x, lo) < 0;
      for (int k = 0; k < 60; ++k) ((fd_det(x, 0.5 * (lo + hi)) < 0) == r_neg ? lo : hi) = 0.5 * (lo + hi);
      EXPECT_NEAR(y_field, 0.5 * (lo + hi), 1e-5) << "x = " << x;
      zeros.push_back(y_field);
    }
  }
  ASSERT_GT(compared, 1000);
  EXPECT_EQ(positive, compared);
  ASSERT_GE(zeros.size(), 5u);
  const double ystar = zeros.front();
  for (double y : zeros) EXPECT_NEAR(y, ystar, 1e-9);
  // S = the line's section of W (one interval, by bisection on reachable()).
  double inside = std::nan("");
  for (int i = 0; i <= 4000 && std::isnan(inside); ++i) {
    const double x = box.min.x + box.width() * i / 4000.0;
    if (f.model->reachable({x, ystar, 0.0})) inside = x;
  }
  ASSERT_FALSE(std::isnan(inside));
  const auto edge = [&](double out) {
    double a = inside, c = out;
    for (int i = 0; i < 200; ++i) (f.model->reachable({0.5 * (a + c), ystar, 0.0}) ? a : c) = 0.5 * (a + c);
    return 0.5 * (a + c);
  };
  const double xa = edge(box.min.x - 10.0), xb = edge(box.max.x + 10.0);
  for (int i = 1; i < 100; ++i) ASSERT_TRUE(f.model->reachable({xa + (xb - xa) * i / 100.0, ystar, 0.0}));
  const int n = 800;
  const double cell = box.width() * box.height() / (double(n) * n);
  double estimate = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Point p{box.min.x + (i + 0.5) * box.width() / n, box.min.y + (j + 0.5) * box.height() / n};
      if (!f.model->reachable({p.x, p.y, 0.0})) continue;
      const double px = std::clamp(p.x, xa, xb);
      if (std::hypot(p.x - px, p.y - ystar) >= delta) estimate += cell;
    }
  }
  const criteria::LimitedWorkspace lw = limited(f);
  std::printf("[ real     ] y* = %.9g, S x in [%.6g, %.6g], grid %.6g, certified [%.9g, %.9g]\n", ystar, xa, xb,
              estimate, lw.region.area_lower, lw.region.area_upper);
  EXPECT_LE(lw.region.area_lower, estimate * (1 + 2e-3));
  EXPECT_GE(lw.region.area_upper, estimate * (1 - 2e-3));
  EXPECT_LE(lw.region.width(), 1e-3 * lw.region.area_upper);
  expect_enclosure(lw.region);
  for (const auto& c : lw.singular_curves) {
    for (const Point& p : c) EXPECT_NEAR(p.y, ystar, lw.singular_error + 1e-6);
  }
}

// ---------------------------------------------------------------------------
// Against an independent sampling of S.

// Points of {g = 0} on the grid lines of W's box (n lines each way), by
// bisection between samples of opposite signs (NaN: outside W).
std::vector<Point> sample_zero_set(const std::function<double(Point)>& g, const geometry::Box& box, int n) {
  std::vector<Point> out;
  const auto line = [&](Point a, Point b) {
    const int m = 4 * n;
    Point prev = a;
    double gp = g(a);
    for (int k = 1; k <= m; ++k) {
      const Point q{a.x + (b.x - a.x) * k / m, a.y + (b.y - a.y) * k / m};
      const double gq = g(q);
      if (std::isfinite(gp) && std::isfinite(gq) && (gp < 0.0) != (gq < 0.0)) {
        Point l = prev, h = q;
        const bool neg = gp < 0.0;
        for (int i = 0; i < 60; ++i) {
          const Point mid{0.5 * (l.x + h.x), 0.5 * (l.y + h.y)};
          const double gm = g(mid);
          if (!std::isfinite(gm)) break;
          ((gm < 0.0) == neg ? l : h) = mid;
        }
        out.push_back({0.5 * (l.x + h.x), 0.5 * (l.y + h.y)});
      }
      prev = q;
      gp = gq;
    }
  };
  for (int i = 0; i <= n; ++i) {
    const double y = box.min.y + box.height() * i / n, x = box.min.x + box.width() * i / n;
    line({box.min.x, y}, {box.max.x, y});
    line({x, box.min.y}, {x, box.max.y});
  }
  return out;
}

double nearest(const std::vector<Point>& pts, Point p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point& q : pts) best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
  return best;
}

// Random points P of W's box: where the sampled distance d_s (>= d) exceeds
// δ + gap, P is in the true set and must be in outer; where d_s < δ it is
// not, and must not be in inner. A grid count of d_s >= δ in W must lie
// within the bounds up to the grid's error.
// `tol`: the bounds' target; `check_width`: whether it must be met (not where
// S meets W's boundary tangentially, a leg's type-1 singularity: the five-bar).
void check_against_samples(const io::MechanismFile& f, const std::function<double(Point)>& g, int lines,
                           unsigned seed, double tol, bool check_width) {
  const double delta = *f.criteria.min_singularity_distance;
  const criteria::LimitedWorkspace lw = limited(f, tol);
  expect_enclosure(lw.region);
  if (check_width) {
    EXPECT_LE(lw.region.width(), tol * lw.region.area_upper);
  }
  std::printf("[ bounds   ] [%.10g, %.10g], width %.2g of the area, w %.2g, %zu boxes not traced\n",
              lw.region.area_lower, lw.region.area_upper, lw.region.width() / lw.region.area_upper, lw.singular_error,
              lw.singular_undecided.size());
  const geometry::Box box = f.model->workspace().bbox();
  const std::vector<Point> s = sample_zero_set(g, box, lines);
  ASSERT_FALSE(s.empty()) << "no type-2 singular point in the workspace";
  const double h = std::max(box.width(), box.height()) / lines;
  const double gap = 3.0 * h;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
  int in_checked = 0, out_checked = 0;
  for (int k = 0; k < 400; ++k) {
    const Point p{ux(rng), uy(rng)};
    if (!f.model->reachable({p.x, p.y, f.model->orientation()})) continue;
    const double ds = nearest(s, p);
    if (ds >= delta + gap) {
      ++in_checked;
      EXPECT_TRUE(lw.region.outer.contains(p)) << p.x << " " << p.y << " d_s " << ds;
    } else if (ds < delta) {
      ++out_checked;
      EXPECT_FALSE(lw.region.inner.contains(p)) << p.x << " " << p.y << " d_s " << ds;
    }
  }
  EXPECT_GT(in_checked, 20);
  EXPECT_GT(out_checked, 5);
  // Grid count (cell centres), with the grid's error: cells within a cell's
  // diagonal of the boundaries (W's and the tube's) may go either way.
  const int m = 240;
  const double cx = box.width() / m, cy = box.height() / m;
  double count = 0.0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const Point p{box.min.x + (i + 0.5) * cx, box.min.y + (j + 0.5) * cy};
      if (f.model->reachable({p.x, p.y, f.model->orientation()}) && nearest(s, p) >= delta) count += cx * cy;
    }
  }
  double length = 0.0;
  for (const auto& c : lw.singular_curves) {
    for (std::size_t k = 1; k < c.size(); ++k) length += std::hypot(c[k].x - c[k - 1].x, c[k].y - c[k - 1].y);
  }
  double perimeter = 0.0;
  for (const auto& comp : f.model->workspace().components()) perimeter += comp.perimeter;
  const double slack = (perimeter + 2.0 * length) * (std::hypot(cx, cy) + gap);
  std::printf("[ grid     ] %d^2 cell count %.10g (slack %.2g), %zu points of S sampled\n", m, count, slack, s.size());
  EXPECT_GE(count, lw.region.area_lower - slack);
  EXPECT_LE(count, lw.region.area_upper + slack);
}

// The five-bar's det from the evaluation's crank angles (its own inverse
// kinematics): B_i = A_i + l_i1 u(q_i), det = (C - B_1) x (C - B_2).
std::function<double(Point)> five_bar_det(const io::MechanismFile& f, const Json& doc) {
  const auto base = doc["base"];
  const auto prox = doc["proximal"];
  return [&f, base, prox](Point c) {
    const auto e = f.model->evaluate({c.x, c.y, 0.0}, {});
    if (e.empty() || !e.front().reachable) return std::numeric_limits<double>::quiet_NaN();
    std::array<Point, 2> u;
    for (std::size_t i = 0; i < 2; ++i) {
      const double q = e.front().joints.at(i);
      const Point b{base[i][0].get<double>() + prox[i].get<double>() * std::cos(q),
                    base[i][1].get<double>() + prox[i].get<double>() * std::sin(q)};
      u[i] = {c.x - b.x, c.y - b.y};
    }
    return u[0].x * u[1].y - u[0].y * u[1].x;
  };
}

// The 3-RPR's det A at the file's φ, written from its geometry ([Briot]: row j
// is the force line through B_j perpendicular to leg j, [n_j, (B_j - P) x n_j]).
std::function<double(Point)> three_rpr_det(const Json& doc) {
  const double phi = doc.value("orientation_deg", 0.0) * std::numbers::pi / 180.0;
  std::array<Point, 3> a, c;
  for (std::size_t j = 0; j < 3; ++j) {
    a[j] = {doc["base"][j][0].get<double>(), doc["base"][j][1].get<double>()};
    const double bx = doc["platform"][j][0].get<double>(), by = doc["platform"][j][1].get<double>();
    c[j] = {std::cos(phi) * bx - std::sin(phi) * by, std::sin(phi) * bx + std::cos(phi) * by};
  }
  return [a, c](Point p) {
    double m[3][3];
    for (std::size_t j = 0; j < 3; ++j) {
      const Point leg{p.x + c[j].x - a[j].x, p.y + c[j].y - a[j].y};
      const Point n{-leg.y, leg.x};
      m[j][0] = n.x;
      m[j][1] = n.y;
      m[j][2] = c[j].x * n.y - c[j].y * n.x;
    }
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
}

TEST(SingularityDistance, DextarAgainstSampledSingularCurve) {
  Json doc = dataset_json("five_bar_dextar_pm");
  doc["criteria"] = {{"min_singularity_distance", 0.02}};
  const io::MechanismFile f = from_json(doc);
  check_against_samples(f, five_bar_det(f, doc), 300, 1, 1e-5, false);
}

TEST(SingularityDistance, RandomFiveBarAgainstSampledSingularCurve) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> base(0.05, 0.2), link(0.15, 0.35);
  Json doc = dataset_json("five_bar_dextar_pp");
  const double a = base(rng);
  doc["base"] = {{-a, 0.0}, {a, 0.0}};
  doc["proximal"] = {link(rng), link(rng)};
  doc["distal"] = {link(rng), link(rng)};
  doc["working_mode"] = {1, -1};
  doc["criteria"] = {{"min_singularity_distance", 0.015}};
  const io::MechanismFile f = from_json(doc);
  check_against_samples(f, five_bar_det(f, doc), 300, 2, 1e-5, false);
}

TEST(SingularityDistance, PaminsaAt25DegAgainstSampledSingularCurve) {
  const Json doc = paminsa(25.0, 0.02);
  const io::MechanismFile f = from_json(doc);
  check_against_samples(f, three_rpr_det(doc), 300, 3, 1e-5, true);
}

TEST(SingularityDistance, RandomThreeRprAgainstSampledSingularCurve) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  Json doc = paminsa(10.0, 0.015);
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 2; ++k) {
      doc["base"][j][k] = doc["base"][j][k].get<double>() + jitter(rng);
      doc["platform"][j][k] = doc["platform"][j][k].get<double>() + 0.3 * jitter(rng);
    }
  }
  const io::MechanismFile f = from_json(doc);
  check_against_samples(f, three_rpr_det(doc), 300, 4, 1e-5, true);
}

TEST(SingularityDistance, OneAndTwoThreadsGiveIdenticalBounds) {
  const io::MechanismFile f = from_json(paminsa(25.0, 0.02));
  const auto one = test::limited_on(f, 1e-4, 1), two = test::limited_on(f, 1e-4, 2);
  EXPECT_EQ(one.region.area_lower, two.region.area_lower);
  EXPECT_EQ(one.region.area_upper, two.region.area_upper);
  EXPECT_EQ(one.singular_curves.size(), two.singular_curves.size());
}

// With a sub-level criterion too (the rods' pressure angle): W' ∩ {d >= δ},
// whose bounds must meet inclusion-exclusion with each limit alone.
TEST(SingularityDistance, CombinesWithALevelSetCriterion) {
  Json doc = dataset_json("biglide_simplified_dsing20");
  doc["criteria"] = {{"min_singularity_distance", 150.0}, {"max_pressure_angle_deg", 50.0}};
  const io::MechanismFile both = from_json(doc);
  ASSERT_EQ(criteria::file_limits(both).size(), 2u);
  const auto lw = limited(both);
  Json only_alpha = doc;
  only_alpha["criteria"].erase("min_singularity_distance");
  const auto a = limited(from_json(only_alpha));
  Json only_distance = doc;
  only_distance["criteria"].erase("max_pressure_angle_deg");
  const auto d = limited(from_json(only_distance));
  const double w = both.model->workspace().area();
  EXPECT_LE(lw.region.area_lower, lw.region.area_upper);
  EXPECT_LE(lw.region.area_lower, std::min(a.region.area_upper, d.region.area_upper));
  EXPECT_GE(lw.region.area_upper, a.region.area_lower + d.region.area_lower - w);
  EXPECT_LT(lw.region.area_upper, a.region.area_lower);  // both limits bind
  EXPECT_LT(lw.region.area_upper, d.region.area_lower);
  EXPECT_LE(lw.region.width(), 1e-5 * lw.region.area_upper);
  expect_enclosure(lw.region);
}

// ---------------------------------------------------------------------------
// The file field and the front door.

TEST(SingularityDistance, BadValuesGiveAOneLineErrorNamingTheField) {
  Json doc = dataset_json("biglide_simplified_dsing20");
  for (const Json& bad : {Json(-0.02), Json(0.0), Json("20 mm"), Json(nullptr)}) {
    doc["criteria"]["min_singularity_distance"] = bad;
    const std::string e = test::load_error(doc);
    EXPECT_NE(e.find("min_singularity_distance"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  Json no_units = dataset_json("biglide_simplified_dsing20");
  no_units.erase("units");
  EXPECT_NE(test::load_error(no_units).find("units"), std::string::npos);
}

TEST(SingularityDistance, CliReportsTheIntervalAndRefusesBadInput) {
  const auto dir = test::scratch_dir("singularity_distance");
  const auto ok = test::run_cli("area " + test::dataset("biglide_simplified_dsing20"), dir);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("singularity_distance >= 20"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("certified"), std::string::npos) << ok.out;
  Json doc = dataset_json("biglide_simplified_dsing20");
  doc["criteria"]["min_singularity_distance"] = -1.0;
  const auto bad_path = dir / "bad.json";
  {
    std::ofstream(bad_path) << doc.dump();
  }
  const auto bad = test::run_cli("area " + bad_path.string(), dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("min_singularity_distance"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  // A mechanism without the field refuses with one line (the Π-joint on its own).
  Json real = dataset_json("pi_joint_prototype");
  real["criteria"] = {{"min_singularity_distance", 10.0}};
  const auto real_path = dir / "real.json";
  {
    std::ofstream(real_path) << real.dump();
  }
  const auto refused = test::run_cli("area " + real_path.string(), dir);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("min_singularity_distance"), std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
}

}  // namespace
