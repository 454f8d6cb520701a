// Certified sub-level sets with traced level curves (see level_set.hpp and
// docs/theory/level_sets.md for the bounds and why they hold).
#include "pkmws/certified/level_set.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "detail/parallel.hpp"
#include "certified/box.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::certified {

using geometry::Box;
using geometry::Point;
using geometry::Region;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Tracer::integrate: a parent's miss past which a piece's own jet is not tried.
constexpr double kHopeless = 16.0;
// The most a retry four levels deeper is expected to narrow the bounds.
constexpr double max_retry_gain = 64.0;


// The bound width a level set aims at for an area: relative, or absolute
// where that is larger (LevelSetOptions).
double target_width(const LevelSetOptions& options, double area) {
  return std::max(options.relative_tolerance * area, options.absolute_tolerance);
}

// A box as a counter-clockwise polygon.
std::vector<Point> box_polygon(const Box& b) { return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}; }

// True if the box holds a point of S = ⋂_k { F_k <= level_k } and a point
// outside it among its centre and corners (F at points, in double): then no
// enclosure can decide it, and the cover splits it without one. Only a
// shortcut: a point misjudged by rounding splits a box that could have been
// decided, and its children are tested as usual.
bool holds_both(const std::vector<Constraint>& cs, const Box& b) {
  const Point pts[5] = {{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)}, b.min, {b.max.x, b.min.y}, b.max,
                        {b.min.x, b.max.y}};
  bool in = false, out = false;
  for (const Point& p : pts) {
    bool all_in = true;
    for (const Constraint& c : cs) {
      const double v = c.field->value(p);
      if (v > c.level) {
        out = true;
        all_in = false;
        break;
      }
      if (!(v <= c.level)) all_in = false;  // NaN: outside F's domain, neither
    }
    in = in || all_in;
    if (in && out) return true;
  }
  return false;
}

// Value enclosure of F over a box against `level`: where F's side test
// decides, an interval on that side of the level only (the cell tests read
// nothing else); else F's cheap form if that decides, else its natural form,
// intersected with the centred (mean-value) form when the box lies in F's
// smooth domain (then F's gradient over the box, which that form takes, is
// stored in `grad` if given).
Interval enclose_value(const ScalarField& f, const Box& box, double level, std::optional<Grad<Interval>>* grad = nullptr) {
  const CellState side = f.side(box, level);
  if (side == CellState::inside) return {-inf, level};
  if (side == CellState::outside) return {std::nextafter(level, inf), inf};
  const Interval cheap = f.enclose_cheap(box);
  if (cheap.hi <= level || cheap.lo > level) return cheap;
  Interval v = f.enclose(box);
  if (v.hi <= level || v.lo > level) return v;  // decided by the natural form
  // The centred form needs F smooth over the box: its domain test, asked
  // only here (it can cost as much as the enclosure).
  if (box.width() > 0.0 && f.domain(box) == CellState::inside) {
    const Grad<Interval> j = f.grad(box);
    if (grad) *grad = j;
    if (j.dx.finite() && j.dy.finite()) {
      const Point c{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)};
      const Interval fc = f.enclose(make_box(c.x, c.y, c.x, c.y));
      const Interval dxr = hull(Interval(box.min.x) - Interval(c.x), Interval(box.max.x) - Interval(c.x));
      const Interval dyr = hull(Interval(box.min.y) - Interval(c.y), Interval(box.max.y) - Interval(c.y));
      const Interval cf = fc + j.dx * dxr + j.dy * dyr;
      const Interval both = intersect(v, cf);
      v = both.lo <= both.hi ? both : cf;
    }
  }
  return v;
}

// The set is ⋂_k { F_k <= level_k } (within W). `undecided_index` is the one
// constraint left undecided when all others hold on the whole box (else -1);
// `grad`, that constraint's gradient over the box where its test took one.
CellState classify(const std::vector<Constraint>& cs, const Box& box, int* undecided_index = nullptr,
                   std::optional<Grad<Interval>>* grad = nullptr) {
  int undecided = 0, last = -1;
  std::optional<Grad<Interval>> g;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const ScalarField& f = *cs[k].field;
    if (f.excluded(box)) return CellState::outside;
    g.reset();
    const Interval v = enclose_value(f, box, cs[k].level, grad ? &g : nullptr);
    if (v.lo > cs[k].level) return CellState::outside;
    if (!(v.hi <= cs[k].level)) {
      ++undecided;
      last = static_cast<int>(k);
      if (grad) *grad = g;
    }
  }
  if (undecided_index) *undecided_index = undecided == 1 ? last : -1;
  return undecided == 0 ? CellState::inside : CellState::undecided;
}

// ---------------------------------------------------------------------------
// Tracing one cell B = [u0, u1] x [v0, v1]. Coordinates (u, v): (x, y) when the
// curve is a graph over x, (y, x) otherwise. G(u, v) = sgn (F - level) is
// increasing in v on the extended box B' = [u0, u1] x [v0 - E, v1 + E], with
// |dg/du| <= L there and L (u1 - u0) <= E: if the curve meets B at all, it is
// the graph of g over the whole [u0, u1] inside B' (docs/theory/level_sets.md).
// h(u) = clamp(g(u), v0, v1) is the boundary of {G <= 0} on each vertical
// segment of B.

struct PLPoint {
  double u, w;  // a vertex of a piecewise-linear envelope w(u)
};

struct CellTrace {
  bool ok = false;
  bool swapped = false;      // u = y, v = x
  int sgn = 1;               // sub-level side: +1 below the curve (v <= h), -1 above
  double lower = 0.0;        // bounds of area(S ∩ cell)
  double upper = 0.0;
  std::vector<PLPoint> env_lo, env_hi;  // envelopes of h(u): env_lo <= h <= env_hi
  CurvePiece curve;
  std::uint64_t points = 0;
  std::size_t constraint = 0;  // the index of the constraint traced
};

// g' and g'' enclosed over a box [a, b] x [lo, hi] of the graph (a parent
// piece's: valid for a child whose own box lies inside it).
struct Curvature {
  Interval g1 = Interval::whole(), g2 = Interval::whole();
  double a = 0.0, b = 0.0, lo = 0.0, hi = -1.0;
  // How far the best bound from this piece's own jet missed the target
  // (width / τΔ; 0: not known).
  double excess = 0.0;
  bool covers(double ca, double cb, double clo, double chi) const {
    return g2.finite() && g1.finite() && ca >= a && cb <= b && clo >= lo && chi <= hi;
  }
};

class Tracer {
 public:
  Tracer(const ScalarField& f, double level, const Box& cell, bool swapped, int sgn, double lipschitz, Interval slope,
         double gv_min, double extent, double tau, const AreaWeight& weight, bool envelopes_only)
      : f_(f), level_(level), swapped_(swapped), sgn_(sgn), L_(lipschitz), slope_(slope), gv_min_(gv_min), tau_(tau),
        envelopes_only_(envelopes_only) {
    unit_ = weight.unit();
    c0_ = weight.c0;
    cu_ = swapped ? weight.cy : weight.cx;
    cv_ = swapped ? weight.cx : weight.cy;
    u0_ = swapped ? cell.min.y : cell.min.x;
    u1_ = swapped ? cell.max.y : cell.max.x;
    v0_ = swapped ? cell.min.x : cell.min.y;
    v1_ = swapped ? cell.max.x : cell.max.y;
    w0_ = v0_ - extent;
    w1_ = v1_ + extent;
    scale_ = std::max({std::abs(u0_), std::abs(u1_), std::abs(w0_), std::abs(w1_), w1_ - w0_});
  }

  bool run(CellTrace& out);

 private:
  // A sample of g at u: state 0: g ∈ [lo, hi] ⊆ [w0, w1]; +1: g above w1
  // (G(u, w1) < 0); -1: below w0 (G(u, w0) > 0).
  struct Sample {
    double lo, hi;
    int state;
  };
  Point xy(double u, double v) const { return swapped_ ? Point{v, u} : Point{u, v}; }
  Box box_uv(double ua, double ub, double va, double vb) const {
    return swapped_ ? make_box(va, ua, vb, ub) : make_box(ua, va, ub, vb);
  }
  int sign_at(double u, double v) const {
    const Point p = xy(u, v);
    const Interval val = f_.enclose(make_box(p.x, p.y, p.x, p.y)) - Interval(level_);
    const Interval g = sgn_ > 0 ? val : -val;
    if (g.lo > 0.0) return 1;
    if (g.hi < 0.0) return -1;
    return 0;
  }
  Sample solve(double u, double guess);
  // q(u) = ∫_{v0}^{w} ρ(u, v) dv: the weighted area under the envelope at u
  // (w - v0 for the plane; terms of one sign where w >= v0 and ρ >= 0).
  double qw(double u, double w) const { return unit_ ? w - v0_ : (w - v0_) * rho(u, 0.5 * (w + v0_)); }
  double rho(double u, double v) const { return c0_ + cu_ * u + cv_ * v; }
  // ∫ q over the envelope's vertices from `first` on (relative to v0: no
  // cancellation). Exact on each linear piece: q is then linear (the plane:
  // the trapezoid rule) or quadratic in u (affine ρ: Simpson's rule).
  double integral(const std::vector<PLPoint>& env, std::size_t first) const {
    double sum = 0.0;
    for (std::size_t k = first; k + 1 < env.size(); ++k) {
      const PLPoint& p = env[k];
      const PLPoint& r = env[k + 1];
      const double du = r.u - p.u;
      if (!(du > 0.0)) continue;
      if (unit_) {
        sum += 0.5 * du * ((p.w - v0_) + (r.w - v0_));
      } else {
        sum += du / 6.0 * (qw(p.u, p.w) + 4.0 * qw(0.5 * (p.u + r.u), 0.5 * (p.w + r.w)) + qw(r.u, r.w));
      }
    }
    return sum;
  }
  void integrate(double a, double b, const Sample& sa, const Sample& sb, int depth, const Curvature& parent = {});
  // Adds clamp(w(u), v0, v1) for the linear w from (a, wa) to (b, wb).
  void add_clamped(std::vector<PLPoint>& env, double a, double wa, double b, double wb) const;
  void add_constant(double a, double b, double w) {
    env_lo_.push_back({a, w}); env_lo_.push_back({b, w});
    env_hi_.push_back({a, w}); env_hi_.push_back({b, w});
  }
  void record(double u, const Sample& s) {
    if (s.state == 0 && s.hi - s.lo <= 1e-12 * scale_) {
      const double v = 0.5 * (s.lo + s.hi);
      if (v >= v0_ && v <= v1_) curve_.push_back(xy(u, v));
    }
  }

  const ScalarField& f_;
  double level_;
  bool swapped_;
  int sgn_;
  double L_;
  Interval slope_;  // g' over B' (signed; |g'| <= L)
  double gv_min_;   // G_v >= gv_min_ > 0 over B'
  double tau_;
  // The cell's bounds are its envelopes' (a cell across W's boundary is
  // clipped to W with them, summarize): each piece is held to τΔ on them,
  // the quadrature's tighter bound would not count.
  bool envelopes_only_;
  double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0, w0_ = 0, w1_ = 0, scale_ = 1;
  bool unit_ = true;                 // ρ = 1
  double c0_ = 1, cu_ = 0, cv_ = 0;  // ρ(u, v) = c0 + cu u + cv v
  bool failed_ = false;
  double slack_ = 0.0;   // allowance the pieces accepted so far left unused
  int useful_ = 0;       // least depth of a jet that served the current first-level piece
  int start_depth_ = 0;  // jets are tried from this depth on (or a parent's enclosure)
  std::uint64_t points_ = 0;
  std::vector<PLPoint> env_lo_, env_hi_;
  double gain_lo_ = 0.0, gain_hi_ = 0.0;  // quadrature over the envelopes' integrals
  CurvePiece curve_;
  static constexpr std::uint64_t max_points = 4096;
  static constexpr int max_depth = 30;
};

Tracer::Sample Tracer::solve(double u, double guess) {
  ++points_;
  // Safeguarded Newton in double arithmetic ...
  double lo = w0_, hi = w1_;
  double v = std::clamp(guess, w0_, w1_);
  bool converged = false;
  double gv_root = 0.0;  // G_v at the last iterate
  int bisections = 0;
  for (int it = 0; it < 50; ++it) {
    const Grad<double> j = f_.grad(xy(u, v));
    const double g = sgn_ * (j.v - level_);
    const double gv = sgn_ * (swapped_ ? j.dx : j.dy);
    if (!std::isfinite(g)) break;
    gv_root = gv;
    if (g < 0.0) lo = std::max(lo, v); else hi = std::min(hi, v);
    // A Newton step below a few ulps: v is the root to G's rounding. (Taken
    // as a step, it rounds to v itself, which the bracket below would refuse
    // and bisect from: 30-40 iterations for nothing, on half the samples.)
    const bool newton = gv > 0.0 && std::isfinite(gv);
    if (newton && std::abs(g) <= 1e-15 * scale_ * gv) {
      converged = true;
      break;
    }
    double next = newton ? v - g / gv : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
      // Bisecting towards an end of B': the curve may be beyond it (then no
      // root: the ends decide below, certified).
      if (++bisections >= 2 && (lo == w0_ || hi == w1_)) {
        const double end = lo == w0_ ? w0_ : w1_;
        const double ge = sgn_ * (f_.value(xy(u, end)) - level_);
        if ((end == w0_ && ge > 0.0) || (end == w1_ && ge < 0.0)) break;
      }
    }
    // Steps of a few ulps are the rounding noise of G near its root (it may
    // keep one sign there, and Newton then creeps by ulps): the certified
    // bracket below takes over.
    const bool done = std::abs(next - v) <= 1e-15 * scale_ || hi - lo <= 1e-15 * scale_;
    v = next;
    if (done) { converged = true; break; }
  }
  // ... then a certified bracket: G(blo) < 0 or blo = w0, G(bhi) > 0 or bhi = w1
  // (G increases in v on B', so the root is between). The first half-width
  // covers the interval evaluation's own width at v (its rounding), so that
  // one or two tries usually certify both sides.
  double blo = w0_, bhi = w1_;
  bool have_lo = false, have_hi = false;
  if (converged && v > w0_ && v < w1_) {
    double delta = 2e-16 * scale_;
    const Point p = xy(u, v);
    const Interval e = f_.enclose(make_box(p.x, p.y, p.x, p.y));
    // One enclosure of G at v brackets the root: G(u, v) = γ and G_v >= m on
    // B' give g in [v - γ/m, v] (γ > 0) or [v, v - γ/m] (γ < 0), the root
    // existing there when that stays inside B' (the mean value theorem along
    // the segment, in B').
    if (e.finite() && gv_min_ > 0.0) {
      const Interval gamma = sgn_ > 0 ? e - Interval(level_) : Interval(level_) - e;
      const Interval root = Interval(v) - gamma / Interval(gv_min_, Interval::inf);
      if (root.lo > w0_ && root.hi < w1_) return {root.lo, root.hi, 0};
    }
    if (gv_root > 0.0 && e.finite()) {
      const double noise = (e.hi - e.lo + std::abs(e.mid() - level_)) / gv_root;
      if (noise < 1e-6 * scale_) delta = std::max(delta, 1.5 * noise);
    }
    for (int k = 0; k < 40 && !(have_lo && have_hi); ++k) {
      const double a = std::max(w0_, v - delta), c = std::min(w1_, v + delta);
      if (!have_lo && a > w0_ && sign_at(u, a) < 0) { blo = a; have_lo = true; }
      if (!have_hi && c < w1_ && sign_at(u, c) > 0) { bhi = c; have_hi = true; }
      if (a <= w0_ || c >= w1_) break;
      delta *= 4.0;
    }
    if (have_lo && have_hi) return {blo, bhi, 0};
  }
  // Near or beyond B''s edges: decide with the ends.
  const int s0 = sign_at(u, w0_);
  if (s0 > 0) return {w0_, w0_, -1};
  const int s1 = sign_at(u, w1_);
  if (s1 < 0) return {w1_, w1_, 1};
  return {have_lo ? blo : w0_, have_hi ? bhi : w1_, 0};
}

void Tracer::add_clamped(std::vector<PLPoint>& env, double a, double wa, double b, double wb) const {
  env.push_back({a, std::clamp(wa, v0_, v1_)});
  // Crossings of the line with v0 and v1 inside (a, b), in increasing u.
  std::array<double, 2> cuts{};
  int n = 0;
  if (wa != wb) {
    for (double level : {v0_, v1_}) {
      const double t = (level - wa) / (wb - wa);
      if (t > 0.0 && t < 1.0) cuts[static_cast<std::size_t>(n++)] = a + t * (b - a);
    }
  }
  if (n == 2 && cuts[0] > cuts[1]) std::swap(cuts[0], cuts[1]);
  for (int k = 0; k < n; ++k) {
    const double u = cuts[static_cast<std::size_t>(k)];
    const double w = wa + (wb - wa) * ((u - a) / (b - a));
    env.push_back({u, std::clamp(w, v0_, v1_)});
  }
  env.push_back({b, std::clamp(wb, v0_, v1_)});
}

void Tracer::integrate(double a, double b, const Sample& sa, const Sample& sb, int depth, const Curvature& parent) {
  if (failed_) return;
  if (points_ > max_points) { failed_ = true; return; }
  const double delta = b - a;
  // A sample beyond B': the curve does not meet B over [a, b] (else it would
  // be in B' over all of [u0, u1]), so h is constant on that side.
  if (sa.state != 0 || sb.state != 0) {
    if (sa.state * sb.state < 0) { failed_ = true; return; }
    add_constant(a, b, (sa.state != 0 ? sa.state : sb.state) > 0 ? v1_ : v0_);
    return;
  }
  // Tent of the curve over [a, b] (if it is in B' there): within L of both ends.
  const double tent_lo = 0.5 * (sa.lo + sb.lo) - 0.5 * L_ * delta;
  const double tent_hi = 0.5 * (sa.hi + sb.hi) + 0.5 * L_ * delta;
  if (tent_lo > v1_) { add_constant(a, b, v1_); return; }  // never reaches B: h = v1
  if (tent_hi < v0_) { add_constant(a, b, v0_); return; }  // h = v0
  auto split = [&](const Curvature& here) {
    const double m = 0.5 * (a + b);
    const Sample sm = solve(m, 0.25 * (sa.lo + sa.hi + sb.lo + sb.hi));
    record(m, sm);
    integrate(a, m, sa, sm, depth + 1, here);
    integrate(m, b, sm, sb, depth + 1, here);
  };
  double box_lo = std::min(sa.lo, sb.lo) - 0.5 * L_ * delta;
  double box_hi = std::max(sa.hi, sb.hi) + 0.5 * L_ * delta;
  // Thinner where g' has a sign: the curve lies between the lines from both
  // samples with the slopes of g' (the cell's enclosure, narrowed by the
  // parent piece's, whose box holds the curve over [a, b]). The lower bound
  // max(lo_a + s⁻(u - a), lo_b - s⁺(b - u)) is convex, its least value at a,
  // b or where the two lines cross; the upper bound likewise.
  Interval s = slope_;
  if (parent.g1.finite() && parent.a <= a && parent.b >= b) {
    const Interval both = intersect(s, parent.g1);
    if (both.lo <= both.hi) s = both;
  }
  if (s.finite() && s.hi > s.lo) {
    const auto lower = [&](double u) { return std::max(sa.lo + s.lo * (u - a), sb.lo - s.hi * (b - u)); };
    const auto upper = [&](double u) { return std::min(sa.hi + s.hi * (u - a), sb.hi - s.lo * (b - u)); };
    const double k_lo = std::clamp((sa.lo - sb.lo + s.hi * b - s.lo * a) / (s.hi - s.lo), a, b);
    const double k_hi = std::clamp((sb.hi - sa.hi - s.lo * b + s.hi * a) / (s.hi - s.lo), a, b);
    const double margin = 1e-13 * scale_;  // the rounding of these few operations
    box_lo = std::max(box_lo, std::min({lower(a), lower(b), lower(k_lo)}) - margin);
    box_hi = std::min(box_hi, std::max({upper(a), upper(b), upper(k_hi)}) + margin);
    if (box_lo > v1_) { add_constant(a, b, v1_); return; }  // never reaches B: h = v1
    if (box_hi < v0_) { add_constant(a, b, v0_); return; }  // h = v0
  }
  if (box_lo >= w0_ && box_hi <= w1_) {
    // g is C² on [a, b] with its graph in S = [a, b] x [box_lo, box_hi] ⊆ B'.
    // chord error: g - chord = -g''(ξ) (u - a)(b - u) / 2, |(u - a)(b - u)| / 2 <= Δ² / 8.
    const double q = delta * delta / 8.0;
    double excess = inf;  // the least width / τΔ of the bounds tried below
    // A piece's allowance is τΔ plus what the pieces before it in this cell
    // left unused (slack_): the cell's width stays within τ times the length
    // traced, and a piece just over its own share is not split.
    // `slack_taken`: the quadrature accepted the piece and took its share of
    // the allowance already; only the envelopes are added.
    auto accept = [&](const Interval& g2, bool force, bool slack_taken = false) {
      if (!g2.finite()) return false;
      const double e_lo = std::max(0.0, g2.hi) * q * (1.0 + 1e-12);
      const double e_hi = std::max(0.0, -g2.lo) * q * (1.0 + 1e-12);
      const double width = delta * (0.5 * (sa.hi - sa.lo + sb.hi - sb.lo) + e_lo + e_hi);
      excess = std::min(excess, width / (tau_ * delta));
      const double allowed = tau_ * delta + slack_;
      if (!(width <= allowed || force)) return false;
      if (!slack_taken) slack_ = std::max(0.0, allowed - width);
      add_clamped(env_lo_, a, sa.lo - e_lo, b, sb.lo - e_lo);
      add_clamped(env_hi_, a, sa.hi + e_hi, b, sb.hi + e_hi);
      return true;
    };
    // The trapezoid rule's remainder, ∫q = Δ (q(a) + q(b)) / 2 - q''(ξ) Δ³ / 12
    // for q(u) = ∫_{v0}^{g(u)} ρ dv (g - v0 for the plane), with the signed
    // enclosure of q'' over S: a width O(Δ⁴) per piece (the envelopes' is
    // O(Δ³)). Weighted (ρ affine): q'' = g'' (c0 + cu u) + 2 cu g' + cv (g'² + g g'').
    // The cell's part is ∫q(clamp(g, v0, v1)) = ∫q(g) - ∫D(g) with
    // D(w) = q(w) - q(clamp(w)), non-decreasing where ρ >= 0 beyond the cell's
    // edges; so ∫D(env_lo) <= ∫D(g) <= ∫D(env_hi), and those differ only
    // where the envelopes straddle an edge (length ~ envelope gap / |g'|):
    // the curve may leave the cell within the piece at fourth order too.
    const bool in_cell = box_lo >= v0_ && box_hi <= v1_;
    const auto quadrature = [&](const Interval& g1, const Interval& g2, bool force) {
      if (envelopes_only_ || !g2.finite() || !g1.finite()) return false;
      // ρ >= 0 wherever D is evaluated: between the cell and the envelopes
      // (which reach beyond S by the chord bound).
      const double e_lo = std::max(0.0, g2.hi) * q * (1.0 + 1e-12), e_hi = std::max(0.0, -g2.lo) * q * (1.0 + 1e-12);
      bool rho_positive = unit_;
      if (!unit_) {
        const double vlo = std::min({box_lo, v0_, sa.lo - e_lo, sb.lo - e_lo});
        const double vhi = std::max({box_hi, v1_, sa.hi + e_hi, sb.hi + e_hi});
        rho_positive = std::min({rho(a, vlo), rho(a, vhi), rho(b, vlo), rho(b, vhi)}) >= 0.0;
      }
      if (!(in_cell || rho_positive)) return false;
      const double c = delta * delta * delta / 12.0;
      Interval q2 = g2;
      if (!unit_) {
        q2 = g2 * (Interval(c0_) + Interval(cu_) * Interval(a, b)) + Interval(2.0 * cu_) * g1 +
             Interval(cv_) * (sqr(g1) + Interval(box_lo, box_hi) * g2);
      }
      double q_lo = delta * 0.5 * (qw(a, sa.lo) + qw(b, sb.lo)) - q2.hi * c;
      double q_hi = delta * 0.5 * (qw(a, sa.hi) + qw(b, sb.hi)) - q2.lo * c;
      if (!in_cell) {
        // ∫ D over a linear envelope from (a, wa) to (b, wb): unclamped minus clamped.
        std::vector<PLPoint> tmp;
        const auto d_integral = [&](double wa, double wb, double& size) {
          tmp = {{a, wa}, {b, wb}};
          const double whole = integral(tmp, 0);
          tmp.clear();
          add_clamped(tmp, a, wa, b, wb);
          const double clamped = integral(tmp, 0);
          size = std::abs(whole) + std::abs(clamped);
          return whole - clamped;
        };
        double s_lo = 0.0, s_hi = 0.0;
        const double d_lo = d_integral(sa.lo - e_lo, sb.lo - e_lo, s_lo);
        const double d_hi = d_integral(sa.hi + e_hi, sb.hi + e_hi, s_hi);
        // Rounding of the differences (a few ulps of the integrals).
        const double round = 8.0 * std::numeric_limits<double>::epsilon() * (s_lo + s_hi + std::abs(q_lo) + std::abs(q_hi));
        q_lo -= d_hi + round;
        q_hi -= d_lo - round;
      }
      // (q_lo <= q_hi always holds where the bounds' assumptions do; an
      // inverted pair would only say they do not.)
      if (q_lo <= q_hi) excess = std::min(excess, (q_hi - q_lo) / (tau_ * delta));
      const double allowed = tau_ * delta + slack_;
      if (!((q_lo <= q_hi && q_hi - q_lo <= allowed) || (force && in_cell))) return false;
      slack_ = std::max(0.0, allowed - (q_hi - q_lo));
      const std::size_t nlo = env_lo_.size(), nhi = env_hi_.size();
      accept(g2, true, true);
      gain_lo_ += std::max(0.0, q_lo - integral(env_lo_, nlo));
      gain_hi_ += std::max(0.0, integral(env_hi_, nhi) - q_hi);
      return true;
    };
    // The parent piece's enclosures first (no jet), when its box holds this one.
    if (parent.covers(a, b, box_lo, box_hi)) {
      if (quadrature(parent.g1, parent.g2, false) || accept(parent.g2, false)) {
        useful_ = std::min(useful_, depth - 1);
        return;
      }
    }
    // Above the depth whose jets served the cell's previous first-level
    // piece (their own bound, or their children's through it), a piece's
    // own jet is not tried: the pieces need about the same length all along
    // a cell (PAMINSA κ <= 4: 1 454 of 4 770 jets, at the first depth, had
    // failed and served no child).
    if (depth < start_depth_ && !parent.g2.finite()) {
      split(Curvature{});
      return;
    }
    // A piece whose parent's own jet missed the target by more than
    // kHopeless cannot meet it either: a halving narrows a piece's bound
    // relative to its allowance τΔ 4 to 16 times (O(Δ⁴) bounds; instrumented on
    // PAMINSA κ ≤ 4 at 1e-9: 33 of 63 800 such pieces passed, 10 700 of
    // 11 700 whose parent missed by 2 to 8 times). It is split without its
    // jet, its halves judged by the parent's miss divided by 16 (the best case).
    if (parent.excess > kHopeless && depth < max_depth) {
      Curvature skipped = parent;
      skipped.excess = parent.excess / kHopeless;
      split(skipped);
      return;
    }
    // g'' over S (one jet).
    const Jet<Interval> j = f_.jet(box_uv(a, b, box_lo, box_hi));
    const Interval fu = swapped_ ? j.dy : j.dx, fv = swapped_ ? j.dx : j.dy;
    const Interval fuu = swapped_ ? j.dyy : j.dxx, fvv = swapped_ ? j.dxx : j.dyy, fuv = j.dxy;
    if (!fv.contains_zero()) {
      // g' = -F_u / F_v, g'' = -(F_uu + 2 F_uv g' + F_vv g'²) / F_v.
      Curvature here;
      here.g1 = -(fu / fv);
      here.g2 = -((fuu + Interval(2.0) * fuv * here.g1 + fvv * sqr(here.g1)) / fv);
      here.a = a;
      here.b = b;
      here.lo = box_lo;
      here.hi = box_hi;
      if (quadrature(here.g1, here.g2, depth >= max_depth) || accept(here.g2, depth >= max_depth)) {
        useful_ = std::min(useful_, depth);
        return;
      }
      here.excess = excess;
      if (here.g2.finite()) { split(here); return; }
    }
  }
  if (depth < max_depth && delta > 1e-14 * scale_) {
    split(Curvature{});
    return;
  }
  // Last resort: h is L-Lipschitz; tents from the clamped samples.
  const double la = std::clamp(sa.lo, v0_, v1_), lb = std::clamp(sb.lo, v0_, v1_);
  const double ha = std::clamp(sa.hi, v0_, v1_), hb = std::clamp(sb.hi, v0_, v1_);
  const double peak_lo = std::clamp(0.5 * (a + b) + (lb - la) / (2.0 * L_), a, b);
  const double peak_hi = std::clamp(0.5 * (a + b) + (hb - ha) / (2.0 * L_), a, b);
  auto lower_at = [&](double u) { return std::max({v0_, la - L_ * (u - a), lb - L_ * (b - u)}); };
  auto upper_at = [&](double u) { return std::min({v1_, ha + L_ * (u - a), hb + L_ * (b - u)}); };
  // Piecewise linear with breaks at the peak and the clamps; sampling at the
  // peak only gives a polyline below (lower) / above (upper)? No: use exact
  // breakpoints. The lower tent max(.) is convex, so its chord over
  // [a, peak] and [peak, b] lies above it: take the constant minimum instead.
  const double lmin = std::min({lower_at(a), lower_at(b), lower_at(peak_lo)});
  const double hmax = std::max({upper_at(a), upper_at(b), upper_at(peak_hi)});
  env_lo_.push_back({a, lmin}); env_lo_.push_back({b, lmin});
  env_hi_.push_back({a, hmax}); env_hi_.push_back({b, hmax});
}

bool Tracer::run(CellTrace& out) {
  const int n0 = 2;
  std::array<Sample, n0 + 1> h{};
  std::array<double, n0 + 1> us{};
  double guess = 0.5 * (v0_ + v1_);
  for (int k = 0; k <= n0; ++k) {
    const auto i = static_cast<std::size_t>(k);
    us[i] = k == n0 ? u1_ : u0_ + (u1_ - u0_) * k / n0;
    h[i] = solve(us[i], guess);
    if (h[i].state == 0) guess = 0.5 * (h[i].lo + h[i].hi);
    record(us[i], h[i]);
  }
  for (int k = 0; k < n0 && !failed_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    useful_ = max_depth + 1;
    integrate(us[i], us[i + 1], h[i], h[i + 1], 0);
    if (useful_ <= max_depth) start_depth_ = useful_;
  }
  if (failed_) return false;
  const double span = u1_ - u0_;
  // The envelopes' integrals, tightened where the quadrature bound is better
  // (both bound the same ∫(h - v0) piece by piece).
  const double ilo = integral(env_lo_, 0) + gain_lo_, ihi = integral(env_hi_, 0) - gain_hi_;
  const double cell = span * (v1_ - v0_) * (unit_ ? 1.0 : rho(0.5 * (u0_ + u1_), 0.5 * (v0_ + v1_)));
  double lower, upper;
  if (sgn_ > 0) {  // S below the curve: area ∫(h - v0)
    lower = ilo;
    upper = ihi;
  } else {  // S above: ∫(v1 - h)
    lower = cell - ihi;
    upper = cell - ilo;
  }
  // Rounding of the sums (terms of one sign, ~n eps relative) and of the vertices.
  const double margin = 16 * std::numeric_limits<double>::epsilon() * cell * static_cast<double>(env_lo_.size() + 8);
  out.lower = std::max(0.0, lower - margin);
  out.upper = std::min(cell, upper + margin);
  out.ok = true;
  out.swapped = swapped_;
  out.sgn = sgn_;
  out.points = points_;
  out.env_lo = std::move(env_lo_);
  out.env_hi = std::move(env_hi_);
  std::sort(curve_.begin(), curve_.end(), [&](const Point& p, const Point& q) {
    return swapped_ ? p.y < q.y : p.x < q.x;
  });
  out.curve = std::move(curve_);
  return true;
}

// The gradient over a box: the natural enclosure, tightened by the centred
// form ∇F(c) + H(B)(B - c) (H enclosed over B, ∇F(c) over the point c) when
// the box lies in F's smooth domain: its overestimation shrinks like the box's
// width squared. It costs a jet; taken only where the natural form fails.
Grad<Interval> centred_gradient(const ScalarField& f, const Box& b, Grad<Interval> g) {
  if (f.domain(b) != CellState::inside) return g;
  const Point c{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)};
  const Jet<Interval> h = f.jet(b);
  const Grad<Interval> gc = f.grad(make_box(c.x, c.y, c.x, c.y));
  const Interval dx = Interval(b.min.x, b.max.x) - Interval(c.x), dy = Interval(b.min.y, b.max.y) - Interval(c.y);
  const Interval cx = gc.dx + h.dxx * dx + h.dxy * dy, cy = gc.dy + h.dxy * dx + h.dyy * dy;
  if (cx.finite()) g.dx = intersect(g.dx, cx);
  if (cy.finite()) g.dy = intersect(g.dy, cy);
  return g;
}

// What try_trace needs of F's gradient over B' (u along the cell's graph
// direction, v across it): F smooth there (its smooth-domain tests passed),
// F_v of one sign sgn with |F_v| >= gv_min, and the curve's slope -F_u / F_v
// (`signed_slope`) with |F_u| / |F_v| <= lipschitz (inf: not bounded).
struct SlopeBound {
  bool smooth = false;
  int sgn = 0;
  double lipschitz = inf, gv_min = 0.0;
  Interval signed_slope = Interval::whole();
};

// The bound from one gradient enclosure g of a smooth box.
SlopeBound slope_bound(const Grad<Interval>& g, bool swapped) {
  SlopeBound b;
  b.smooth = true;
  const Interval fv = swapped ? g.dx : g.dy, fu = swapped ? g.dy : g.dx;
  if (fv.contains_zero() || !fu.finite()) return b;
  b.sgn = fv.lo > 0.0 ? 1 : -1;
  b.lipschitz = fu.mag() / fv.mig() * (1.0 + 1e-12);
  b.gv_min = fv.mig();
  b.signed_slope = -(fu / fv);
  return b;
}

// try_trace takes B' in parts where its whole-box gradient is too wide, up to
// this extent (in cell sides): at most this many slabs on each side.
constexpr double kPartsExtent = 4.0;

// The bound over B' = the cell (gradient `j`) and slabs of at most the cell's
// side below and above it (extent E each side), each slab with its own
// smooth-domain test and gradient (natural, centred where F_v's sign is
// unknown): the worst part's |F_u| / |F_v|. The parts cover B' exactly, so
// this bounds the same slopes as one enclosure over B', and it is tighter: an
// enclosure grows wider than F's range of gradients with its box (PAMINSA
// κ <= 4 over a 2.5 mm cell: F_x's enclosure is 13 times its sampled range,
// and B' is twice to five times as tall), so the parts' bound holds where the
// whole box's fails, and such cells are traced instead of split in four
// (docs/theory/level_sets.md). The cell lies in F's smooth domain (try_trace's
// precondition).
SlopeBound slope_over_parts(const ScalarField& f, const Box& cell, const Grad<Interval>& j, double extent, bool swapped) {
  const double u0 = swapped ? cell.min.y : cell.min.x, u1 = swapped ? cell.max.y : cell.max.x;
  const double v0 = swapped ? cell.min.x : cell.min.y, v1 = swapped ? cell.max.x : cell.max.y;
  SlopeBound b = slope_bound(j, swapped);
  if (b.sgn == 0) return b;  // (try_trace chose v where the cell's F_v has a sign)
  const int n = std::max(1, static_cast<int>(std::ceil(extent / (u1 - u0) - 1e-9)));
  for (int side = 0; side < 2; ++side) {
    // n slabs of equal height from `from` to `to` (the ends exact, the cuts shared).
    const double from = side == 0 ? v0 - extent : v1, to = side == 0 ? v0 : v1 + extent;
    for (int k = 0; k < n; ++k) {
      const double va = k == 0 ? from : from + (to - from) * k / n, vb = k == n - 1 ? to : from + (to - from) * (k + 1) / n;
      const Box part = swapped ? make_box(va, u0, vb, u1) : make_box(u0, va, u1, vb);
      if (f.domain(part) != CellState::inside) return {};
      const Grad<Interval> g = f.grad(part);
      SlopeBound p = slope_bound(g, swapped);
      if (p.sgn == 0) p = slope_bound(centred_gradient(f, part, g), swapped);
      if (p.sgn != b.sgn) return SlopeBound{true};
      b.lipschitz = std::max(b.lipschitz, p.lipschitz);
      b.gv_min = std::min(b.gv_min, p.gv_min);
      b.signed_slope = hull(b.signed_slope, p.signed_slope);
    }
  }
  return b;
}

// The cell lies in F's smooth domain (refine tests it first). `known`: F's
// gradient over the cell, if the cell's test took it already.
CellTrace try_trace(const ScalarField& f, double level, const Box& cell, double tau, const AreaWeight& weight,
                    bool envelopes_only, const std::optional<Grad<Interval>>& known = std::nullopt) {
  CellTrace t;
  Grad<Interval> j = known ? *known : f.grad(cell);
  // The centred form where a component's sign is unknown: it decides which
  // graph direction (the steeper one) is taken, and a poor choice costs pieces.
  // Where one component's sign is known and the gradient at the centre
  // agrees that it is the larger, the natural form's choice stands (a jet
  // saved: 40 % of the centred forms on the PAMINSA, same cells).
  if (j.dx.contains_zero() || j.dy.contains_zero()) {
    bool need = j.dx.contains_zero() && j.dy.contains_zero();
    if (!need) {
      const Grad<double> gc = f.grad(Point{0.5 * (cell.min.x + cell.max.x), 0.5 * (cell.min.y + cell.max.y)});
      need = !(j.dx.contains_zero() ? std::abs(gc.dx) <= std::abs(gc.dy) : std::abs(gc.dy) <= std::abs(gc.dx));
    }
    if (need) j = centred_gradient(f, cell, j);
  }
  if (!j.dx.finite() || !j.dy.finite()) return t;
  const bool y_ok = !j.dy.contains_zero(), x_ok = !j.dx.contains_zero();
  bool swapped;
  if (y_ok && (!x_ok || j.dy.mig() >= j.dx.mig())) {
    swapped = false;
  } else if (x_ok) {
    swapped = true;
  } else {
    return t;
  }
  const double du = swapped ? cell.height() : cell.width();
  // Extent E of B' with L(B') du <= E: a few tries. Each takes B' whole (the
  // natural gradient, then the centred one) and, where that fails with E of
  // at most kPartsExtent du, B' in parts (slope_over_parts).
  SlopeBound bound = slope_bound(j, swapped);
  double extent = 1.5 * bound.lipschitz * du + 1e-12 * du;
  bool ok = false;
  for (int attempt = 0; attempt < 4 && std::isfinite(extent); ++attempt) {
    const Box ext = swapped ? make_box(cell.min.x - extent, cell.min.y, cell.max.x + extent, cell.max.y)
                            : make_box(cell.min.x, cell.min.y - extent, cell.max.x, cell.max.y + extent);
    bound = SlopeBound{};
    if (f.domain(ext) == CellState::inside) {
      const Grad<Interval> je = f.grad(ext);
      bound = slope_bound(je, swapped);
      if (!(bound.lipschitz * du <= extent)) bound = slope_bound(centred_gradient(f, ext, je), swapped);
    }
    if (!(bound.lipschitz * du <= extent) && extent <= kPartsExtent * du) {
      const SlopeBound parts = slope_over_parts(f, cell, j, extent, swapped);
      if (parts.smooth && (!bound.smooth || parts.lipschitz < bound.lipschitz)) bound = parts;
    }
    if (!bound.smooth || !std::isfinite(bound.lipschitz)) return t;
    if (bound.lipschitz * du <= extent) {
      ok = true;
      break;
    }
    extent = 1.5 * bound.lipschitz * du + 1e-12 * du;
  }
  if (!ok) return t;
  Tracer tracer(f, level, cell, swapped, bound.sgn, bound.lipschitz, bound.signed_slope, bound.gv_min, extent, tau, weight,
                envelopes_only);
  tracer.run(t);
  return t;
}

// The part of the cell between an envelope and the cell's base edge (v0 when
// S lies below the curve, v1 when above), as simple polygons: one per run
// where the envelope is off the base edge.
void envelope_polygons(const std::vector<PLPoint>& env, const CellTrace& t, const Box& cell,
                       std::vector<std::vector<Point>>& out) {
  const double v0 = t.swapped ? cell.min.x : cell.min.y, v1 = t.swapped ? cell.max.x : cell.max.y;
  const double base = t.sgn > 0 ? v0 : v1;
  auto xy = [&](double u, double v) { return t.swapped ? Point{v, u} : Point{u, v}; };
  std::vector<Point> run;
  auto emit = [&](double u_end) {
    if (run.empty()) return;
    const Point end = xy(u_end, base);
    if (run.back() != end) run.push_back(end);
    if (run.size() >= 3) out.push_back(run);
    run.clear();
  };
  bool have_base = false;
  double last_base = 0.0;  // u of the last envelope vertex on the base edge
  for (std::size_t k = 0; k < env.size(); ++k) {
    const double w = std::clamp(env[k].w, v0, v1);
    const Point p = xy(env[k].u, w);
    if (w == base) {
      if (!run.empty()) run.push_back(p);
      emit(env[k].u);
      have_base = true;
      last_base = env[k].u;
      continue;
    }
    // A run starts where the envelope leaves the base edge (the last vertex on
    // it), or at the cell's side.
    if (run.empty()) run.push_back(xy(have_base ? last_base : env[k].u, base));
    if (run.back() != p) run.push_back(p);
  }
  if (!env.empty()) emit(env.back().u);
}

void envelope_polygons(const CellTrace& t, const Box& cell, bool use_hi, std::vector<std::vector<Point>>& out) {
  envelope_polygons(use_hi ? t.env_hi : t.env_lo, t, cell, out);
}

// A piecewise-linear function p with few vertices on one side of the
// envelope env (p >= env when `above`, else p <= env, at every u) and within
// `tol` of it: Douglas-Peucker's chords, each moved to the envelope's side by
// its largest deviation (with a margin for rounding), then clamped to
// [v0, v1] (clamping keeps the side: it is monotone). Where consecutive chords
// end at different heights, p jumps (two vertices at one u).
std::vector<PLPoint> follow_envelope(const std::vector<PLPoint>& env, double v0, double v1, bool above, double tol) {
  std::vector<PLPoint> chords;
  if (env.size() < 2) return env;
  double scale = std::max(std::abs(v0), std::abs(v1));
  for (const PLPoint& p : env) scale = std::max({scale, std::abs(p.u), std::abs(p.w)});
  const double margin = 8.0 * std::numeric_limits<double>::epsilon() * scale;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, env.size() - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    const PLPoint& a = env[i];
    const PLPoint& b = env[j];
    const double du = b.u - a.u;
    if (j == i + 1 || !(du > 0.0)) {  // one piece, or a jump: as it is
      for (std::size_t k = i; k <= j; ++k) chords.push_back(env[k]);
      continue;
    }
    const auto chord = [&](double u) { return a.w + (b.w - a.w) * ((u - a.u) / du); };
    double dmax = 0.0, dmin = 0.0, worst = 0.0;
    std::size_t split = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const double d = env[k].w - chord(env[k].u);
      dmax = std::max(dmax, d);
      dmin = std::min(dmin, d);
      if (std::abs(d) > worst) { worst = std::abs(d); split = k; }
    }
    if (dmax - dmin <= tol || split == i) {
      // A level chord through level vertices (an envelope along the cell's
      // edge) is exact: no margin, so that it stays on the edge.
      const bool level = a.w == b.w && dmax == 0.0 && dmin == 0.0;
      const double shift = level ? 0.0 : above ? dmax + margin : dmin - margin;
      chords.push_back({a.u, a.w + shift});
      chords.push_back({b.u, b.w + shift});
      continue;
    }
    todo.push_back({split, j});  // popped after [i, split]: left to right
    todo.push_back({i, split});
  }
  // Clamped to [v0, v1], with the vertices where a chord crosses v0 or v1.
  std::vector<PLPoint> out;
  out.reserve(chords.size() + 4);
  for (std::size_t k = 0; k < chords.size(); ++k) {
    const PLPoint& p = chords[k];
    if (k > 0) {
      const PLPoint& q = chords[k - 1];
      if (p.u > q.u && p.w != q.w) {
        std::array<double, 2> cuts{};
        int n = 0;
        for (double level : {v0, v1}) {
          const double s = (level - q.w) / (p.w - q.w);
          if (s > 0.0 && s < 1.0) cuts[static_cast<std::size_t>(n++)] = q.u + s * (p.u - q.u);
        }
        if (n == 2 && cuts[0] > cuts[1]) std::swap(cuts[0], cuts[1]);
        // The crossing on the level itself (exactly: a neighbouring cell's
        // edge), its u moved by a few ulps to the side the chord keeps: later
        // where p rises (below the envelope) or falls (above), else earlier.
        const double nudge = ((p.w > q.w) != above ? 4.0 : -4.0) * std::numeric_limits<double>::epsilon() *
                             std::max(std::abs(q.u), std::abs(p.u));
        for (int c = 0; c < n; ++c) {
          const double u = std::clamp(cuts[static_cast<std::size_t>(c)] + nudge, q.u, p.u);
          const double s = (u - q.u) / (p.u - q.u);
          out.push_back({u, q.w + s * (p.w - q.w) < 0.5 * (v0 + v1) ? v0 : v1});
        }
      }
    }
    out.push_back({p.u, std::clamp(p.w, v0, v1)});
  }
  // A jump is its first and last vertex (the ones between could run back
  // along the jump: a polygon that is not simple).
  std::size_t n = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const bool inside_jump = n >= 2 && out[n - 1].u == out[k].u && out[n - 2].u == out[k].u;
    if (inside_jump) out[n - 1] = out[k];
    else if (n == 0 || out[n - 1].u != out[k].u || out[n - 1].w != out[k].w) out[n++] = out[k];
  }
  out.resize(n);
  return out;
}

// The area bounds of a box that is in S wherever it is in W, from splits
// against W alone: parts inside W count fully, parts across W's boundary at
// the depth limit count as undecided.
void split_within(const WithinTest& within_test, const AreaWeight& weight, const Box& b, int depth, double& inside_area,
                  double& undecided_area) {
  const CellState c = within_test(b);
  if (c == CellState::outside) return;
  if (c == CellState::inside) {
    inside_area += weight.box(b);
    return;
  }
  if (depth == 0) {
    undecided_area += weight.box(b);
    return;
  }
  const double xm = 0.5 * (b.min.x + b.max.x), ym = 0.5 * (b.min.y + b.max.y);
  split_within(within_test, weight, make_box(b.min.x, b.min.y, xm, ym), depth - 1, inside_area, undecided_area);
  split_within(within_test, weight, make_box(xm, b.min.y, b.max.x, ym), depth - 1, inside_area, undecided_area);
  split_within(within_test, weight, make_box(b.min.x, ym, xm, b.max.y), depth - 1, inside_area, undecided_area);
  split_within(within_test, weight, make_box(xm, ym, b.max.x, b.max.y), depth - 1, inside_area, undecided_area);
}

// The bound on the work shared by the threads of one refinement: the deadline
// (read every few cell tests) and the progress reports.
class Budget {
 public:
  Budget(const LevelSetOptions& o, std::size_t leaves) : o_(o), leaves_(leaves) {}
  // True once the deadline has passed (then for good).
  bool expired() {
    if (stopped_.load(std::memory_order_relaxed)) return true;
    if (o_.deadline == std::chrono::steady_clock::time_point::max()) return false;
    if ((ticks_.fetch_add(1, std::memory_order_relaxed) & 15u) != 0) return false;
    if (std::chrono::steady_clock::now() < o_.deadline) return false;
    stopped_.store(true, std::memory_order_relaxed);
    return true;
  }
  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }
  void leaf_done() {
    const std::size_t done = done_.fetch_add(1, std::memory_order_relaxed) + 1;
    if (!o_.progress || leaves_ == 0) return;
    std::unique_lock lock(report_, std::try_to_lock);
    if (lock.owns_lock()) o_.progress(static_cast<double>(done) / static_cast<double>(leaves_));
  }

 private:
  const LevelSetOptions& o_;
  std::size_t leaves_;
  std::atomic<bool> stopped_{false};
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<std::size_t> done_{0};
  std::mutex report_;
};

// How a cell certified in S lies against W (in the cheap box test): inside W;
// across W's boundary and large (clipped to W exactly); across and small
// (bounded by a split against the box test alone).
enum class InsideKind : char { in_w, straddle, small_split };

struct LeafResult {
  std::vector<Box> inside;      // certified in S (by value)
  std::vector<InsideKind> inside_kind;  // per inside box
  double in_lower = 0.0;        // area of inside boxes certified in W (in_w, and small_split's part)
  double undecided_in = 0.0;    // small_split boxes' area W's box test left undecided
  std::vector<Box> undecided;   // at the depth limit
  std::vector<std::pair<Box, CellTrace>> traced;
  std::vector<std::pair<Box, CellTrace>> traced_across;  // traced, across W's boundary
  std::uint64_t tests = 0;
};

// Appends b's results to a's (in order: the merged result is the one a serial
// recursion would give).
void append(LeafResult& a, LeafResult&& b) {
  const auto move_all = [](auto& to, auto& from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
  };
  move_all(a.inside, b.inside);
  move_all(a.inside_kind, b.inside_kind);
  a.in_lower += b.in_lower;
  a.undecided_in += b.undecided_in;
  move_all(a.undecided, b.undecided);
  move_all(a.traced, b.traced);
  move_all(a.traced_across, b.traced_across);
  a.tests += b.tests;
}

// The first levels of a leaf's refinement run their four children as parallel
// tasks (a few leaves near singular points hold most of the work); each child
// fills its own result, merged in child order, so the results do not depend on
// the number of threads.
constexpr int kParallelRefineDepth = 5;

// A cell certified in S, with its position against W (in_w: the box test's).
// Refined cells across W's boundary are small (near the points where the
// level curve meets W's boundary): smaller than `small_cell`, their area is
// bounded by a split against W's box test alone (lower: the parts inside W)
// instead of exact clipping, which would cost more than it gains; the regions
// take the whole box, clipped to W exactly (the split's hundreds of boxes
// along W's boundary would only make the Boolean operations slow).
void add_inside(const WithinTest& within_test, const AreaWeight& weight, const Box& cell, CellState in_w, double small_cell,
                LeafResult& r) {
  r.inside.push_back(cell);
  if (in_w == CellState::inside) {
    r.in_lower += weight.box(cell);
    r.inside_kind.push_back(InsideKind::in_w);
  } else if (cell.width() >= small_cell) {
    r.inside_kind.push_back(InsideKind::straddle);
  } else {
    split_within(within_test, weight, cell, 8, r.in_lower, r.undecided_in);
    r.inside_kind.push_back(InsideKind::small_split);
  }
}

// The cover's tests of its finest cells that came out undecided, kept for
// the refinement, whose first step would test each of those leaves again:
// the one constraint left undecided (or -1) and its gradient over the leaf
// (try_trace's start). Written by the cover's tasks, read after it.
class LeafTests {
 public:
  struct Entry {
    int active = -1;
    std::optional<Grad<Interval>> grad;
  };
  void put(const Box& b, int active, const std::optional<Grad<Interval>>& grad) {
    const std::lock_guard<std::mutex> lock(mutex_);
    entries_[key(b)] = Entry{active, grad};
  }
  const Entry* find(const Box& b) const {
    const auto it = entries_.find(key(b));
    return it == entries_.end() ? nullptr : &it->second;
  }

 private:
  // The leaves are the same boxes to the bit in both (cell_box and leaf_cells
  // compute their sides alike); a box not found is tested again.
  static std::array<double, 4> key(const Box& b) { return {b.min.x, b.min.y, b.max.x, b.max.y}; }
  std::mutex mutex_;
  std::map<std::array<double, 4>, Entry> entries_;
};

// `leaf`: the cover's test of this cell when it is one of its undecided
// leaves (depth 0 of the first pass), instead of testing it again.
void refine(const std::vector<Constraint>& cs, const WithinTest& within_test, const AreaWeight& weight, const Box& cell,
            int depth, int max_depth, double tau, double small_cell, bool trace, Budget& budget, LeafResult& r,
            bool parallel = false, const LeafTests::Entry* leaf = nullptr) {
  if (budget.expired()) { r.undecided.push_back(cell); return; }  // valid: undecided is always allowed
  if (!leaf) ++r.tests;
  const CellState in_w = within_test(cell);
  if (in_w == CellState::outside) return;  // S ⊆ W
  int active = leaf ? leaf->active : -1;
  std::optional<Grad<Interval>> grad = leaf ? leaf->grad : std::nullopt;
  const CellState c = leaf ? CellState::undecided : classify(cs, cell, &active, &grad);
  if (c == CellState::inside) { add_inside(within_test, weight, cell, in_w, small_cell, r); return; }
  if (c == CellState::outside) return;
  if (trace && active >= 0) {
    const Constraint& k = cs[static_cast<std::size_t>(active)];
    // Across W's boundary too, where the field is smooth over the whole cell
    // (a stroke limit, not a singularity): its area is then clipped to W
    // exactly (summarize), instead of refining the points where the level
    // curve meets W's boundary to the depth limit.
    if (k.field->domain(cell) == CellState::inside) {
      CellTrace t = try_trace(*k.field, k.level, cell, tau, weight, in_w != CellState::inside, grad);
      t.constraint = static_cast<std::size_t>(active);
      if (t.ok) {
        (in_w == CellState::inside ? r.traced : r.traced_across).emplace_back(cell, std::move(t));
        return;
      }
    }
  }
  if (depth >= max_depth) { r.undecided.push_back(cell); return; }
  const double xm = 0.5 * (cell.min.x + cell.max.x), ym = 0.5 * (cell.min.y + cell.max.y);
  const std::array<Box, 4> kids = {make_box(cell.min.x, cell.min.y, xm, ym), make_box(xm, cell.min.y, cell.max.x, ym),
                                   make_box(cell.min.x, ym, xm, cell.max.y), make_box(xm, ym, cell.max.x, cell.max.y)};
  if (parallel && depth < kParallelRefineDepth) {
    std::array<LeafResult, 4> parts;
    detail::ParallelPolicy nested;  // the enclosing arena's threads
    nested.serial_threshold = 0;
    detail::for_each_block(nested, kids.size(), kids.size(), [&](std::size_t k) {
      refine(cs, within_test, weight, kids[k], depth + 1, max_depth, tau, small_cell, trace, budget, parts[k], true);
    });
    for (LeafResult& p : parts) append(r, std::move(p));
    return;
  }
  for (const Box& k : kids) refine(cs, within_test, weight, k, depth + 1, max_depth, tau, small_cell, trace, budget, r);
}

// Splits merged runs of the cover back into its leaf cells.
std::vector<Box> leaf_cells(const std::vector<Box>& runs, const Box& window, int base, int depth) {
  const double n = static_cast<double>(base) * std::ldexp(1.0, depth);
  const double cw = window.width() / n;
  std::vector<Box> out;
  for (const Box& r : runs) {
    const auto count = static_cast<long>(std::llround(r.width() / cw));
    if (count <= 1) { out.push_back(r); continue; }
    const auto i0 = std::llround((r.min.x - window.min.x) / cw);
    for (long k = 0; k < count; ++k) {
      Box b = r;
      b.min.x = window.min.x + window.width() * (static_cast<double>(i0 + k) / n);
      b.max.x = window.min.x + window.width() * (static_cast<double>(i0 + k + 1) / n);
      if (k == 0) b.min.x = r.min.x;
      if (k == count - 1) b.max.x = r.max.x;
      out.push_back(b);
    }
  }
  return out;
}

// One refinement: the cover, τ, and every undecided leaf of the cover refined
// (and, after `deepen`, its undecided cells refined further).
struct Pass {
  CellOptions co;
  CellCover cover;
  double tau = 0.0;
  std::vector<Box> leaves;  // the cover's undecided leaves, per_leaf's cells
  std::vector<LeafResult> per_leaf;
  int depth = 0;          // refine depth reached below the cover's leaves
  double small_cell = 0.0;  // see add_inside
  bool stopped = false;   // the deadline stopped it
};

// The options with the cover's depth chosen where it is 0: a level coarser
// (4) for relative targets of 1e-7 and wider and for absolute ones, where the
// traced cells of that size are cheaper than twice as many of half the size,
// else 5; the refinement then goes a level deeper below it, so undecided
// cells reach the same size as below a cover of 5.
LevelSetOptions resolved(LevelSetOptions o) {
  if (o.cover_depth > 0) return o;
  constexpr int fine = 5, coarse = 4;
  o.cover_depth = o.relative_tolerance >= 1e-7 || o.absolute_tolerance > 0.0 ? coarse : fine;
  o.refine_depth = std::min(40, o.refine_depth + fine - o.cover_depth);
  return o;
}

Pass first_pass(const std::vector<Constraint>& cs, const Region& within, const WithinTest& within_test,
                const LevelSetOptions& options, double tau_override) {
  Pass pass;
  CellOptions& co = pass.co;
  co.window = within.bbox();
  co.base = options.base;
  co.base_rows = options.base_rows;
  co.max_depth = options.cover_depth;
  co.threads = options.threads;
  // S ⊆ W: a box outside W is outside S, whatever the fields (whose domain
  // may reach beyond W, e.g. past a stroke limit).
  const double leaf_side = co.window.width() / (co.base * std::ldexp(1.0, co.max_depth));
  LeafTests leaf_tests;
  pass.cover = certified::cover(
      [&](const Box& b) {
        const CellState in_w = within_test(b);
        if (in_w == CellState::outside) return CellState::outside;
        // A box of W with points on both sides is split without enclosures.
        if (in_w == CellState::inside && holds_both(cs, b)) return CellState::undecided;
        if (!(b.width() <= leaf_side * (1.0 + 1e-9))) return classify(cs, b);
        int active = -1;
        std::optional<Grad<Interval>> grad;
        const CellState c = classify(cs, b, &active, &grad);
        if (c == CellState::undecided) leaf_tests.put(b, active, grad);
        return c;
      },
      co);
  pass.leaves = leaf_cells(pass.cover.undecided, co.window, co.base, co.max_depth);
  const std::vector<Box>& leaves = pass.leaves;

  // τ: the allowed width per unit length of curve, from the cover's estimate
  // of the area and of the curve length: undecided leaves x leaf size x π/4,
  // the mean length of a straight curve per grid cell it crosses (a line at
  // angle θ crosses (|cos θ| + |sin θ|) / h cells per unit length, 4 / (π h)
  // on average over θ). A trace is held to τ per unit of its cell's extent
  // along u, not of the curve's length, so a pass whose pieces use all of
  // their allowance misses the target by up to 4/π; the retry then traces
  // the widest leaves again (retrace_widest). Most pieces use less: at 1e-6
  // no bundled case needs it, and the looser τ is 1.02-1.04x faster there.
  double tau = tau_override;
  if (!(tau > 0.0)) {
    const double length = std::max(1.0, static_cast<double>(leaves.size())) * leaf_side * (std::numbers::pi / 4.0);
    const AreaWeight& w = options.weight;
    double inside_est = pass.cover.area_inside, undecided_est = pass.cover.area_undecided;
    if (!w.unit()) {
      inside_est = undecided_est = 0.0;
      for (const Box& b : pass.cover.inside) inside_est += w.box(b);
      for (const Box& b : pass.cover.undecided) undecided_est += w.box(b);
    }
    const double area_est = std::max(inside_est + 0.5 * undecided_est, 1e-6 * w.box(co.window));
    tau = target_width(options, area_est) / length;
  }
  pass.tau = tau;
  pass.depth = options.refine_depth;
  pass.small_cell = co.window.width() / (co.base * std::ldexp(1.0, co.max_depth + 4));

  pass.per_leaf.resize(leaves.size());
  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 8;
  Budget budget(options, leaves.size());
  detail::for_each_block(policy, leaves.size(), leaves.size() * 64, [&](std::size_t k) {
    refine(cs, within_test, options.weight, leaves[k], 0, options.refine_depth, tau, pass.small_cell, options.trace, budget,
           pass.per_leaf[k], detail::effective_threads(policy) > 1, leaf_tests.find(leaves[k]));
    budget.leaf_done();
  });
  pass.stopped = budget.stopped();
  return pass;
}

// Refines each of `cells` `levels` levels deep with τ = `tau`, as a task of
// its own (its leaves' refinement in parallel too where `nested`), into its
// own slot of `out`. Returns true if the deadline stopped it.
bool refine_each(const Pass& pass, const std::vector<Constraint>& cs, const WithinTest& within_test,
                 const LevelSetOptions& options, const std::vector<Box>& cells, int levels, double tau, bool nested,
                 std::vector<LeafResult>& out) {
  out.assign(cells.size(), LeafResult{});
  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 8;
  Budget budget(options, cells.size());
  detail::for_each_block(policy, cells.size(), cells.size() * 64, [&](std::size_t i) {
    refine(cs, within_test, options.weight, cells[i], 0, levels, tau, pass.small_cell, options.trace, budget, out[i],
           nested && detail::effective_threads(policy) > 1);
    budget.leaf_done();
  });
  return budget.stopped();
}

// Refines the cells a pass left undecided `levels` levels further, with the
// same τ (its traced and decided cells stay): the retry when undecided cells
// dominate the width. Each undecided cell is a task of its own (a few leaves
// next to singular points hold most of them); the results replace the cells
// in their leaf, in order, so they do not depend on the number of threads.
void deepen(Pass& pass, const std::vector<Constraint>& cs, const WithinTest& within_test,
            const LevelSetOptions& options, int levels) {
  std::vector<std::pair<std::size_t, Box>> cells;
  for (std::size_t k = 0; k < pass.per_leaf.size(); ++k) {
    for (const Box& b : pass.per_leaf[k].undecided) cells.emplace_back(k, b);
    pass.per_leaf[k].undecided.clear();
  }
  std::vector<Box> boxes;
  boxes.reserve(cells.size());
  for (const auto& c : cells) boxes.push_back(c.second);
  std::vector<LeafResult> parts;
  pass.stopped = refine_each(pass, cs, within_test, options, boxes, levels, pass.tau, false, parts) || pass.stopped;
  for (std::size_t i = 0; i < cells.size(); ++i) append(pass.per_leaf[cells[i].first], std::move(parts[i]));
  pass.depth += levels;
}

// The retry when the traced cells' width misses the target (τ was estimated
// from the cover's leaves before any trace): the leaves whose traces gain the
// most from τ' = τ / 4 are traced again with it, the largest gain first, until
// the width their traces are held to (τ' times the traced cells' extent along
// u) brings the total to 0.9 of the target; their results replace the leaf's.
// The cover, every other leaf and their tests stay. Returns the number of
// leaves traced again; 0 (the pass unchanged) where that would take half of
// the traced leaves or more: then a new pass with one τ for all (the caller)
// is cheaper per leaf. The leaves are chosen from the pass's own numbers and
// retraced as tasks into their own slots, so the result does not depend on
// the number of threads. (At 1e-9 the DexTAR (-1, -1) α <= 80°'s first pass
// missed by 3 %, and a new pass had cost 1.6 times the first.)
std::size_t retrace_widest(Pass& pass, const std::vector<Constraint>& cs, const WithinTest& within_test,
                           const LevelSetOptions& options, double width, double target) {
  constexpr double kFactor = 0.25;
  struct Leaf {
    std::size_t index;
    double gain;  // width now minus the width its retrace is held to
  };
  std::vector<Leaf> traced;
  for (std::size_t k = 0; k < pass.per_leaf.size(); ++k) {
    const LeafResult& r = pass.per_leaf[k];
    double w = 0.0, extent = 0.0;
    for (const auto* cells : {&r.traced, &r.traced_across}) {
      for (const auto& [cell, t] : *cells) {
        w += t.upper - t.lower;
        extent += t.swapped ? cell.height() : cell.width();
      }
    }
    if (w > 0.0) traced.push_back({k, w - kFactor * pass.tau * extent});
  }
  std::stable_sort(traced.begin(), traced.end(), [](const Leaf& a, const Leaf& b) { return a.gain > b.gain; });
  std::vector<std::size_t> chosen;
  double left = width - 0.9 * target;
  for (const Leaf& l : traced) {
    if (left <= 0.0 || !(l.gain > 0.0)) break;
    chosen.push_back(l.index);
    left -= l.gain;
  }
  if (left > 0.0 || 2 * chosen.size() >= traced.size()) return 0;
  std::vector<Box> boxes;
  boxes.reserve(chosen.size());
  for (const std::size_t k : chosen) boxes.push_back(pass.leaves[k]);
  std::vector<LeafResult> redone;
  pass.stopped = refine_each(pass, cs, within_test, options, boxes, options.refine_depth, kFactor * pass.tau, true, redone) ||
                 pass.stopped;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    redone[i].tests += pass.per_leaf[chosen[i]].tests;  // the first trace's tests were made too
    pass.per_leaf[chosen[i]] = std::move(redone[i]);
  }
  return chosen.size();
}

// Areas of W in groups of pieces across W's boundary (each group's pieces
// disjoint): in closed form where W is a set of signed disks (`disks`
// non-empty, area_in_disks), the pieces it cannot decide clipped to W exactly.
// The clippings are collected, then run as parallel tasks over fixed blocks
// of a group's pieces (a Region is a value, readable from any thread; each
// task builds its own polygon sets), and each group's areas are summed in
// block order, so the result does not depend on the number of threads.
class ClipToW {
 public:
  ClipToW(const Region& within, const std::vector<SignedDisk>& disks)
      : within_(within), disks_(disks),
        // A block's clipping sweeps W's curves again: at least as many pieces as W has curves.
        per_block_(std::max<std::size_t>(8, within.curve_count())) {}

  // A group of polygons; returns its index for area().
  std::size_t add(const std::vector<std::vector<Point>>& pieces) {
    const std::size_t group = sums_.size();
    sums_.emplace_back(0.0);
    std::vector<std::vector<Point>> left;
    for (const std::vector<Point>& p : pieces) {
      const std::optional<Interval> a = disks_.empty() ? std::nullopt : area_in_disks(p, disks_);
      if (a) sums_[group] = sums_[group] + *a;
      else left.push_back(p);
    }
    add_jobs(group, left, &Job::pieces);
    return group;
  }

  // A group of boxes (where W is not a set of disks: merged into rectilinear loops).
  std::size_t add(const std::vector<Box>& boxes) {
    if (!disks_.empty()) {
      std::vector<std::vector<Point>> pieces;
      pieces.reserve(boxes.size());
      for (const Box& b : boxes) pieces.push_back(box_polygon(b));
      return add(pieces);
    }
    const std::size_t group = sums_.size();
    sums_.emplace_back(0.0);
    add_jobs(group, boxes, &Job::boxes);
    return group;
  }

  void run(int threads) {
    std::vector<double> areas(jobs_.size(), 0.0);
    detail::ParallelPolicy policy;
    policy.threads = threads;
    policy.serial_threshold = 2;  // one exact clipping costs about 0.1 ms and more
    detail::for_each_block(policy, jobs_.size(), jobs_.size(), [&](std::size_t k) {
      const Job& job = jobs_[k];
      // The pieces lie in distinct cells: united by edge cancellation.
      areas[k] = within_.intersect(job.boxes.empty() ? polygons_region(job.pieces) : boxes_region(job.boxes)).area();
    });
    for (std::size_t k = 0; k < jobs_.size(); ++k) sums_[jobs_[k].group] = sums_[jobs_[k].group] + Interval(areas[k]);
    jobs_.clear();
  }

  Interval area(std::size_t group) const { return sums_[group]; }

 private:
  struct Job {
    std::size_t group;
    std::vector<std::vector<Point>> pieces;
    std::vector<Box> boxes;
  };
  // The group's items as jobs of per_block_ items (the last one fewer), in order.
  template <class T> void add_jobs(std::size_t group, const std::vector<T>& items, std::vector<T> Job::*field) {
    for (std::size_t b = 0; b < items.size(); b += per_block_) {
      Job job{group, {}, {}};
      (job.*field).assign(items.begin() + static_cast<std::ptrdiff_t>(b),
                          items.begin() + static_cast<std::ptrdiff_t>(std::min(items.size(), b + per_block_)));
      jobs_.push_back(std::move(job));
    }
  }
  const Region& within_;
  const std::vector<SignedDisk>& disks_;
  std::size_t per_block_;
  std::vector<Interval> sums_;
  std::vector<Job> jobs_;
};

// The bounds, pieces and curves of a pass. The pass is not changed: a retry
// may refine it further and summarise it again.
LevelSetResult summarize(const Pass& pass, const Region& within, const WithinTest& within_test, const AreaWeight& weight,
                         const std::vector<SignedDisk>& disks) {
  LevelSetResult result;
  const CellCover& cover_result = pass.cover;
  const std::vector<LeafResult>& per_leaf = pass.per_leaf;
  result.cell_tests = cover_result.tests;
  result.tolerance_per_length = pass.tau;
  result.stopped = pass.stopped;

  double in_lower = 0.0, traced_lower = 0.0, traced_upper = 0.0, undecided_in = 0.0;
  std::vector<Box> straddle_inside;
  std::vector<Box> inside_all = cover_result.inside;
  std::vector<Box> undecided_all;
  for (const Box& b : cover_result.inside) {
    if (within_test(b) == CellState::inside) in_lower += weight.box(b);
    else straddle_inside.push_back(b);
  }
  std::vector<std::vector<Point>> across_inner, across_outer;  // envelope polygons of traced cells across W's boundary
  // What every traced cell gives, inside W or across its boundary: counts and the curve.
  const auto take_trace = [&](const CellTrace& t) {
    ++result.traced_cells;
    result.curve_points += t.points;
    if (t.curve.size() >= 2) {
      result.curves.push_back(t.curve);
      result.curve_constraints.push_back(t.constraint);
    }
  };
  // The traced cells' envelope polygons (most of this summary's work outside
  // the clipping), built per leaf as parallel tasks over fixed blocks of
  // leaves and taken in leaf order below.
  struct LeafPolygons {
    std::vector<std::vector<Point>> inner, across_inner, across_outer;
  };
  std::vector<LeafPolygons> polygons(per_leaf.size());
  {
    std::size_t traced = 0;
    for (const LeafResult& r : per_leaf) traced += r.traced.size() + r.traced_across.size();
    detail::ParallelPolicy policy;
    policy.threads = pass.co.threads;
    policy.serial_threshold = 256;  // traced cells
    constexpr std::size_t leaves_per_block = 16;
    detail::for_each_block(policy, detail::block_count(per_leaf.size(), leaves_per_block), traced, [&](std::size_t b) {
      for (std::size_t k = b * leaves_per_block; k < std::min(per_leaf.size(), (b + 1) * leaves_per_block); ++k) {
        for (const auto& [cell, t] : per_leaf[k].traced) {
          envelope_polygons(t, cell, t.sgn < 0, polygons[k].inner);  // below env_lo, or above env_hi
        }
        for (const auto& [cell, t] : per_leaf[k].traced_across) {  // bounded below by clipping to W exactly
          envelope_polygons(t, cell, t.sgn < 0, polygons[k].across_inner);
          envelope_polygons(t, cell, t.sgn > 0, polygons[k].across_outer);
        }
      }
    });
  }
  const auto take_polygons = [](std::vector<std::vector<Point>>& from, std::vector<std::vector<Point>>& to) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
  };
  for (std::size_t k = 0; k < per_leaf.size(); ++k) {
    const LeafResult& r = per_leaf[k];
    result.cell_tests += r.tests;
    in_lower += r.in_lower;
    undecided_in += r.undecided_in;
    for (std::size_t i = 0; i < r.inside.size(); ++i) {
      inside_all.push_back(r.inside[i]);
      if (r.inside_kind[i] == InsideKind::straddle) straddle_inside.push_back(r.inside[i]);
    }
    for (const Box& b : r.undecided) {
      undecided_all.push_back(b);
      ++result.undecided_cells;
      undecided_in += weight.box(b);
    }
    for (const auto& [cell, t] : r.traced) {
      traced_lower += t.lower;
      traced_upper += t.upper;
      take_trace(t);
    }
    for (const auto& [cell, t] : r.traced_across) take_trace(t);
    take_polygons(polygons[k].inner, result.inner_polygons);
    take_polygons(polygons[k].across_inner, across_inner);
    take_polygons(polygons[k].across_outer, across_outer);
  }
  // Cells across W's boundary: exact region operations. A traced cell's part
  // of S lies between W ∩ (the cell's side of its inner envelope) and
  // W ∩ (the side of its outer envelope).
  if (!weight.unit()) {
    // A chart's plane: no exact clipping (W is not a region there); its
    // window test should decide every cell, else they count as undecided.
    for (const Box& b : straddle_inside) undecided_in += weight.box(b);
    straddle_inside.clear();
    for (const LeafResult& r : per_leaf) {
      for (const auto& [cell, t] : r.traced_across) traced_upper += weight.box(cell);
    }
    across_inner.clear();
    across_outer.clear();
  }
  // The three groups' clippings run together.
  ClipToW clip(within, disks);
  const std::size_t straddle_group = clip.add(straddle_inside), inner_group = clip.add(across_inner),
                    outer_group = clip.add(across_outer);
  clip.run(pass.co.threads);
  const Interval straddle = clip.area(straddle_group);
  if (!across_inner.empty() || !across_outer.empty()) {
    const Interval lo = clip.area(inner_group), hi = clip.area(outer_group);
    traced_lower += lo.lo;
    traced_upper += std::max(lo.hi, hi.hi);
  }
  result.inner_polygons.insert(result.inner_polygons.end(), across_inner.begin(), across_inner.end());
  // Sums of positive terms: relative rounding ~ n eps; a margin of 1e-13 of the total.
  const double lower = in_lower + straddle.lo + traced_lower;
  const double upper = in_lower + straddle.hi + traced_upper + undecided_in;
  result.region.area_lower = std::max(0.0, lower * (1.0 - 1e-13));
  result.region.area_upper = upper * (1.0 + 1e-13);
  result.undecided_area = undecided_in;
  result.traced_width = traced_upper - traced_lower;
  result.region.exact = false;
  result.inside_boxes = std::move(inside_all);
  result.undecided_boxes = std::move(undecided_all);
  return result;
}

// The exact inner/outer regions of the pass `result` summarises (asked with
// build_regions; built once, for the final pass): the cells certified in S
// (and, for outer, the undecided ones) as boxes, and each traced cell's part
// on S's side of a few chords that follow its inner / outer envelope within
// a quarter of τ (follow_envelope). So inner ⊆ S ⊆ outer, area(inner) <=
// area_lower and area(outer) >= area_upper, each within about half of the
// traced cells' width more.
void add_regions(const Pass& pass, const Region& within, const LevelSetOptions& options, LevelSetResult& result) {
  // Past the deadline the exact regions (seconds to minutes of Boolean
  // operations on many boxes) are not started either.
  if (std::chrono::steady_clock::now() >= options.deadline) result.stopped = true;
  if (result.stopped) return;  // stopped: too many cells to be worth it
  const bool want_inner = options.regions != LevelSetOptions::Regions::outer;
  const bool want_outer = options.regions != LevelSetOptions::Regions::inner;
  std::vector<std::vector<Point>> in_parts, out_parts;
  for (const Box& b : result.inside_boxes) {
    if (want_inner) in_parts.push_back(box_polygon(b));
    if (want_outer) out_parts.push_back(box_polygon(b));
  }
  if (want_outer) {
    for (const Box& b : result.undecided_boxes) out_parts.push_back(box_polygon(b));
  }
  const double tol = 0.25 * pass.tau;
  for (const LeafResult& r : pass.per_leaf) {
    for (const auto* traced : {&r.traced, &r.traced_across}) {
      for (const auto& [cell, t] : *traced) {
        const double v0 = t.swapped ? cell.min.x : cell.min.y, v1 = t.swapped ? cell.max.x : cell.max.y;
        for (const bool inner : {true, false}) {
          if (!(inner ? want_inner : want_outer)) continue;
          // S's part lies below h (sgn > 0) or above it: inner takes the
          // envelope on S's side and stays on it, outer the other one.
          const bool use_hi = (t.sgn > 0) != inner;
          envelope_polygons(follow_envelope(use_hi ? t.env_hi : t.env_lo, v0, v1, use_hi, tol), t, cell,
                            inner ? in_parts : out_parts);
        }
      }
    }
  }
  if (want_inner) result.region.inner = within.intersect(polygons_region(in_parts));
  if (want_outer) result.region.outer = within.intersect(polygons_region(out_parts));
}

}  // namespace

LevelSetResult sublevel_set(const std::vector<Constraint>& constraints, const Region& within,
                            const WithinTest& within_test, const LevelSetOptions& given) {
  if (!(given.relative_tolerance > 0.0)) throw std::invalid_argument("sublevel_set: relative_tolerance must be positive");
  if (!(given.absolute_tolerance >= 0.0)) throw std::invalid_argument("sublevel_set: absolute_tolerance must be >= 0");
  if (given.refine_depth < 0 || given.refine_depth > 40) throw std::invalid_argument("sublevel_set: refine_depth in [0, 40]");
  if (given.cover_depth < 0 || given.cover_depth > 24) throw std::invalid_argument("sublevel_set: cover_depth in [0, 24]");
  const LevelSetOptions options = resolved(given);
  if (constraints.empty()) throw std::invalid_argument("sublevel_set: no field");
  if (within.empty()) {
    LevelSetResult r;
    r.region = from_exact(within);
    return r;
  }
  // The regions (costly) only for the final pass: the retries need the bounds.
  const auto final_result = [&](const Pass& pass, LevelSetResult&& bounds) {
    if (options.build_regions && options.weight.unit()) add_regions(pass, within, options, bounds);
    return std::move(bounds);
  };
  Pass pass = first_pass(constraints, within, within_test, options, 0.0);
  LevelSetResult r = summarize(pass, within, within_test, options.weight, options.within_disks);
  // Retries (not when the deadline stopped the first run: a retry would stop
  // too). When the traced cells dominate the width (the estimate of area or
  // curve length was off), one rerun with a tighter τ. When the undecided
  // cells do, they alone are refined further, as many levels as the shortfall
  // needs, again while the target is missed. How far depends on how their
  // area shrinks per level, measured on the way: by about 2 where they form a
  // band along a curve (their number doubles per level), ~2.8 next to a
  // tangency with W's boundary, 4 around isolated points (the 0/0 points of a
  // criterion, where every level curve ends: their number stays). Bands and
  // tangencies go at most 4 levels deeper (~16 times narrower, at 16 times
  // the cells), and only when the first pass's width is within that reach
  // (64 times the target): far beyond it (a level at the field's extreme,
  // where the set degenerates to a curve and no depth decides its cells) the
  // bounds reached are the answer. Points go
  // up to 16 levels deeper (each level costs the same few cells). Where the
  // kind is not known yet, a one-level step measures it.
  const auto target = [&] { return target_width(options, r.region.area_upper); };
  const auto width = [&] { return r.region.width(); };
  if (!options.trace || !options.retries || r.stopped || width() <= target()) return final_result(pass, std::move(r));
  if (r.traced_width > 0.5 * width()) {
    const std::size_t retraced = retrace_widest(pass, constraints, within_test, options, width(), target());
    if (retraced > 0) {
      LevelSetResult again = summarize(pass, within, within_test, options.weight, options.within_disks);
      again.retraced_leaves = retraced;
      if (again.stopped || again.region.width() <= target()) return final_result(pass, std::move(again));
    }
    const double tau = r.tolerance_per_length * 0.5 * target() / width();
    const Pass again = first_pass(constraints, within, within_test, options, tau);
    return final_result(again, summarize(again, within, within_test, options.weight, options.within_disks));
  }
  const int band_depth = std::min(40, options.refine_depth + 4), point_depth = std::min(40, options.refine_depth + 16);
  // Beyond the bands' reach, the probe costs at most a quarter of the first
  // pass and the retries together at most the first pass (each level tests
  // about 4 cells per undecided cell).
  const bool reach = width() <= max_retry_gain * target();
  const std::uint64_t first_tests = r.cell_tests;
  const auto affordable = [&](int levels, std::uint64_t share) {
    return share * (r.cell_tests - first_tests + 4 * static_cast<std::uint64_t>(levels) * r.undecided_cells) <= first_tests;
  };
  double shrink = 0.0, growth = 0.0;  // per level, measured: the undecided area's shrink, their number's growth
  while (!r.stopped && width() > target() && r.undecided_area > 0.0) {
    const bool points = shrink >= 3.0 && growth <= 1.5;
    const int cap = points ? point_depth : band_depth;
    if (pass.depth >= cap || (!reach && !points && shrink > 0.0)) break;
    const double room = target() - r.traced_width;
    const double need = room > 0.0 ? 1.25 * r.undecided_area / room : 16.0;
    int levels = std::clamp(static_cast<int>(std::ceil(std::log(std::max(need, 2.0)) / std::log(points ? 3.0 : 2.0))), 1,
                            cap - pass.depth);
    if (!reach) {
      if (shrink == 0.0) levels = 1;  // the probe
      while (levels > 0 && !affordable(levels, shrink == 0.0 ? 4 : 1)) --levels;
      if (levels == 0) break;
    }
    const double before = r.undecided_area;
    const auto count = static_cast<double>(r.undecided_cells);
    deepen(pass, constraints, within_test, options, levels);
    r = summarize(pass, within, within_test, options.weight, options.within_disks);
    shrink = r.undecided_area > 0.0 ? std::pow(before / r.undecided_area, 1.0 / levels) : inf;
    growth = std::pow(static_cast<double>(r.undecided_cells) / std::max(count, 1.0), 1.0 / levels);
  }
  return final_result(pass, std::move(r));
}

LevelSetResult sublevel_set(const ScalarField& field, double level, const Region& within, const WithinTest& within_test,
                            const LevelSetOptions& options) {
  return sublevel_set(std::vector<Constraint>{{&field, level}}, within, within_test, options);
}

CertifiedRegion certify_cells(const ScalarField& field, double level, const Region& within, int base, int max_depth,
                              int threads) {
  CellOptions co;
  co.base = base;
  co.max_depth = max_depth;
  co.threads = threads;
  const std::vector<Constraint> cs{{&field, level}};
  return certify([&](const Box& b) { return classify(cs, b); }, within, co);
}

std::vector<Band> bands_from_sublevels(const std::vector<double>& levels, const std::vector<LevelSetResult>& sublevels) {
  if (levels.size() != sublevels.size()) throw std::invalid_argument("bands_from_sublevels: one result per level");
  std::vector<Band> out;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    Band b;
    b.upper_level = levels[k];
    b.lower_level = k == 0 ? -inf : levels[k - 1];
    const CertifiedRegion& s = sublevels[k].region;
    if (k == 0) {
      b.area_lower = s.area_lower;
      b.area_upper = s.area_upper;
    } else {
      const CertifiedRegion& p = sublevels[k - 1].region;
      // S_{k-1} ⊆ S_k: area(band) = area(S_k) - area(S_{k-1}).
      b.area_lower = std::max(0.0, s.area_lower - p.area_upper);
      b.area_upper = std::max(0.0, s.area_upper - p.area_lower);
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace pkmws::certified
