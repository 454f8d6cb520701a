// Five-bar criterion fields ([Briot]): the pressure angle and the reaction as
// cos²ε, the velocity ratio and condition number from the rows of dq/dC, all
// from the closed-form inverse kinematics (docs/theory/level_sets.md).
#include "mechanisms/five_bar/criteria.hpp"

#include "criteria/support.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::criteria {

namespace {

// Five-bar: cos ε from the inverse kinematics in closed form.
//
// Leg i, w = C - A_i, r² = |w|²: the elbow is B_i = A_i + a w + s b J w with
// a = 1/2 + (l1² - l2²) / (2 r²), b = sqrt(D) / (2 r²),
// D = ((l1 + l2)² - r²)(r² - (l1 - l2)²) (law of cosines, docs/theory/five_bar.md
// eq. IK: cos β = (r² + l1² - l2²) / (2 r l1)), J the rotation by +90°, and
// s the working mode (s = sign(w x (B_i - A_i))). Distal vector
// u_i = C - B_i = (1 - a) w - s b J w; cos ε = u_1 . u_2 / (l12 l22).
struct FiveBarCosEps {
  std::array<Point, 2> base;
  std::array<double, 2> l1, l2, s;
  std::array<double, 2> r_out2, r_in2;
  std::array<std::optional<std::array<double, 2>>, 2> limits;  // crank angles (explicit or from a Π-joint)

  explicit FiveBarCosEps(const mechanisms::FiveBar& m) {
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& leg = m.legs()[i];
      limits[i] = m.crank_limits(static_cast<int>(i));
      base[i] = leg.base;
      l1[i] = leg.proximal;
      l2[i] = leg.distal;
      s[i] = leg.working_mode;
      r_out2[i] = (l1[i] + l2[i]) * (l1[i] + l2[i]);
      r_in2[i] = (l1[i] - l2[i]) * (l1[i] - l2[i]);
    }
  }
  // Leg i at C = (x, y): w = C - A_i and the distal vector u = C - B_i.
  // Derived constants in the scalar arithmetic S of T, so that interval
  // evaluations enclose their rounding too (and jets carry no derivatives of
  // constants).
  template <class T> struct Leg {
    T wx, wy, ux, uy;
  };
  template <class T> Leg<T> leg(std::size_t i, const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    using S = certified::scalar_t<T>;
    const S p = S(l1[i]), q = S(l2[i]);
    Leg<T> g{x - base[i].x, y - base[i].y, T(0.0), T(0.0)};
    const T r2 = sqr(g.wx) + sqr(g.wy);
    const T inv2r2 = 0.5 / r2;
    const T one_minus_a = 0.5 - ((p - q) * (p + q)) * inv2r2;
    const T d = (sqr(p + q) - r2) * (r2 - sqr(p - q));
    const T b = sqrt(max(d, 0.0)) * inv2r2;
    g.ux = one_minus_a * g.wx + s[i] * (b * g.wy);
    g.uy = one_minus_a * g.wy - s[i] * (b * g.wx);
    return g;
  }
  // The same for jets over a box, cheaper: 1 - a and b are functions of ρ = r²
  // alone, A(ρ) = ½ - c/(2ρ) with c = l1² - l2², B(ρ) = √D(ρ)/(2ρ) with
  // D = ((l1 + l2)² - ρ)(ρ - (l1 - l2)²), each composed with ρ's jet from its
  // closed-form first and second derivatives (derived; two compositions in
  // place of the generic chain's reciprocal, square root and two products).
  Leg<certified::Jet<Interval>> leg(std::size_t i, const certified::Jet<Interval>& x,
                                    const certified::Jet<Interval>& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    const Interval p(l1[i]), q(l2[i]);
    Leg<certified::Jet<Interval>> g{x - Interval(base[i].x), y - Interval(base[i].y), {}, {}};
    const certified::Jet<Interval> rho = sqr(g.wx) + sqr(g.wy);
    const Interval r = rho.v, c = (p - q) * (p + q), big = sqr(p + q), small = sqr(p - q);
    const Interval h = Interval(0.5) / r, h1 = -(Interval(2.0) * sqr(h)), h2 = Interval(8.0) * sqr(h) * h;  // 1/(2ρ)
    const Interval d = (big - r) * (r - small), d1 = big + small - Interval(2.0) * r;  // D'' = -2
    const Interval sd = sqrt(max(d, 0.0)), sd1 = d1 / (Interval(2.0) * sd), sd2 = -(Interval(1.0) + sqr(sd1)) / sd;
    const certified::Jet<Interval> one_minus_a = certified::compose(rho, Interval(0.5) - c * h, -(c * h1), -(c * h2));
    const certified::Jet<Interval> b =
        certified::compose(rho, sd * h, sd1 * h + sd * h1, sd2 * h + Interval(2.0) * (sd1 * h1) + sd * h2);
    g.ux = one_minus_a * g.wx + s[i] * (b * g.wy);
    g.uy = one_minus_a * g.wy - s[i] * (b * g.wx);
    return g;
  }
  template <class T> T cos_eps(const T& x, const T& y) const { return cos_eps_of(leg(0, x, y), leg(1, x, y)); }
  // |u_1| |u_2|: sin ε = det A / eps_scale() (det A = singular_det).
  double eps_scale() const { return l2[0] * l2[1]; }
  template <class T> T cos_eps_of(const Leg<T>& g0, const Leg<T>& g1) const {
    using S = certified::scalar_t<T>;
    return (g0.ux * g1.ux + g0.uy * g1.uy) / (S(l2[0]) * S(l2[1]));
  }
  // det A = u_1 x u_2: zero where the distal links are aligned (type 2,
  // [Briot]: A's rows are the distal directions; derived).
  template <class T> T singular_det(const T& x, const T& y) const { return singular_det_of(leg(0, x, y), leg(1, x, y)); }
  template <class T> static T singular_det_of(const Leg<T>& g0, const Leg<T>& g1) { return g0.ux * g1.uy - g0.uy * g1.ux; }
  // Rows of dq/dC: differentiating |C - B_i|² = l_i2² with B_i - A_i = w - u_i
  // gives dq_i = u_i . dC / (w_i x u_i) (the eval's B⁻¹A, docs/theory/five_bar.md).
  // As u_i / (w_i x u_i) (the cross product vanishes at a leg's type-1 singularity).
  template <class T> Rows2<T> rows(const T& x, const T& y) const { return rows_of(leg(0, x, y), leg(1, x, y)); }
  template <class T> static Rows2<T> rows_of(const Leg<T>& g0, const Leg<T>& g1) {
    return {g0.ux, g0.uy, g1.ux, g1.uy, g0.wx * g0.uy - g0.wy * g0.ux, g1.wx * g1.uy - g1.wy * g1.ux};
  }
  // Leg j strictly inside its annulus (and off its base) over a box: C² there.
  CellState leg_domain(std::size_t j, const Interval& r2) const {
    if (r2.lo > r_out2[j] || r2.hi < r_in2[j]) return CellState::outside;
    return r2.hi < r_out2[j] && r2.lo > r_in2[j] && r2.lo > 0.0 ? CellState::inside : CellState::undecided;
  }
  // The charts at the stretched legs' circles and at the base joints of equal
  // links (defined after FiveBarChart).
  std::optional<CriterionFields::Charts> charts(const geometry::Region& workspace) const;
  // Smooth where every leg is strictly inside its annulus (D > 0, r > 0).
  CellState domain(const Box& b) const {
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const CellState c = leg_domain(i, dist2(b, base[i]));
      if (c == CellState::outside) return c;
      inside = inside && c == CellState::inside;
    }
    return inside ? CellState::inside : CellState::undecided;
  }
  // Box ⊆ workspace: inside both annuli and, with crank limits, every crank
  // direction B_i - A_i = w - u over the box (interval arithmetic) inside the
  // allowed sector of angles.
  CellState within(const Box& box) const {
    const CellState annuli = domain(box);
    if (annuli == CellState::outside) return annuli;
    bool inside = annuli == CellState::inside;
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    for (std::size_t i = 0; i < 2; ++i) {
      if (!limits[i]) continue;
      if (!(dist2(box, base[i]).lo > 0.0)) return CellState::undecided;
      const Leg<Interval> g = leg(i, x, y);
      const CellState sector = in_sector(g.wx - g.ux, g.wy - g.uy, (*limits[i])[0], (*limits[i])[1]);
      if (sector == CellState::outside) return sector;
      inside = inside && sector == CellState::inside;
    }
    return inside ? CellState::inside : CellState::undecided;
  }
  // Position of the directions of the vector box (dx, dy) against the angle
  // sector [lo, hi] (hi - lo <= 2 pi): the box's extreme directions are at its
  // corners (when it misses the origin); atan2's rounding is covered by a margin.
  static CellState in_sector(const Interval& dx, const Interval& dy, double lo, double hi) {
    if (dx.contains_zero() && dy.contains_zero()) return CellState::undecided;
    const double ref = std::atan2(0.5 * (dy.lo + dy.hi), 0.5 * (dx.lo + dx.hi));
    double amin = inf_angle, amax = -inf_angle;
    for (double cx : {dx.lo, dx.hi}) {
      for (double cy : {dy.lo, dy.hi}) {
        double t = std::atan2(cy, cx);
        while (t > ref + pi) t -= 2 * pi;
        while (t <= ref - pi) t += 2 * pi;
        amin = std::min(amin, t);
        amax = std::max(amax, t);
      }
    }
    constexpr double margin = 1e-12;
    amin -= margin;
    amax += margin;
    // Shift the directions' range next to the sector.
    const double shift = 2 * pi * std::floor((amin - lo) / (2 * pi));
    amin -= shift;
    amax -= shift;  // now lo <= amin < lo + 2 pi
    if (amax <= hi) return CellState::inside;
    if (amin > hi && amax < lo + 2 * pi) return CellState::outside;
    return CellState::undecided;
  }
  static constexpr double inf_angle = std::numeric_limits<double>::infinity();
};

// A chart about the base A_k of leg k (docs/theory/level_sets.md, "Charts"):
// θ = c u is the angle of C - A_k from the unit direction d, and
//  - at the circle where leg k is stretched (r = R = l1 + l2, W's boundary):
//    v = s = √(R² - r²), so that √D = s √(r² - (l1 - l2)²) = s √(4 l1 l2 - s²)
//    is smooth across s = 0 (the law of cosines of the inverse kinematics,
//    docs/theory/five_bar.md eq. IK); dA = r dr dθ = c s ds du;
//  - at the base joint of equal links (C = A_k, every level curve ends there):
//    v = r, where √D / (2r) = √(R² - r²) / 2 and (1 - a) r = r / 2 are smooth
//    at r = 0; dA = c r dr du.
// Leg k's vectors come from (u, v) directly, the other leg's from C(u, v).
struct FiveBarChart {
  FiveBarCosEps plane;
  std::size_t k = 0;
  bool at_base = false;
  double c = 1.0;    // θ = c u
  Point d{1.0, 0.0};  // θ = 0

  template <class T> FiveBarCosEps::Leg<T> chart_leg(const T& u, const T& v, T& x, T& y) const {
    using certified::cos;
    using certified::max;
    using certified::sin;
    using certified::sqr;
    using certified::sqrt;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T th = c * u;
    const T ct = cos(th), st = sin(th);
    const T ex = ct * d.x - st * d.y, ey = ct * d.y + st * d.x;
    using S = certified::scalar_t<T>;
    const S p = S(plane.l1[k]), q = S(plane.l2[k]);
    T r, alpha, beta;  // alpha = (1 - a) r, beta = √D / (2r)
    if (at_base) {  // l1 = l2
      r = v;
      alpha = 0.5 * v;
      beta = 0.5 * sqrt(max(sqr(p + q) - sqr(v), 0.0));
    } else {
      r = sqrt(max(sqr(p + q) - sqr(v), 0.0));
      alpha = (sqr(r) - (p - q) * (p + q)) / (2.0 * r);
      beta = v * sqrt(max(4.0 * p * q - sqr(v), 0.0)) / (2.0 * r);
    }
    FiveBarCosEps::Leg<T> g{r * ex, r * ey, T(0.0), T(0.0)};
    x = plane.base[k].x + g.wx;
    y = plane.base[k].y + g.wy;
    const double s = plane.s[k];
    g.ux = alpha * ex + s * (beta * ey);
    g.uy = alpha * ey - s * (beta * ex);
    return g;
  }
  template <class T> std::array<FiveBarCosEps::Leg<T>, 2> legs(const T& u, const T& v) const {
    T x, y;
    const FiveBarCosEps::Leg<T> gk = chart_leg(u, v, x, y);
    const FiveBarCosEps::Leg<T> gj = plane.leg(1 - k, x, y);
    return k == 0 ? std::array{gk, gj} : std::array{gj, gk};
  }
  Point to_plane(double u, double v) const {
    double x = 0.0, y = 0.0;
    chart_leg(u, v, x, y);
    return {x, y};
  }
  template <class T> T cos_eps(const T& u, const T& v) const {
    const auto g = legs(u, v);
    return plane.cos_eps_of(g[0], g[1]);
  }
  double eps_scale() const { return plane.eps_scale(); }
  template <class T> T singular_det(const T& u, const T& v) const {
    const auto g = legs(u, v);
    return FiveBarCosEps::singular_det_of(g[0], g[1]);
  }
  template <class T> Rows2<T> rows(const T& u, const T& v) const {
    const auto g = legs(u, v);
    return FiveBarCosEps::rows_of(g[0], g[1]);
  }
  // C(u, v) over a box, and whether leg k's formulas are smooth there
  // (|v| < R at the base, |v| < √(4 l1 l2) <= R at the circle: then r > 0).
  bool chart_smooth(const Box& b) const {
    const double vmax = std::max(std::abs(b.min.y), std::abs(b.max.y));
    const double lim = at_base ? plane.l1[k] + plane.l2[k] : 2.0 * std::sqrt(plane.l1[k] * plane.l2[k]);
    return vmax < lim * (1.0 - 1e-9);
  }
  Interval image_dist2(const Box& b, Point centre) const {
    Interval x, y;
    chart_leg(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y), x, y);
    return sqr(x - Interval(centre.x)) + sqr(y - Interval(centre.y));
  }
  CellState domain(const Box& b) const {
    if (!chart_smooth(b)) return CellState::undecided;
    return plane.leg_domain(1 - k, image_dist2(b, plane.base[1 - k]));
  }
  // The window is the chart's domain; W's boundary is in the cuts.
  CellState within(const Box&) const { return CellState::inside; }
};

// A condition of a chart's part of W, as a field F <= 0 in (u, v):
// σ (|C - centre|² - ρ²) with ρ = ρa + ρb (σ = +1: inside the disk, -1:
// outside). (The edge towards the rest, a line v = const, is the window's.)
struct FiveBarChartCut {
  FiveBarChart chart;
  Point centre{};
  double rho_a = 0.0, rho_b = 0.0;
  double sign = 1.0;
  template <class T> T eval(const T& u, const T& v) const {
    using certified::sqr;
    const T rho = T(rho_a) + T(rho_b);
    T x, y;
    chart.chart_leg(u, v, x, y);
    return sign * (sqr(x - centre.x) + sqr(y - centre.y) - sqr(rho));
  }
  CellState domain(const Box& b) const { return chart.chart_smooth(b) ? CellState::inside : CellState::undecided; }
};

// Where both bands overlap (both legs nearly stretched), each point goes to
// the band whose leg is the closer to stretched, relative to the band's
// depth: D_i = (R_i² − r_i²) / (R_i² − ρ_i²) (0 on W's circle r_i = R_i, 1 on
// the band's inner circle). Band k's part has D_k <= D_j: F = w_j (R_k² − r_k²)
// − w_k (R_j² − r_j²) <= 0 with w_i = R_i² − ρ_i², one real function of C for
// both bands (σ = +1 for band 0, −1 for band 1; its constants enclosed in the
// scalar type). So the other leg's circle r_j = R_j (D_j = 0, where the field
// is singular and band k's coordinates do not smooth it) meets band k's part
// only where D_k = 0 too, at W's corners; a level curve crossing it does so
// in band j's chart, where it is smooth. D_j >= D_k >= 0 also keeps the part
// inside r_j <= R_j.
struct FiveBarBandSplit {
  FiveBarChart chart;
  std::array<double, 2> rho{};  // the bands' inner radii
  double sign = 1.0;
  template <class T> T eval(const T& u, const T& v) const {
    using certified::sqr;
    using S = certified::scalar_t<T>;
    const FiveBarCosEps& p = chart.plane;
    T x, y;
    chart.chart_leg(u, v, x, y);
    const std::array<S, 2> reach2{sqr(S(p.l1[0]) + S(p.l2[0])), sqr(S(p.l1[1]) + S(p.l2[1]))};  // R_i²
    const auto depth2 = [&](std::size_t i) { return reach2[i] - sqr(S(rho[i])); };          // w_i
    const auto slack = [&](std::size_t i) {                                                  // R_i² − r_i²
      return reach2[i] - (sqr(x - p.base[i].x) + sqr(y - p.base[i].y));
    };
    return sign * (depth2(1) * slack(0) - depth2(0) * slack(1));
  }
  CellState domain(const Box& b) const { return chart.chart_smooth(b) ? CellState::inside : CellState::undecided; }
};

std::optional<CriterionFields::Charts> FiveBarCosEps::charts(const geometry::Region& workspace) const {
  for (const auto& l : limits) {
    if (l) return std::nullopt;  // crank limits: W is not the two annuli alone
  }
  CriterionFields::Charts out;
  // Bands at the circles r_k = R_k (width R_k / 32), disks at the bases of equal links (radius R_k / 6).
  std::array<double, 2> R{}, rho{}, rho_base{};
  std::array<bool, 2> band{}, at_base{};
  const double dist = std::hypot(base[1].x - base[0].x, base[1].y - base[0].y);
  for (std::size_t k = 0; k < 2; ++k) {
    R[k] = l1[k] + l2[k];
    rho[k] = R[k] * (31.0 / 32.0);
    band[k] = rho[k] > std::abs(l1[k] - l2[k]) && dist > 0.0;
    rho_base[k] = R[k] / 6.0;
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t j = 1 - k;
    // The base disk lies inside the rest: off the other leg's band and its inner circle.
    // Off the other base disk too (bases closer than the two radii: no base charts).
    at_base[k] = l1[k] == l2[k] && dist + rho_base[k] < (band[j] ? rho[j] : R[j]) &&
                 dist - rho_base[k] > std::abs(l1[j] - l2[j]) && rho_base[k] < rho[k] &&
                 dist > 1.01 * (rho_base[0] + rho_base[1]);
  }
  if (!band[0] && !band[1] && !at_base[0] && !at_base[1]) return std::nullopt;
  geometry::Region rest = workspace;
  for (std::size_t k = 0; k < 2; ++k) {
    if (band[k]) rest = rest.intersect(geometry::disk(base[k], rho[k]));
  }
  for (std::size_t k = 0; k < 2; ++k) {
    if (at_base[k]) rest = rest.subtract(geometry::disk(base[k], rho_base[k]));
  }
  out.rest = std::move(rest);
  // The same set as signed disks: W's annuli, inside the bands' inner
  // circles, outside the base disks.
  for (std::size_t k = 0; k < 2; ++k) {
    out.rest_disks.push_back({base[k], R[k], true});
    if (l1[k] != l2[k]) out.rest_disks.push_back({base[k], std::abs(l1[k] - l2[k]), false});
    if (band[k]) out.rest_disks.push_back({base[k], rho[k], true});
    if (at_base[k]) out.rest_disks.push_back({base[k], rho_base[k], false});
  }
  out.rest_test = [self = *this, band, rho, at_base, rho_base](const Box& b) {
    CellState c = self.within(b);
    if (c == CellState::outside) return c;
    for (std::size_t k = 0; k < 2; ++k) {
      const Interval r2 = dist2(b, self.base[k]);
      if (band[k]) {
        const Interval lim = sqr(Interval(rho[k]));
        if (r2.lo > lim.hi) return CellState::outside;
        if (!(r2.hi < lim.lo)) c = CellState::undecided;
      }
      if (at_base[k]) {
        const Interval lim = sqr(Interval(rho_base[k]));
        if (r2.hi < lim.lo) return CellState::outside;
        if (!(r2.lo > lim.hi)) c = CellState::undecided;
      }
    }
    return c;
  };
  constexpr double pi_up = 3.1415926535897936;  // the double above π
  // A window over angles [-θm, θm] (θm = π: the full turn, overlapping by
  // under 1e-14 rad) for radii [0, vmax] of a chart with θ = c u.
  const auto make_chart = [&](std::size_t k, bool base_chart, double theta_max, double vmax, double band_area_per_rad) {
    const double scale = base_chart ? rho_base[k] : R[k];  // u in lengths: arc length at that radius
    const std::size_t j = 1 - k;
    const FiveBarChart m{*this, k, base_chart, 1.0 / scale,
                         Point{(base[j].x - base[k].x) / dist, (base[j].y - base[k].y) / dist}};
    const bool full = theta_max >= 3.14;
    const double umax = (full ? pi_up * (1.0 + 4e-16) : theta_max) * scale;
    CriterionFields::Chart ch;
    // The part towards the rest, v <= vc (r >= ρ_k on the band, r <= ρ_base at a
    // base; vmax is vc to 1e-14), ends at the window's top edge vt just
    // below vc, not at a cut: where a level curve crossed a cut's curve both
    // were undecided, and no depth traced such cells (the DexTAR (-1, +1),
    // α <= 40°: 860 traced cells of band 0 piled up at one such crossing).
    // The sliver vt < v <= vc is in neither part: its area, ∫ c v dv du, is
    // added to the upper bounds.
    const double vt = vmax * (1.0 - 1e-12);
    ch.window = Box{{-umax, 0.0}, {umax, vt}};
    ch.weight = certified::AreaWeight{0.0, 0.0, m.c};
    ch.overlap = full ? 1e-14 * band_area_per_rad : 0.0;
    const double vc = vmax * (1.0 + 1e-13);
    ch.uncovered = m.c * umax * (vc - vt) * (vc + vt) * (1.0 + 1e-9);
    ch.to_plane = [m](Point p) { return m.to_plane(p.x, p.y); };
    ch.field = point_platform_chart_fields(m, "five_bar");
    const auto cut = [&](Point centre, double ra, double rb, double sign) {
      FiveBarChartCut f{m, centre, ra, rb, sign};
      ch.cuts.push_back({std::make_shared<certified::TemplateField<FiveBarChartCut>>(f), 0.0});
    };
    if (!base_chart) {
      if (band[j]) {
        const FiveBarBandSplit f{m, rho, k == 0 ? 1.0 : -1.0};
        ch.cuts.push_back({std::make_shared<certified::TemplateField<FiveBarBandSplit>>(f), 0.0});
      } else {
        cut(base[j], l1[j], l2[j], 1.0);  // r_j <= R_j
      }
      if (l1[j] != l2[j]) cut(base[j], l1[j], -l2[j], -1.0);  // r_j >= |l1 - l2|
      for (std::size_t b = 0; b < 2; ++b) {
        const double db = b == k ? 0.0 : dist;
        if (at_base[b] && db + rho_base[b] >= rho[k]) cut(base[b], rho_base[b], 0.0, -1.0);
      }
    }
    out.charts.push_back(std::move(ch));
  };
  for (std::size_t k = 0; k < 2; ++k) {
    if (!band[k]) continue;
    const std::size_t j = 1 - k;
    // Band k meets disk j at angles up to θm from d (at its inner radius ρ_k,
    // where cos θ = (ρ² + dist² - R_j²) / (2 ρ dist) is smallest when A_k is inside disk j).
    double theta_max = 4.0;
    if (dist < R[j]) {
      const double cm = (rho[k] * rho[k] + dist * dist - R[j] * R[j]) / (2.0 * rho[k] * dist);
      if (cm > -1.0) theta_max = std::acos(std::min(1.0, cm)) + 0.02;
    }
    make_chart(k, false, std::min(theta_max, 4.0), std::sqrt((R[k] - rho[k]) * (R[k] + rho[k])),
               0.5 * (R[k] - rho[k]) * (R[k] + rho[k]));
  }
  for (std::size_t k = 0; k < 2; ++k) {
    if (at_base[k]) make_chart(k, true, 4.0, rho_base[k], 0.5 * rho_base[k] * rho_base[k]);
  }
  return out;
}
}  // namespace

CriterionField five_bar_pressure_angle(const mechanisms::FiveBar& m) {
  return point_platform_field(FiveBarCosEps(m), m, "five_bar", "pressure_angle");
}
CriterionField five_bar_reaction(const mechanisms::FiveBar& m, double force_N) {
  return point_platform_field(FiveBarCosEps(m), m, "five_bar", "reaction", force_N);
}
CriterionField five_bar_velocity_ratio(const mechanisms::FiveBar& m) {
  return point_platform_field(FiveBarCosEps(m), m, "five_bar", "velocity_ratio");
}
CriterionField five_bar_condition_number(const mechanisms::FiveBar& m) {
  return point_platform_field(FiveBarCosEps(m), m, "five_bar", "condition_number");
}

// Crank limits and Π-joint drives bound the workspace W, which the level sets
// are restricted to (within()).
std::shared_ptr<const CriterionFields> five_bar_fields(const mechanisms::FiveBar& mechanism) {
  return std::make_shared<PointPlatformFields<FiveBarCosEps>>(FiveBarCosEps(mechanism), &mechanism, "five_bar");
}

}  // namespace pkmws::criteria
