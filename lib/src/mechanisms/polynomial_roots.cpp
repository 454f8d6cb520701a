// Real-root isolation by Sturm sequences, refinement by safeguarded Newton /
// bisection, complex roots from the companion matrix (docs/theory/three_dof.md).
#include "pkmws/mechanisms/polynomial_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

namespace pkmws::mechanisms {

namespace {

using Poly = std::vector<long double>;  // ascending coefficients

long double max_abs(const Poly& p) {
  long double m = 0.0L;
  for (long double c : p) m = std::max(m, std::fabs(c));
  return m;
}

void trim_exact(Poly& p) {
  while (!p.empty() && p.back() == 0.0L) p.pop_back();
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(static_cast<long double>(k) * p[k]);
  return d;
}

long double horner(const Poly& p, long double x) {
  long double v = 0.0L;
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + p[k];
  return v;
}

// Sturm chain p0 = p, p1 = p', p_{k+1} = -rem(p_{k-1}, p_k). A remainder whose
// coefficients are below tol times the size of the terms that produced it is
// zero (the chain then ends at an approximate gcd: multiple roots). Every
// member is scaled to max-abs 1 (positive factors keep the sign counts).
std::vector<Poly> sturm_chain(const Poly& p, long double tol) {
  std::vector<Poly> chain;
  Poly a = p;
  const long double ma = max_abs(a);
  for (auto& c : a) c /= ma;
  chain.push_back(a);
  Poly b = derivative(a);
  const long double mb = max_abs(b);
  if (mb == 0.0L) return chain;
  for (auto& c : b) c /= mb;
  chain.push_back(b);
  while (chain.back().size() > 1) {
    Poly r = chain[chain.size() - 2];
    const Poly& d = chain.back();
    long double quotient_size = 0.0L;
    while (r.size() >= d.size()) {
      const long double f = r.back() / d.back();
      quotient_size = std::max(quotient_size, std::fabs(f));
      const std::size_t shift = r.size() - d.size();
      for (std::size_t k = 0; k < d.size(); ++k) r[k + shift] -= f * d[k];
      r.pop_back();
    }
    const long double scale = 1.0L + quotient_size;  // members have max-abs 1
    while (!r.empty() && std::fabs(r.back()) <= tol * scale) r.pop_back();
    if (r.empty()) break;
    const long double mr = max_abs(r);
    for (auto& c : r) c = -c / mr;
    chain.push_back(std::move(r));
  }
  return chain;
}

int sign_of(long double v) { return v > 0.0L ? 1 : (v < 0.0L ? -1 : 0); }

int variations(const std::vector<Poly>& chain, long double x) {
  int count = 0, last = 0;
  for (const Poly& q : chain) {
    const int s = sign_of(horner(q, x));
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

int variations_at_infinity(const std::vector<Poly>& chain, int direction) {
  int count = 0, last = 0;
  for (const Poly& q : chain) {
    int s = sign_of(q.back());
    if (direction < 0 && (q.size() - 1) % 2 == 1) s = -s;
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

// Fujiwara's bound on the moduli of the roots.
long double root_bound(const Poly& p) {
  const std::size_t n = p.size() - 1;
  long double b = 0.0L;
  for (std::size_t k = 1; k <= n; ++k) {
    long double r = std::fabs(p[n - k] / p[n]);
    if (k == n) r /= 2.0L;
    b = std::max(b, std::pow(r, 1.0L / static_cast<long double>(k)));
  }
  return 2.0L * b * (1.0L + 1e-6L) + std::numeric_limits<long double>::min();
}

// Root of p with a sign change in [a, b] (fa = p(a) != 0): safeguarded Newton.
long double bracketed_root(const Poly& p, const Poly& dp, long double a, long double b) {
  long double lo = a, hi = b;
  const int s_lo = horner(p, a) > 0.0L ? 1 : -1;
  long double x = 0.5L * (lo + hi);
  for (int it = 0; it < 300; ++it) {
    const long double fx = horner(p, x);
    if (fx == 0.0L) return x;
    if ((fx > 0.0L ? 1 : -1) == s_lo) lo = x; else hi = x;
    const long double dfx = horner(dp, x);
    long double next = dfx != 0.0L ? x - fx / dfx : 0.5L * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5L * (lo + hi);
    const bool done = next == x || hi - lo <= 4.0L * std::numeric_limits<long double>::epsilon() *
                                                   std::max(std::fabs(lo), std::fabs(hi));
    x = next;
    if (done) break;
  }
  return x;
}

// The root(s) of p in the isolating interval (a, b].
std::vector<RealRoot> refine(const Poly& p, const Poly& dp, long double a, long double b,
                             const std::vector<std::complex<double>>& eigenvalues) {
  RealRoot out;
  out.lower = static_cast<double>(a);
  out.upper = static_cast<double>(b);
  const long double fb = horner(p, b);
  if (fb == 0.0L) {
    out.value = static_cast<double>(b);
    return {out};
  }
  const long double fa = horner(p, a);
  if (sign_of(fa) * sign_of(fb) < 0) {
    out.value = static_cast<double>(bracketed_root(p, dp, a, b));
    return {out};
  }
  // No sign change: the Sturm chain merged an even-multiplicity root, or two
  // roots closer than its tolerance. Locate the cluster's centre m (the
  // companion eigenvalues inside the interval nearest the real axis give a
  // start, Newton on p' the vertex), then try to split: with p(m) p''(m) < 0
  // the local quadratic has roots m ± δ, and a sign change of p across each
  // proves two distinct real roots.
  std::vector<std::complex<double>> inside;
  for (const auto& z : eigenvalues) {
    if (std::isfinite(z.real()) && z.real() >= a && z.real() <= b) inside.push_back(z);
  }
  std::sort(inside.begin(), inside.end(), [](const auto& u, const auto& v) { return std::abs(u.imag()) < std::abs(v.imag()); });
  long double m = 0.5L * (a + b);
  if (inside.size() >= 2) {
    m = 0.5L * (static_cast<long double>(inside[0].real()) + inside[1].real());
  } else if (inside.size() == 1) {
    m = inside[0].real();
  }
  const Poly ddp = derivative(dp);
  for (int it = 0; it < 20; ++it) {  // the vertex (or double root) is a simple root of p'
    const long double dd = horner(ddp, m);
    if (dd == 0.0L) break;
    const long double next = m - horner(dp, m) / dd;
    if (!(next >= a && next <= b) || next == m) break;
    m = next;
  }
  const long double pm = horner(p, m), d2 = horner(ddp, m);
  if (pm != 0.0L && d2 != 0.0L && sign_of(pm) != sign_of(d2)) {
    const long double delta = std::sqrt(-2.0L * pm / d2);
    const long double left = m - 2.0L * delta, right = m + 2.0L * delta;
    if (left > a && right <= b && sign_of(horner(p, left)) != sign_of(pm) && sign_of(horner(p, right)) != sign_of(pm)) {
      RealRoot r1 = out, r2 = out;
      r1.upper = r2.lower = static_cast<double>(m);
      r1.value = static_cast<double>(bracketed_root(p, dp, left, m));
      r2.value = static_cast<double>(bracketed_root(p, dp, m, right));
      return {r1, r2};
    }
  }
  out.sign_change = false;
  out.value = static_cast<double>(m);
  return {out};
}

Poly prepare(std::span<const long double> coefficients) {
  Poly p(coefficients.begin(), coefficients.end());
  for (long double c : p) {
    if (!std::isfinite(c)) throw std::invalid_argument("polynomial_roots: non-finite coefficient");
  }
  trim_exact(p);
  if (p.empty()) throw std::invalid_argument("polynomial_roots: the zero polynomial has no isolated roots");
  return p;
}

}  // namespace

long double polynomial_value(std::span<const long double> coefficients, long double x) {
  return horner(Poly(coefficients.begin(), coefficients.end()), x);
}

int sturm_root_count(std::span<const long double> coefficients, long double a, long double b, long double multiple_tol) {
  const Poly p = prepare(coefficients);
  if (p.size() == 1) return 0;
  const auto chain = sturm_chain(p, multiple_tol);
  return variations(chain, a) - variations(chain, b);
}

PolynomialRoots polynomial_roots(std::span<const long double> coefficients, long double multiple_tol) {
  const Poly p = prepare(coefficients);
  PolynomialRoots out;
  out.degree = static_cast<int>(p.size()) - 1;
  if (out.degree == 0) return out;

  // Every root: eigenvalues of the companion matrix of the monic polynomial.
  const int n = out.degree;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < n; ++i) companion(i, n - 1) = -static_cast<double>(p[static_cast<std::size_t>(i)] / p.back());
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
  if (solver.info() == Eigen::Success) {
    for (int i = 0; i < n; ++i) out.eigenvalues.push_back(solver.eigenvalues()(i));
  } else {
    // The real QR iteration can fail to converge on a companion matrix with
    // exactly repeated roots; the complex one does not.
    const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> complex_solver(companion.cast<std::complex<double>>(), false);
    if (complex_solver.info() == Eigen::Success) {
      for (int i = 0; i < n; ++i) out.eigenvalues.push_back(complex_solver.eigenvalues()(i));
    }
  }

  // Real roots: isolate with the Sturm sequence, then refine.
  const auto chain = sturm_chain(p, multiple_tol);
  const Poly dp = derivative(p);
  const long double bound = root_bound(p);
  out.sturm_count = variations_at_infinity(chain, -1) - variations_at_infinity(chain, +1);
  struct Interval { long double a, b; int va, vb; };
  std::vector<Interval> stack{{-bound, bound, variations(chain, -bound), variations(chain, bound)}};
  std::vector<std::pair<long double, long double>> isolated;
  while (!stack.empty()) {
    const Interval iv = stack.back();
    stack.pop_back();
    const int count = iv.va - iv.vb;
    if (count <= 0) continue;
    const long double width = iv.b - iv.a;
    const long double tiny = 8.0L * std::numeric_limits<long double>::epsilon() * std::max(std::fabs(iv.a), std::fabs(iv.b));
    if (count == 1 || width <= tiny) {
      isolated.push_back({iv.a, iv.b});  // an unresolvable cluster counts as one root
      continue;
    }
    const long double mid = 0.5L * (iv.a + iv.b);
    const int vm = variations(chain, mid);
    stack.push_back({iv.a, mid, iv.va, vm});
    stack.push_back({mid, iv.b, vm, iv.vb});
  }
  std::sort(isolated.begin(), isolated.end());
  for (const auto& [a, b] : isolated) {
    for (const RealRoot& r : refine(p, dp, a, b, out.eigenvalues)) out.real.push_back(r);
  }

  // Complex roots: the eigenvalues left after removing, for every certified
  // real root, the one (odd multiplicity) or two (even) eigenvalues nearest it.
  std::vector<std::complex<double>> rest = out.eigenvalues;
  for (const RealRoot& r : out.real) {
    for (int k = 0; k < (r.sign_change ? 1 : 2) && !rest.empty(); ++k) {
      auto nearest = std::min_element(rest.begin(), rest.end(), [&](const auto& u, const auto& v) {
        return std::abs(u - r.value) < std::abs(v - r.value);
      });
      rest.erase(nearest);
    }
  }
  std::sort(rest.begin(), rest.end(), [](const auto& u, const auto& v) {
    return u.real() != v.real() ? u.real() < v.real() : u.imag() < v.imag();
  });
  out.complex = rest;
  return out;
}

}  // namespace pkmws::mechanisms
