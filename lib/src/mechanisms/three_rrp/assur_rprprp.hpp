// The class-3 Assur group RP-RP-RP ([Mitsi] §3; docs/theory/three_dof.md): three external
// revolutes A_1, A_2, A_3 at known positions, each on a slider that moves
// along one side line of a rigid triangle B1B2B3 (the platform of the 3-RRP and
// 3-PRP): slider i runs on side i, the line B_i B_{i+1}. Position analysis:
// given the A_i, find every placement of the triangle (every assembly mode).
//
// Conventions (reconstructed from [Mitsi] eq. 3-5 and 14-18, see
// docs/theory/three_dof.md): the triangle is counter-clockwise; side i has
// length l_i = |B_i B_{i+1}| and unit direction u_i from B_i to B_{i+1};
// α_i is the interior angle at B_i; the slider displacement s_i is the signed
// distance from A_i to B_i along u_i:
//
//   B_i = A_i + s_i u_i                                   ([Mitsi] eq. 14)
//   (s1 + l1)^2 + s2^2 + 2 (s1 + l1) s2 cos α2 = |A1 A2|^2   (eq. 3)
//   (s2 + l2)^2 + s3^2 + 2 (s2 + l2) s3 cos α3 = |A2 A3|^2   (eq. 4)
//   (s3 + l3)^2 + s1^2 + 2 (s3 + l3) s1 cos α1 = |A3 A1|^2   (eq. 5)
//
// Two independent solvers:
//  * assur_elimination: the paper's route. Eq. 3-5 as eq. 9-11, s2 eliminated
//    by a Sylvester resultant (eq. 12), then s3 (eq. 13). The eliminant has
//    nominal degree 8 in s1, but its coefficients of s1^8 ... s1^5 vanish
//    identically (s1^8: 16 G^2 with G = cos²α1 + cos²α2 + cos²α3 +
//    2 cos α1 cos α2 cos α3 - 1 = 0 for the angles of a triangle; the next three
//    by the triangle's closure, see the theory note): the TRUE degree is 4.
//    Its four roots are the two placements of the triangle A1A2A3 and the two
//    of its mirror image (eq. 3-5 only know the distances |A_i A_j|); the
//    back-substitution (eq. 14-18) keeps the placements of the true one.
//  * assur_closed_form: the three lines through the A_i with the triangle's
//    side directions rotated by ψ bound a triangle similar to B1B2B3 with scale
//    λ(ψ) = (C cos ψ + S sin ψ) / (2 area); its side l_1 λ(ψ) = K sin(ψ + δ)
//    equals l_1 at two rotations, one (tangent: a type-2 singularity) or none.
// Both return at most two assemblies and agree to machine precision.
#pragma once

#include <algorithm>
#include <array>
#include <complex>
#include <cstddef>
#include <vector>

#include "pkmws/geometry/types.hpp"
#include "pkmws/mechanisms/polynomial_roots.hpp"

namespace pkmws::mechanisms {

using geometry::Point;

/// The rigid triangle B1B2B3 of the triad, in its own (platform) frame.
struct AssurTriangle {
  std::array<Point, 3> vertices;      // B'_i, counter-clockwise
  std::array<double, 3> side{};       // l_i = |B_i B_{i+1}|
  std::array<double, 3> angle{};      // α_i: interior angle at B_i (radians)
  std::array<Point, 3> direction;     // u'_i: unit direction of side i, B_i -> B_{i+1}
  std::array<Point, 3> normal;        // n'_i: outward unit normal of side i, (u_y, -u_x)
  std::array<double, 3> offset{};     // h_i = n'_i . B'_i: side line i is {X : n'_i . X = h_i}
  double area = 0.0;                  // > 0

  /// Throws std::invalid_argument unless the points form a counter-clockwise,
  /// non-degenerate triangle (area > 1e-12 times the longest side squared).
  static AssurTriangle from_vertices(const std::array<Point, 3>& vertices);
};

/// One assembly of the triad.
struct AssurAssembly {
  double phi = 0.0;                  // rotation of the platform frame, radians in (-pi, pi]
  Point origin;                      // the platform frame's origin in the base frame
  std::array<Point, 3> vertices;     // B1, B2, B3 in the base frame
  std::array<double, 3> s{};         // slider displacements: B_i = A_i + s_i u_i (eq. 14)
};

/// Closed form (docs/theory/three_dof.md note). Assemblies sorted by phi; none when the
/// A_i all coincide or the sinusoid's amplitude is below l_1.
std::vector<AssurAssembly> assur_closed_form(const AssurTriangle& triangle, const std::array<Point, 3>& a);

/// λ(ψ) = (C cos ψ + S sin ψ) / (2 area): scale, relative to the platform, of
/// the triangle bounded by the three side lines through the A_i rotated by ψ.
/// Returns {C / (2 area), S / (2 area)}; amplitude hypot of them (assemble iff >= 1).
std::array<double, 2> assur_scale_sinusoid(const AssurTriangle& triangle, const std::array<Point, 3>& a);

// ---------------------------------------------------------------------------
// The paper's elimination ([Mitsi] eq. 9-13), generic in the scalar so that a
// test can run it in exact rational arithmetic.

/// Coefficients a_ij of [Mitsi] eq. 9-11:
///   s1^2 + s2^2 + a11 s1 s2 + a12 s1 + a13 s2 + a14 = 0   (eq. 9)
///   s2^2 + s3^2 + a21 s2 s3 + a22 s2 + a23 s3 + a24 = 0   (eq. 10)
///   s3^2 + s1^2 + a31 s3 s1 + a32 s3 + a33 s1 + a34 = 0   (eq. 11)
/// Row i holds a_{i+1, 1..4}.
template <class T>
struct AssurQuadratics {
  std::array<std::array<T, 4>, 3> a;
};

/// From eq. 3-5: a11 = 2 cos α2, a12 = 2 l1, a13 = 2 l1 cos α2, a14 = l1^2 - |A1A2|^2;
/// a21 = 2 cos α3, a22 = 2 l2, a23 = 2 l2 cos α3, a24 = l2^2 - |A2A3|^2;
/// a31 = 2 cos α1, a32 = 2 l3, a33 = 2 l3 cos α1, a34 = l3^2 - |A3A1|^2.
/// `cos_angle[i]` = cos α_{i+1}; `squared_distance` = |A1A2|^2, |A2A3|^2, |A3A1|^2.
template <class T>
AssurQuadratics<T> assur_quadratics(const std::array<T, 3>& side, const std::array<T, 3>& cos_angle,
                                    const std::array<T, 3>& squared_distance) {
  AssurQuadratics<T> q;
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const T& c = cos_angle[static_cast<std::size_t>((i + 1) % 3)];  // eq. 3 uses α2, eq. 4 α3, eq. 5 α1
    q.a[k] = {T(2) * c, T(2) * side[k], T(2) * side[k] * c, side[k] * side[k] - squared_distance[k]};
  }
  return q;
}

namespace assur_detail {

template <class T>
using Poly = std::vector<T>;  // ascending powers of s1
template <class T>
using BiPoly = std::vector<Poly<T>>;  // index: power of s3; entries: polynomials in s1

template <class T>
Poly<T> add(const Poly<T>& a, const Poly<T>& b, int sign = 1) {
  Poly<T> r(std::max(a.size(), b.size()), T(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (sign > 0) {
      r[i] += b[i];
    } else {
      r[i] -= b[i];
    }
  }
  return r;
}

template <class T>
Poly<T> mul(const Poly<T>& a, const Poly<T>& b) {
  if (a.empty() || b.empty()) return {};
  Poly<T> r(a.size() + b.size() - 1, T(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

template <class T>
BiPoly<T> add(const BiPoly<T>& a, const BiPoly<T>& b, int sign = 1) {
  BiPoly<T> r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i] = add(i < a.size() ? a[i] : Poly<T>{}, i < b.size() ? b[i] : Poly<T>{}, sign);
  }
  return r;
}

template <class T>
BiPoly<T> mul(const BiPoly<T>& a, const BiPoly<T>& b) {
  if (a.empty() || b.empty()) return {};
  BiPoly<T> r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] = add(r[i + j], mul(a[i], b[j]));
  return r;
}

}  // namespace assur_detail

/// Bivariate F1(s1, s3) = Res_{s2}(eq. 9, eq. 10) ([Mitsi] eq. 12), as
/// coefficients F1[j][i] of s3^j s1^i. Both equations are monic quadratics in
/// s2, x^2 + p x + q, so their Sylvester resultant is
/// (q10 - q9)^2 - (p10 - p9)(p9 q10 - q9 p10) = Δp^2 q9 - Δp Δq p9 + Δq^2.
template <class T>
std::vector<std::vector<T>> assur_first_resultant(const AssurQuadratics<T>& q) {
  using namespace assur_detail;
  const auto& a1 = q.a[0];
  const auto& a2 = q.a[1];
  const BiPoly<T> p9{{a1[2], a1[0]}};                 // a13 + a11 s1
  const BiPoly<T> q9{{a1[3], a1[1], T(1)}};           // a14 + a12 s1 + s1^2
  const BiPoly<T> p10{{a2[1]}, {a2[0]}};              // a22 + a21 s3
  const BiPoly<T> q10{{a2[3]}, {a2[2]}, {T(1)}};      // a24 + a23 s3 + s3^2
  const BiPoly<T> dp = add(p10, p9, -1), dq = add(q10, q9, -1);
  return add(add(mul(mul(dp, dp), q9), mul(mul(dp, dq), p9), -1), mul(dq, dq));
}

/// The eliminant R(s1) = Res_{s3}(eq. 11, F1) ([Mitsi] eq. 13), ascending
/// coefficients of s1^0 ... s1^8. Eq. 11 is monic in s3, s3^2 + p s3 + q, so
/// with F1 reduced modulo it to α(s1) s3 + β(s1) the Sylvester resultant is
/// the product over its roots τ1, τ2 of F1(s1, τ): α^2 q - α β p + β^2.
/// For a real triangle the coefficients of s1^5 ... s1^8 vanish identically.
template <class T>
std::array<T, 9> assur_eliminant(const AssurQuadratics<T>& q) {
  using namespace assur_detail;
  BiPoly<T> f = assur_first_resultant(q);
  const auto& a3 = q.a[2];
  const Poly<T> p11{a3[1], a3[0]};        // a32 + a31 s1
  const Poly<T> q11{a3[3], a3[2], T(1)};  // a34 + a33 s1 + s1^2
  while (f.size() < 2) f.push_back({});
  for (std::size_t j = f.size(); j-- > 2;) {  // s3^j = -s3^{j-2} (p s3 + q)
    f[j - 1] = add(f[j - 1], mul(f[j], p11), -1);
    f[j - 2] = add(f[j - 2], mul(f[j], q11), -1);
    f[j].clear();
  }
  const Poly<T>& alpha = f[1];
  const Poly<T>& beta = f[0];
  const Poly<T> r = add(add(mul(mul(alpha, alpha), q11), mul(mul(alpha, beta), p11), -1), mul(beta, beta));
  std::array<T, 9> out;
  out.fill(T(0));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < 9) out[i] = r[i];
  }
  return out;
}

/// A real root s1 of the eliminant with its back-substitution.
struct AssurRealRoot {
  double s1 = 0.0;
  bool assembled = false;            // a placement of the true triangle (false: its mirror image)
  std::array<double, 3> s{};         // (s1, s2, s3) solving eq. 9-11 (polished by Newton)
  double residual = 0.0;             // max |eq. 9-11| / (L^2 + |s|^2) after polishing
};

struct AssurElimination {
  double length_scale = 1.0;               // L: the equations are solved in s / L
  std::array<long double, 9> eliminant{};  // R(σ), σ = s1 / L, nominal degree 8 (eq. 13)
  PolynomialRoots roots;                   // of the true (degree-4) eliminant, in σ = s1 / L
  std::vector<double> real_s1;             // real roots, in the mechanism's unit
  std::vector<std::complex<double>> complex_s1;  // complex roots, in the mechanism's unit
  std::vector<AssurRealRoot> real_roots;   // every real solution of eq. 9-11 (true and mirror)
  std::vector<AssurAssembly> assemblies;   // the true triangle's placements, sorted by phi
};

/// The paper's method ([Mitsi] eq. 9-18). The eliminant is computed in long
/// double; its coefficients of σ^5..σ^8 are roundoff of identically vanishing
/// terms and are dropped. Real roots: Sturm isolation + Newton; each is polished
/// on eq. 9-11, back-substituted by eq. 14-18 (every angle from atan2 of its
/// sine and cosine) and kept when the third chain closes (the true triangle).
AssurElimination assur_elimination(const AssurTriangle& triangle, const std::array<Point, 3>& a);

}  // namespace pkmws::mechanisms
