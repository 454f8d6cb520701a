// Five-bar criterion fields ([Briot]): the pressure angle and the reaction as
// cos²ε, the velocity ratio and condition number from the rows of dq/dC, all
// from the closed-form inverse kinematics (docs/theory/level_sets.md).
#include "mechanisms/five_bar/criteria.hpp"

#include "criteria/support.hpp"

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
  // Derived constants in T arithmetic, so that interval evaluations enclose
  // their rounding too.
  template <class T> struct Leg {
    T wx, wy, ux, uy;
  };
  template <class T> Leg<T> leg(std::size_t i, const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    const T p = T(l1[i]), q = T(l2[i]);
    Leg<T> g{x - base[i].x, y - base[i].y, T(0.0), T(0.0)};
    const T r2 = sqr(g.wx) + sqr(g.wy);
    const T inv2r2 = 0.5 / r2;
    const T one_minus_a = 0.5 - (p - q) * (p + q) * inv2r2;
    const T d = (sqr(p + q) - r2) * (r2 - sqr(p - q));
    const T b = sqrt(max(d, 0.0)) * inv2r2;
    g.ux = one_minus_a * g.wx + s[i] * (b * g.wy);
    g.uy = one_minus_a * g.wy - s[i] * (b * g.wx);
    return g;
  }
  template <class T> T cos_eps(const T& x, const T& y) const {
    const Leg<T> g0 = leg(0, x, y), g1 = leg(1, x, y);
    return (g0.ux * g1.ux + g0.uy * g1.uy) / (T(l2[0]) * T(l2[1]));
  }
  // det A = u_1 x u_2: zero where the distal links are aligned (type 2,
  // [Briot]: A's rows are the distal directions; derived).
  template <class T> T singular_det(const T& x, const T& y) const {
    const Leg<T> g0 = leg(0, x, y), g1 = leg(1, x, y);
    return g0.ux * g1.uy - g0.uy * g1.ux;
  }
  // Rows of dq/dC: differentiating |C - B_i|² = l_i2² with B_i - A_i = w - u_i
  // gives dq_i = u_i . dC / (w_i x u_i) (the eval's B⁻¹A, docs/theory/five_bar.md).
  // As u_i / (w_i x u_i) (the cross product vanishes at a leg's type-1 singularity).
  template <class T> Rows2<T> rows(const T& x, const T& y) const {
    const Leg<T> g0 = leg(0, x, y), g1 = leg(1, x, y);
    return {g0.ux, g0.uy, g1.ux, g1.uy, g0.wx * g0.uy - g0.wy * g0.ux, g1.wx * g1.uy - g1.wy * g1.ux};
  }
  // Smooth where every leg is strictly inside its annulus (D > 0, r > 0).
  CellState domain(const Box& b) const {
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Interval r2 = dist2(b, base[i]);
      if (r2.lo > r_out2[i] || r2.hi < r_in2[i]) return CellState::outside;
      inside = inside && r2.hi < r_out2[i] && r2.lo > r_in2[i] && r2.lo > 0.0;
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
