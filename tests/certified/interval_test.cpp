// Interval division: every quotient of points of the operands lies in the
// enclosure; a divisor with 0 at an end gives a half-line (the quotient over
// its nonzero points), one with 0 inside the whole line. Jets: the point
// derivatives match finite differences, and a box's jet encloses every point's.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pkmws/certified/interval.hpp"

namespace {

using pkmws::certified::Interval;
using pkmws::certified::Jet;

void expect_quotients_inside(const Interval& a, const Interval& b, std::mt19937& rng) {
  const Interval q = a / b;
  std::uniform_real_distribution<double> ua(a.lo, a.hi), ub(b.lo, b.hi);
  for (int k = 0; k < 2000; ++k) {
    const double x = ua(rng), y = ub(rng);
    if (y == 0.0) continue;
    EXPECT_TRUE(q.contains(x / y)) << x << " / " << y << " not in [" << q.lo << ", " << q.hi << "]";
  }
  // The ends of the operands too (the extremes of a quotient are there).
  for (double x : {a.lo, a.hi}) {
    for (double y : {b.lo, b.hi}) {
      if (y != 0.0) {
        EXPECT_TRUE(q.contains(x / y));
      }
    }
  }
}

TEST(Interval, DivisionByADivisorWithZeroAtAnEndIsAHalfLine) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0.1, 3.0);
  for (int k = 0; k < 200; ++k) {
    const double l = pos(rng), h = l + pos(rng), d = pos(rng);
    // Positive numerator over [0, d]: [l / d, +inf).
    const Interval q = Interval(l, h) / Interval(0.0, d);
    EXPECT_EQ(q.hi, Interval::inf);
    EXPECT_LE(q.lo, l / d);
    EXPECT_GE(q.lo, l / d * (1 - 1e-15));
    expect_quotients_inside(Interval(l, h), Interval(0.0, d), rng);
    // Negative numerator over [0, d], positive over [-d, 0], negative over [-d, 0].
    expect_quotients_inside(Interval(-h, -l), Interval(0.0, d), rng);
    expect_quotients_inside(Interval(l, h), Interval(-d, 0.0), rng);
    expect_quotients_inside(Interval(-h, -l), Interval(-d, 0.0), rng);
    EXPECT_EQ((Interval(l, h) / Interval(-d, 0.0)).lo, -Interval::inf);
    EXPECT_LT((Interval(l, h) / Interval(-d, 0.0)).hi, 0.0);
    // Ordinary divisors: tight to rounding.
    const Interval r = Interval(l, h) / Interval(d, d + 1.0);
    EXPECT_NEAR(r.lo, l / (d + 1.0), 1e-15 * h / d);
    EXPECT_NEAR(r.hi, h / d, 1e-15 * h / d);
    expect_quotients_inside(Interval(-l, h), Interval(d, d + 1.0), rng);
  }
}

TEST(Interval, DivisionWithZeroInsideTheDivisorOrZeroOverZeroIsTheWholeLine) {
  const Interval w = Interval(1.0, 2.0) / Interval(-1.0, 1.0);
  EXPECT_EQ(w.lo, -Interval::inf);
  EXPECT_EQ(w.hi, Interval::inf);
  // A numerator containing 0 over a divisor ending at 0: the quotient takes
  // every value (x / y with x of either sign and y -> 0).
  const Interval z = Interval(-1.0, 1.0) / Interval(0.0, 1.0);
  EXPECT_EQ(z.lo, -Interval::inf);
  EXPECT_EQ(z.hi, Interval::inf);
  const Interval zero = Interval(1.0, 2.0) / Interval(0.0, 0.0);
  EXPECT_EQ(zero.lo, -Interval::inf);
  EXPECT_EQ(zero.hi, Interval::inf);
  // [0, 1] / [0, 1]: 0 / y = 0 and x / y over (0, 1] x (0, 1] covers [0, inf).
  const Interval h = Interval(0.0, 1.0) / Interval(0.0, 1.0);
  EXPECT_LE(h.lo, 0.0);
  EXPECT_EQ(h.hi, Interval::inf);
}

TEST(Interval, AnExactZeroTimesAnySetOfRealsIsZero) {
  // Unbounded ends stand for unbounded sets of reals, not infinities: 0 * b = 0
  // for each of them (a structural zero of a jet times a factor unbounded
  // near a singularity). A factor that only contains 0 stays a product.
  for (const Interval& b : {Interval::whole(), Interval(1.0, Interval::inf), Interval(-Interval::inf, -2.0), Interval(-3.0, 5.0)}) {
    const Interval p = Interval(0.0) * b, q = b * Interval(0.0);
    EXPECT_EQ(p.lo, 0.0);
    EXPECT_EQ(p.hi, 0.0);
    EXPECT_EQ(q.lo, 0.0);
    EXPECT_EQ(q.hi, 0.0);
  }
  const Interval r = Interval(0.0, 1.0) * Interval(1.0, Interval::inf);
  EXPECT_LE(r.lo, 0.0);
  EXPECT_EQ(r.hi, Interval::inf);
}

// A field built from the jet operations of the five-bar's fields
// (squares, square roots, products, quotients, sums with constants).
template <class T> T jet_field(const T& x, const T& y) {
  using pkmws::certified::sqr;
  using pkmws::certified::sqrt;
  using std::sqrt;
  const T r2 = sqr(x) + sqr(y);
  return sqrt(r2) * x / (x * y + 3.0) + sqr(x - 2.0 * y) - 1.5 / r2;
}

TEST(Jet, PointDerivativesMatchFiniteDifferencesAndBoxJetsEncloseThem) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.3, 2.0), w(1e-3, 0.2);
  for (int k = 0; k < 300; ++k) {
    const double x0 = u(rng), y0 = u(rng), hx = w(rng), hy = w(rng);
    const Jet<Interval> box = jet_field(Jet<Interval>::variable_x(Interval(x0, x0 + hx)),
                                        Jet<Interval>::variable_y(Interval(y0, y0 + hy)));
    std::uniform_real_distribution<double> px(x0, x0 + hx), py(y0, y0 + hy);
    for (int n = 0; n < 20; ++n) {
      const double x = px(rng), y = py(rng);
      const Jet<double> j = jet_field(Jet<double>::variable_x(x), Jet<double>::variable_y(y));
      for (const auto& [in, v] : {std::pair{box.v, j.v}, {box.dx, j.dx}, {box.dy, j.dy}, {box.dxx, j.dxx},
                                  {box.dxy, j.dxy}, {box.dyy, j.dyy}}) {
        EXPECT_TRUE(in.contains(v)) << v << " not in [" << in.lo << ", " << in.hi << "]";
      }
      // Central differences of the value and of the first derivatives.
      const double e = 1e-5;
      const auto at = [&](double a, double b) { return jet_field(Jet<double>::variable_x(a), Jet<double>::variable_y(b)); };
      const Jet<double> xp = at(x + e, y), xm = at(x - e, y), yp = at(x, y + e), ym = at(x, y - e);
      const double tol = 1e-6 * (1.0 + std::abs(j.dxx) + std::abs(j.dyy) + std::abs(j.dxy));
      EXPECT_NEAR(j.dx, (xp.v - xm.v) / (2 * e), tol);
      EXPECT_NEAR(j.dy, (yp.v - ym.v) / (2 * e), tol);
      EXPECT_NEAR(j.dxx, (xp.dx - xm.dx) / (2 * e), tol);
      EXPECT_NEAR(j.dxy, (yp.dx - ym.dx) / (2 * e), tol);
      EXPECT_NEAR(j.dyy, (yp.dy - ym.dy) / (2 * e), tol);
    }
  }
}

TEST(Jet, ASquareIsNoWiderThanTheProductWithItself) {
  // sqr knows both factors are the same number: its enclosure lies inside the
  // product's (which treats them as independent), and its value part is never
  // negative. Doubling is exact.
  const Interval a(-0.5, 2.0);
  const Jet<Interval> x = Jet<Interval>::variable_x(a), y = Jet<Interval>::variable_y(Interval(1.0, 3.0));
  const Jet<Interval> f = x * y - 2.0 * x;  // a jet with every component nonzero over the box
  const Jet<Interval> s = pkmws::certified::sqr(f), p = f * f;
  for (const auto& [in, out] : {std::pair{s.v, p.v}, {s.dx, p.dx}, {s.dy, p.dy}, {s.dxx, p.dxx}, {s.dxy, p.dxy},
                                {s.dyy, p.dyy}}) {
    EXPECT_GE(in.lo, out.lo);
    EXPECT_LE(in.hi, out.hi);
  }
  EXPECT_GE(s.v.lo, 0.0);
  EXPECT_LT(p.v.lo, 0.0);
  const Interval t = pkmws::certified::twice(Interval(0.1, 0.3));
  EXPECT_EQ(t.lo, 0.2);
  EXPECT_EQ(t.hi, 0.6);
}

}  // namespace
