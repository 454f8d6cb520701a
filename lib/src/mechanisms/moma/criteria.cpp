// MOMA criterion fields: the rods' pressure angle and reaction as cos²ε, the
// velocity ratio (largest singular value of dq/dP) and the condition number of
// dq/dP, from the closed-form inverse kinematics (docs/theory/level_sets.md, MOMA).
#include "mechanisms/moma/criteria.hpp"

#include <array>
#include <utility>

#include "criteria/support.hpp"

namespace pkmws::criteria {

namespace {

// Leg i, guide a_i, normal n_i = J a_i, w_i = P - R_i, branch b_i: the slider
// sits at p_i = a_i.w_i + b_i r_i with r_i = sqrt(l_i² - (n_i.w_i)²)
// ([Vasilic] eq. 5-6 written with |w|² = (a.w)² + (n.w)², docs/theory/moma.md),
// so the rod vector is P - S_i = (n_i.w_i) n_i - b_i r_i a_i. Differentiating
// eq. 3 gives dp_i = (P - S_i).dP / ((P - S_i).a_i) (docs/theory/moma.md,
// Jacobians): row i of dq/dP is m_i = a_i - b_i c_i n_i with c_i = (n_i.w_i) / r_i.
struct MomaTransmission {
  std::array<Point, 2> ref, a, n;
  std::array<double, 2> l, b, stroke_lo, stroke_hi;

  explicit MomaTransmission(const mechanisms::Moma& m) {
    for (int i = 0; i < 2; ++i) {
      const auto& leg = m.legs()[static_cast<std::size_t>(i)];
      const std::size_t k = static_cast<std::size_t>(i);
      ref[k] = leg.reference;
      a[k] = m.guide_direction(i);
      n[k] = {-a[k].y, a[k].x};
      l[k] = leg.rod_length;
      b[k] = leg.branch;
      stroke_lo[k] = leg.stroke_min;
      stroke_hi[k] = leg.stroke_max;
    }
  }
  template <class T> struct Leg {
    T along, across, r2;  // a.w, n.w, l² - (n.w)²
  };
  template <class T> Leg<T> leg(std::size_t i, const T& x, const T& y) const {
    using certified::sqr;
    using S = certified::scalar_t<T>;
    const T wx = x - ref[i].x, wy = y - ref[i].y;
    Leg<T> g;
    g.along = S(a[i].x) * wx + S(a[i].y) * wy;
    g.across = S(n[i].x) * wx + S(n[i].y) * wy;
    g.r2 = (S(l[i]) - g.across) * (S(l[i]) + g.across);
    return g;
  }
  // The rod vectors u_i = P - S_i (x parts, y parts).
  template <class T> std::pair<std::array<T, 2>, std::array<T, 2>> rods(const T& x, const T& y) const {
    using certified::max;
    using certified::sqrt;
    using std::sqrt;
    std::array<T, 2> ux, uy;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<T> g = leg(i, x, y);
      const T r = sqrt(max(g.r2, 0.0));
      ux[i] = g.across * n[i].x - b[i] * (r * a[i].x);
      uy[i] = g.across * n[i].y - b[i] * (r * a[i].y);
    }
    return {ux, uy};
  }
  double eps_scale() const { return l[0] * l[1]; }  // sin ε = singular_det / (l_1 l_2)
  // cos ε = (P - S_1).(P - S_2) / (l_1 l_2).
  template <class T> T cos_eps(const T& x, const T& y) const {
    using S = certified::scalar_t<T>;
    const auto [ux, uy] = rods(x, y);
    return (ux[0] * ux[1] + uy[0] * uy[1]) / (S(l[0]) * S(l[1]));
  }
  // det A = u_1 x u_2 of the rod vectors (derived from [Vasilic] eq. 3-6 as
  // cos_eps): zero where the rods are aligned (type 2).
  template <class T> T singular_det(const T& x, const T& y) const {
    const auto [ux, uy] = rods(x, y);
    return ux[0] * uy[1] - uy[0] * ux[1];
  }
  // Rows m_i = a_i - b_i c_i n_i of dq/dP, c_i = across_i / r_i: as
  // (r_i a_i - b_i across_i n_i) / r_i (r_i -> 0 at a rod's type-1 singularity).
  template <class T> Rows2<T> rows(const T& x, const T& y) const {
    using certified::max;
    using certified::sqrt;
    using std::sqrt;
    std::array<T, 2> mx, my, d;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<T> g = leg(i, x, y);
      d[i] = sqrt(max(g.r2, 0.0));
      mx[i] = a[i].x * d[i] - b[i] * (g.across * n[i].x);
      my[i] = a[i].y * d[i] - b[i] * (g.across * n[i].y);
    }
    return {mx[0], my[0], mx[1], my[1], d[0], d[1]};
  }
  // Smooth where both rods are strictly off the guides' normals (r_i > 0).
  CellState domain(const Box& box) const {
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<Interval> g = leg(i, x, y);
      if (g.r2.hi < 0.0) return CellState::outside;
      inside = inside && g.r2.lo > 0.0;
    }
    return inside ? CellState::inside : CellState::undecided;
  }
  // Box ⊆ workspace: both rods reach and both sliders are within their strokes.
  CellState within(const Box& box) const {
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<Interval> g = leg(i, x, y);
      if (g.r2.hi < 0.0) return CellState::outside;
      const Interval p = g.along + b[i] * certified::sqrt(certified::max(g.r2, 0.0));
      if (p.hi < stroke_lo[i] || p.lo > stroke_hi[i]) return CellState::outside;
      inside = inside && g.r2.lo > 0.0 && p.lo >= stroke_lo[i] && p.hi <= stroke_hi[i];
    }
    return inside ? CellState::inside : CellState::undecided;
  }
};

}  // namespace

CriterionField moma_pressure_angle(const mechanisms::Moma& m) {
  return point_platform_field(MomaTransmission(m), m, "moma", "pressure_angle");
}
CriterionField moma_reaction(const mechanisms::Moma& m, double force_N) {
  return point_platform_field(MomaTransmission(m), m, "moma", "reaction", force_N);
}
CriterionField moma_velocity_ratio(const mechanisms::Moma& m) {
  return point_platform_field(MomaTransmission(m), m, "moma", "velocity_ratio");
}
CriterionField moma_condition_number(const mechanisms::Moma& m) {
  return point_platform_field(MomaTransmission(m), m, "moma", "condition_number");
}

std::shared_ptr<const CriterionFields> moma_fields(const mechanisms::Moma& mechanism) {
  return std::make_shared<PointPlatformFields<MomaTransmission>>(MomaTransmission(mechanism), &mechanism, "moma");
}

}  // namespace pkmws::criteria
