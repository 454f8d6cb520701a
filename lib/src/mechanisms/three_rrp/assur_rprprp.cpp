// The Assur group RP-RP-RP ([Mitsi] §3): closed form and the paper's
// elimination (eq. 3-18). Derivations in docs/theory/three_dof.md.
#include "mechanisms/three_rrp/assur_rprprp.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

namespace pkmws::mechanisms {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();

Point rotate(Point v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
Point perp(Point v) { return {-v.y, v.x}; }  // J v: rotation by +90 degrees

double wrap_pi(double q) {
  double r = std::remainder(q, 2.0 * pi);
  if (r <= -pi) r += 2.0 * pi;
  return r;
}

// Origin of the platform frame from the three placed vertices (their mean
// misfit is a few ulps; averaging keeps the result symmetric in the vertices).
Point frame_origin(const AssurTriangle& t, const std::array<Point, 3>& b, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  Point o{0.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i) o = o + (1.0 / 3.0) * (b[i] - rotate(t.vertices[i], c, s));
  return o;
}

// The placement at rotation psi: side line i is {X : n_i . X = n_i . A_i - h_i}
// with n_i = R(psi) n'_i (the line through A_i); P solves the three equations
// in least squares (they are consistent at a root of the sinusoid).
AssurAssembly place(const AssurTriangle& t, const std::array<Point, 3>& a, double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix2d n_n = Eigen::Matrix2d::Zero();
  Eigen::Vector2d n_r = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < 3; ++i) {
    const Point n = rotate(t.normal[i], c, s);
    const double rhs = dot(n, a[i]) - t.offset[i];
    n_n(0, 0) += n.x * n.x; n_n(0, 1) += n.x * n.y; n_n(1, 1) += n.y * n.y;
    n_r(0) += n.x * rhs; n_r(1) += n.y * rhs;
  }
  n_n(1, 0) = n_n(0, 1);
  const Eigen::Vector2d p = n_n.ldlt().solve(n_r);
  AssurAssembly out;
  out.phi = wrap_pi(psi);
  out.origin = {p(0), p(1)};
  for (std::size_t i = 0; i < 3; ++i) {
    out.vertices[i] = out.origin + rotate(t.vertices[i], c, s);
    out.s[i] = dot(out.vertices[i] - a[i], rotate(t.direction[i], c, s));
  }
  return out;
}

// Final refinement of an assembly by Newton (long double) on the three
// incidence conditions g_i = n_i(phi) . (A_i - P) - h_i = 0 in (P, phi): near a
// double solution of eq. 9-11 (nearly collinear A's, whose mirror image is
// almost the same triangle) their Newton stalls at ~sqrt(eps), while these
// conditions still have a simple root.
void polish(const AssurTriangle& t, const std::array<Point, 3>& a, AssurAssembly& as) {
  using LD = long double;
  LD x = as.origin.x, y = as.origin.y, phi = as.phi;
  auto residual = [&](LD px, LD py, LD ph, Eigen::Matrix<LD, 3, 3>* jac) {
    Eigen::Matrix<LD, 3, 1> g;
    const LD c = std::cos(ph), s = std::sin(ph);
    for (int i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const LD nx = c * t.normal[k].x - s * t.normal[k].y, ny = s * t.normal[k].x + c * t.normal[k].y;
      const LD dx = a[k].x - px, dy = a[k].y - py;
      g(i) = nx * dx + ny * dy - t.offset[k];
      if (jac) {
        (*jac)(i, 0) = -nx;
        (*jac)(i, 1) = -ny;
        (*jac)(i, 2) = -ny * dx + nx * dy;  // (J n) . (A - P)
      }
    }
    return g;
  };
  Eigen::Matrix<LD, 3, 3> jac;
  LD res = residual(x, y, phi, &jac).cwiseAbs().maxCoeff();
  for (int it = 0; it < 6 && res > 0.0L; ++it) {
    const Eigen::Matrix<LD, 3, 1> step = jac.fullPivLu().solve(residual(x, y, phi, nullptr));
    if (!step.allFinite()) break;
    Eigen::Matrix<LD, 3, 3> next_jac;
    const LD nres = residual(x - step(0), y - step(1), phi - step(2), &next_jac).cwiseAbs().maxCoeff();
    if (!(nres < res)) break;
    x -= step(0);
    y -= step(1);
    phi -= step(2);
    res = nres;
    jac = next_jac;
  }
  as.phi = wrap_pi(static_cast<double>(phi));
  as.origin = {static_cast<double>(x), static_cast<double>(y)};
  const LD c = std::cos(phi), s = std::sin(phi);
  for (std::size_t i = 0; i < 3; ++i) {
    const LD bx = x + c * t.vertices[i].x - s * t.vertices[i].y, by = y + s * t.vertices[i].x + c * t.vertices[i].y;
    as.vertices[i] = {static_cast<double>(bx), static_cast<double>(by)};
    const LD ux = c * t.direction[i].x - s * t.direction[i].y, uy = s * t.direction[i].x + c * t.direction[i].y;
    as.s[i] = static_cast<double>((bx - a[i].x) * ux + (by - a[i].y) * uy);
  }
}

bool same_assembly(const AssurAssembly& x, const AssurAssembly& y, double length) {
  return std::abs(wrap_pi(x.phi - y.phi)) <= 1e-9 && norm(x.origin - y.origin) <= 1e-9 * length;
}

void sort_by_phi(std::vector<AssurAssembly>& v) {
  std::sort(v.begin(), v.end(), [](const AssurAssembly& x, const AssurAssembly& y) { return x.phi < y.phi; });
}

}  // namespace

AssurTriangle AssurTriangle::from_vertices(const std::array<Point, 3>& vertices) {
  AssurTriangle t;
  t.vertices = vertices;
  double longest = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(vertices[i].x) || !std::isfinite(vertices[i].y)) {
      throw std::invalid_argument("platform: non-finite vertex");
    }
    longest = std::max(longest, norm(vertices[(i + 1) % 3] - vertices[i]));
  }
  t.area = 0.5 * cross(vertices[1] - vertices[0], vertices[2] - vertices[0]);
  if (!(t.area > 1e-12 * longest * longest)) {
    throw std::invalid_argument(t.area < 0.0 ? "platform: B1, B2, B3 must be counter-clockwise"
                                             : "platform: B1, B2, B3 must not be collinear");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const Point d = vertices[(i + 1) % 3] - vertices[i];
    t.side[i] = norm(d);
    t.direction[i] = (1.0 / t.side[i]) * d;
    t.normal[i] = {t.direction[i].y, -t.direction[i].x};
    t.offset[i] = dot(t.normal[i], vertices[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const Point u = t.direction[i], back = -1.0 * t.direction[(i + 2) % 3];  // B_i -> B_{i-1}
    t.angle[i] = std::atan2(cross(u, back), dot(u, back));
  }
  return t;
}

std::array<double, 2> assur_scale_sinusoid(const AssurTriangle& t, const std::array<Point, 3>& a) {
  // Σ l_i n_i(ψ) . A_i = 2 area λ(ψ), n_i(ψ) = cos ψ n'_i + sin ψ J n'_i: the P terms
  // cancel because Σ l_i n'_i = 0, and Σ l_i h_i = 2 area.
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    c += t.side[i] * dot(t.normal[i], a[i]);
    s += t.side[i] * dot(perp(t.normal[i]), a[i]);
  }
  return {c / (2.0 * t.area), s / (2.0 * t.area)};
}

std::vector<AssurAssembly> assur_closed_form(const AssurTriangle& t, const std::array<Point, 3>& a) {
  const auto [c, s] = assur_scale_sinusoid(t, a);
  const double amplitude = std::hypot(c, s);
  std::vector<AssurAssembly> out;
  if (!(amplitude > 0.0)) return out;
  // λ(ψ) = amplitude cos(ψ - δ) = 1; side l_1 λ(ψ) = l_1 amplitude sin(ψ - δ + pi/2).
  const double delta = std::atan2(s, c);
  const double ratio = 1.0 / amplitude;
  constexpr double tangent_tol = 8.0 * eps;
  if (ratio > 1.0 + tangent_tol) return out;
  if (ratio >= 1.0 - tangent_tol) {
    out.push_back(place(t, a, delta));  // tangent: one (type-2 singular) assembly
    return out;
  }
  const double beta = std::acos(ratio);
  out.push_back(place(t, a, delta - beta));
  out.push_back(place(t, a, delta + beta));
  sort_by_phi(out);
  return out;
}

AssurElimination assur_elimination(const AssurTriangle& t, const std::array<Point, 3>& a) {
  AssurElimination out;
  const std::array<double, 3> dist2 = {dot(a[1] - a[0], a[1] - a[0]), dot(a[2] - a[1], a[2] - a[1]),
                                       dot(a[0] - a[2], a[0] - a[2])};
  double length = 0.0;
  for (std::size_t i = 0; i < 3; ++i) length = std::max({length, t.side[i], std::sqrt(dist2[i])});
  out.length_scale = length;
  using LD = long double;
  const LD ll = length;
  // The data of eq. 3-5 in long double straight from the points (distances,
  // sides and cosines rounded once in double would perturb the problem).
  std::array<LD, 3> side{}, cosine{}, d2{};
  auto sub = [](Point p, Point q) { return std::array<LD, 2>{static_cast<LD>(p.x) - q.x, static_cast<LD>(p.y) - q.y}; };
  for (std::size_t i = 0; i < 3; ++i) {
    const auto e = sub(t.vertices[(i + 1) % 3], t.vertices[i]);        // side i
    const auto back = sub(t.vertices[(i + 2) % 3], t.vertices[i]);     // B_i -> B_{i-1}
    const auto ad = sub(a[(i + 1) % 3], a[i]);
    side[i] = std::hypot(e[0], e[1]) / ll;
    cosine[i] = (e[0] * back[0] + e[1] * back[1]) / (std::hypot(e[0], e[1]) * std::hypot(back[0], back[1]));
    d2[i] = (ad[0] * ad[0] + ad[1] * ad[1]) / (ll * ll);
  }
  const AssurQuadratics<LD> q = assur_quadratics(side, cosine, d2);  // eq. 9-11 in σ = s / L
  out.eliminant = assur_eliminant(q);                                // eq. 12-13
  // The coefficients of σ^5..σ^8 vanish identically (docs/theory/three_dof.md):
  // what is computed there is rounding; the eliminant is the quartic.
  const std::array<LD, 5> quartic = {out.eliminant[0], out.eliminant[1], out.eliminant[2], out.eliminant[3],
                                     out.eliminant[4]};
  bool all_zero = true;
  for (LD c : quartic) all_zero = all_zero && c == 0.0L;
  if (all_zero) return out;
  out.roots = polynomial_roots(quartic);
  for (const RealRoot& r : out.roots.real) out.real_s1.push_back(r.value * length);
  for (const auto& z : out.roots.complex) out.complex_s1.push_back(z * length);

  const auto& A = q.a;
  auto residuals = [&](const std::array<LD, 3>& x) {
    return std::array<LD, 3>{
        x[0] * x[0] + x[1] * x[1] + A[0][0] * x[0] * x[1] + A[0][1] * x[0] + A[0][2] * x[1] + A[0][3],   // eq. 9
        x[1] * x[1] + x[2] * x[2] + A[1][0] * x[1] * x[2] + A[1][1] * x[1] + A[1][2] * x[2] + A[1][3],   // eq. 10
        x[2] * x[2] + x[0] * x[0] + A[2][0] * x[2] * x[0] + A[2][1] * x[2] + A[2][2] * x[0] + A[2][3]};  // eq. 11
  };
  auto size = [](const std::array<LD, 3>& r) { return std::max({std::fabs(r[0]), std::fabs(r[1]), std::fabs(r[2])}); };
  // Residual relative to the size of the terms (s_i ~ 20 L happens).
  auto relative = [](const std::array<LD, 3>& x, LD residual) {
    return residual / (1.0L + x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  };

  std::vector<std::pair<AssurAssembly, double>> found;  // assembly, chain-closure misfit
  for (const RealRoot& root : out.roots.real) {
    const RealRoot* root_ptr = &root;
    const LD seed = root.value, s1 = seed;
    // s3 from eq. 11 and s2 from eq. 9 (quadratics in s3 and s2): of the four
    // pairs keep those that also fit eq. 10. (Eliminating s2 linearly through
    // eq. 9 - eq. 10 fails where the true and the mirror solution share s1 and
    // s3: both then solve eq. 9 and 10, whose difference loses its s2 term.)
    const LD p11 = A[2][0] * s1 + A[2][1], q11 = s1 * s1 + A[2][2] * s1 + A[2][3];
    const LD p9 = A[0][0] * s1 + A[0][2], q9 = s1 * s1 + A[0][1] * s1 + A[0][3];
    const LD d11 = std::sqrt(std::max(0.0L, p11 * p11 - 4.0L * q11));
    const LD d9 = std::sqrt(std::max(0.0L, p9 * p9 - 4.0L * q9));
    std::vector<std::array<LD, 3>> candidates;
    for (int sign3 : {-1, 1}) {
      for (int sign2 : {-1, 1}) {
        const std::array<LD, 3> x{s1, (-p9 + static_cast<LD>(sign2) * d9) / 2.0L,
                                  (-p11 + static_cast<LD>(sign3) * d11) / 2.0L};
        if (relative(x, size(residuals(x))) <= 1e-6L) candidates.push_back(x);
      }
    }
    for (std::array<LD, 3> x : candidates) {
      // Newton on eq. 9-11 (the paper's system), while the residual decreases.
      LD res = size(residuals(x));
      for (int it = 0; it < 8 && res > 0.0L; ++it) {
        const auto r = residuals(x);
        Eigen::Matrix<LD, 3, 3> j;
        j << 2 * x[0] + A[0][0] * x[1] + A[0][1], 2 * x[1] + A[0][0] * x[0] + A[0][2], 0.0L,
            0.0L, 2 * x[1] + A[1][0] * x[2] + A[1][1], 2 * x[2] + A[1][0] * x[1] + A[1][2],
            2 * x[0] + A[2][0] * x[2] + A[2][2], 0.0L, 2 * x[2] + A[2][0] * x[0] + A[2][1];
        const Eigen::Matrix<LD, 3, 1> step = j.fullPivLu().solve(Eigen::Matrix<LD, 3, 1>(r[0], r[1], r[2]));
        if (!step.allFinite()) break;
        const std::array<LD, 3> next{x[0] - step(0), x[1] - step(1), x[2] - step(2)};
        const LD next_res = size(residuals(next));
        if (!(next_res < res)) break;
        x = next;
        res = next_res;
      }
      AssurRealRoot info;
      info.s1 = static_cast<double>(x[0] * ll);
      info.s = {static_cast<double>(x[0] * ll), static_cast<double>(x[1] * ll), static_cast<double>(x[2] * ll)};
      info.residual = static_cast<double>(relative(x, res));
      if (!(info.residual <= 1e-12)) continue;  // Newton did not converge to a solution
      // Polishing must not carry s1 onto a neighbouring root (near a double
      // solution Newton can wander there; that root is back-substituted from
      // its own seed).
      bool wandered = false;
      for (const RealRoot& other : out.roots.real) {
        const LD other_value = other.value;
        if (&other != root_ptr && std::fabs(x[0] - other_value) < 1e-3L * std::fabs(seed - other_value)) wandered = true;
      }
      if (wandered) continue;
      const double reach = length + std::max({std::abs(info.s[0]), std::abs(info.s[1]), std::abs(info.s[2])});
      bool seen = false;
      for (const AssurRealRoot& other : out.real_roots) {
        seen = seen || std::max({std::abs(other.s[0] - info.s[0]), std::abs(other.s[1] - info.s[1]),
                                 std::abs(other.s[2] - info.s[2])}) <= 1e-9 * reach;
      }
      if (seen) continue;  // two candidates polished to the same solution
      // Back-substitution (eq. 14-18) from the pair of chains k, k+1 whose A's are
      // farthest apart (the paper's k = 1 unless A1 and A2 nearly coincide).
      std::size_t k = 0;
      if (dist2[0] < 1e-12 * length * length) k = dist2[1] >= dist2[2] ? 1 : 2;
      const std::size_t k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      // In long double: a placement far from the A's (|s| >> L) amplifies the
      // rounding of φ_1 by |s|.
      const LD sk = x[k] * ll, sk1 = x[k1] * ll;
      const LD theta = std::atan2(static_cast<LD>(a[k1].y) - a[k].y, static_cast<LD>(a[k1].x) - a[k].x);  // eq. 15: θ_1
      // eq. 16 (law of sines) with the law-of-cosines partner, both over |A1 A2|:
      // sin γ1 = s2 sin α2 / l, cos γ1 = ((s1 + l1) + s2 cos α2) / l.
      const LD gamma = std::atan2(sk1 * std::sin(static_cast<LD>(t.angle[k1])),
                                  (sk + t.side[k]) + sk1 * std::cos(static_cast<LD>(t.angle[k1])));
      const LD phi_k = theta + gamma;  // eq. 15: direction φ_1 of side 1
      const LD phi_k2 = phi_k + t.angle[k];
      const LD bkx = a[k].x + sk * std::cos(phi_k), bky = a[k].y + sk * std::sin(phi_k);  // eq. 14
      std::array<Point, 3> b;
      b[k] = {static_cast<double>(bkx), static_cast<double>(bky)};
      b[k1] = {static_cast<double>(bkx + t.side[k] * std::cos(phi_k)),                    // eq. 17
               static_cast<double>(bky + t.side[k] * std::sin(phi_k))};
      b[k2] = {static_cast<double>(bkx + t.side[k2] * std::cos(phi_k2)),                  // eq. 18
               static_cast<double>(bky + t.side[k2] * std::sin(phi_k2))};
      // The third chain closes only for the true triangle A1A2A3 (eq. 3-5 also
      // admit its mirror image): A_{k+2} must lie on side line k+2.
      const Point u2 = b[k] - b[k2];
      const double misfit = std::abs(cross(u2, a[k2] - b[k2])) / norm(u2);
      info.assembled = misfit <= 1e-8 * reach;
      out.real_roots.push_back(info);
      if (!info.assembled) continue;
      AssurAssembly as;
      as.phi = wrap_pi(static_cast<double>(phi_k - std::atan2(static_cast<LD>(t.direction[k].y), t.direction[k].x)));
      as.vertices = b;
      as.origin = frame_origin(t, b, as.phi);
      as.s = info.s;
      polish(t, a, as);
      bool duplicate = false;
      for (auto& [other, other_misfit] : found) {
        if (same_assembly(other, as, length)) {
          duplicate = true;
          if (misfit < other_misfit) {
            other = as;
            other_misfit = misfit;
          }
        }
      }
      if (!duplicate) found.push_back({as, misfit});
    }
  }
  for (const auto& f : found) out.assemblies.push_back(f.first);
  sort_by_phi(out.assemblies);
  return out;
}

}  // namespace pkmws::mechanisms
