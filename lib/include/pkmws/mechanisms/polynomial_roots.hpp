// Roots of a real univariate polynomial of small degree (the direct
// kinematics eliminants of the 3-DOF mechanisms: degree 4 for the Assur group
// RP-RP-RP, degree 6 for the 3-RPR; docs/theory/three_dof.md).
//
// Real roots are isolated with a Sturm sequence (in long double) and refined
// by safeguarded Newton/bisection inside their isolating interval, so each
// reported real root comes with an interval that provably (up to the rounding
// of the Sturm chain) holds exactly one distinct root; complex roots are the
// eigenvalues of the companion matrix (Eigen), reported for completeness.
#pragma once

#include <complex>
#include <span>
#include <vector>

namespace pkmws::mechanisms {

struct RealRoot {
  double value = 0.0;
  double lower = 0.0;   // isolating interval [lower, upper] holding this root only
  double upper = 0.0;
  bool sign_change = true;  // p changes sign across the interval (odd multiplicity);
                            // false: an even-multiplicity (e.g. tangent, double) root
};

struct PolynomialRoots {
  int degree = 0;
  std::vector<RealRoot> real;                    // distinct real roots, ascending
  std::vector<std::complex<double>> complex;     // non-real roots (companion-matrix eigenvalues),
                                                 // with multiplicity, conjugate pairs adjacent
  std::vector<std::complex<double>> eigenvalues; // every root of the companion matrix (degree of them)
  int sturm_count = 0;                           // distinct real roots counted by the Sturm sequence
};

/// Roots of p(x) = sum_k coefficients[k] x^k (ascending order). Trailing
/// (leading-power) coefficients that are exactly zero are dropped; the
/// remaining leading coefficient must be non-zero (throws std::invalid_argument
/// when every coefficient is zero or not finite).
///
/// `multiple_tol` is the relative size below which a remainder of the Sturm
/// chain counts as zero: real roots closer than about sqrt(multiple_tol) times
/// the root scale are reported as one (even-multiplicity) root.
PolynomialRoots polynomial_roots(std::span<const long double> coefficients, long double multiple_tol = 1e-15L);

/// Horner evaluation in long double.
long double polynomial_value(std::span<const long double> coefficients, long double x);

/// Number of distinct real roots in (a, b] from the Sturm sequence of p.
int sturm_root_count(std::span<const long double> coefficients, long double a, long double b,
                     long double multiple_tol = 1e-15L);

}  // namespace pkmws::mechanisms
