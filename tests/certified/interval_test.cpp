// Interval division: every quotient of points of the operands lies in the
// enclosure; a divisor with 0 at an end gives a half-line (the quotient over
// its nonzero points), one with 0 inside the whole line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pkmws/certified/interval.hpp"

namespace {

using pkmws::certified::Interval;

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

}  // namespace
