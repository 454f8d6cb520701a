// MOMA criterion fields: the rods' pressure angle and reaction as cos²ε, the
// velocity ratio (largest singular value of dq/dP) and the condition number of
// dq/dP, from the closed-form inverse kinematics (docs/theory/level_sets.md, MOMA).
#include "mechanisms/moma/criteria.hpp"

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
  enum class What { cos2eps, ratio2, kappa };  // cos²ε, σ_max² of dq/dP, -(det / F)² of dq/dP
  std::array<Point, 2> ref, a, n;
  std::array<double, 2> l, b, stroke_lo, stroke_hi;
  What what = What::cos2eps;

  MomaTransmission(const mechanisms::Moma& m, What w) : what(w) {
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
    const T wx = x - ref[i].x, wy = y - ref[i].y;
    Leg<T> g;
    g.along = T(a[i].x) * wx + T(a[i].y) * wy;
    g.across = T(n[i].x) * wx + T(n[i].y) * wy;
    g.r2 = (T(l[i]) - g.across) * (T(l[i]) + g.across);
    return g;
  }
  // cos ε = (P - S_1).(P - S_2) / (l_1 l_2).
  template <class T> T cos_eps(const T& x, const T& y) const {
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
    return (ux[0] * ux[1] + uy[0] * uy[1]) / (T(l[0]) * T(l[1]));
  }
  // Rows m_i = a_i - b_i c_i n_i of dq/dP.
  template <class T> Rows2<T> rows(const T& x, const T& y) const {
    using certified::max;
    using certified::sqrt;
    using std::sqrt;
    std::array<T, 2> mx, my;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<T> g = leg(i, x, y);
      const T c = g.across / sqrt(max(g.r2, 0.0));
      mx[i] = a[i].x - b[i] * (c * n[i].x);
      my[i] = a[i].y - b[i] * (c * n[i].y);
    }
    return {mx[0], my[0], mx[1], my[1]};
  }
  template <class T> T eval(const T& x, const T& y) const {
    if (what == What::ratio2) return sigma_max2(rows(x, y));
    if (what == What::kappa) return kappa_surrogate(rows(x, y));
    return certified::sqr(cos_eps(x, y));
  }
  // Smooth where both rods are strictly off the guides' normals (r_i > 0);
  // σ_max² also needs distinct singular values.
  CellState domain(const Box& box) const {
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Leg<Interval> g = leg(i, x, y);
      if (g.r2.hi < 0.0) return CellState::outside;
      inside = inside && g.r2.lo > 0.0;
    }
    if (inside && what == What::ratio2 && !detail::distinct_singular_values(rows(x, y))) {
      return CellState::undecided;  // near an isotropic point
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

// The file's working mode at p: the evaluation the fields describe (NaN
// outside the workspace).
const mechanisms::Evaluation* own_mode(const std::vector<mechanisms::Evaluation>& e) {
  return !e.empty() && e.front().reachable ? &e.front() : nullptr;
}

}  // namespace

CriterionField moma_pressure_angle(const mechanisms::Moma& mechanism) {
  const MomaTransmission impl(mechanism, MomaTransmission::What::cos2eps);
  CriterionField c;
  c.name = "pressure_angle";
  c.unit = "deg";
  c.threshold_max = 90.0;
  c.key = "moma.cos2eps";
  c.surrogate = std::make_shared<certified::TemplateField<MomaTransmission>>(impl);
  // α = acos|sin ε| <= α_max  <=>  cos²ε <= sin²α_max ([Briot], as for the five-bar).
  c.level = [](double alpha_deg) {
    const double s = std::sin(std::clamp(alpha_deg, 0.0, 90.0) * deg);
    return s * s;
  };
  const mechanisms::Moma* m = &mechanism;
  c.value = [m](Point p) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, {});
    const auto* own = own_mode(e);
    return own ? own->pressure_angle_deg.at(0) : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField moma_reaction(const mechanisms::Moma& mechanism, double force_N) {
  CriterionField c = moma_pressure_angle(mechanism);
  c.name = "reaction";
  c.unit = "N";
  c.threshold_max = std::numeric_limits<double>::infinity();
  // R = f / |sin ε| <= R_max  <=>  cos²ε <= 1 - (f / R_max)² (two-force rods, as the five-bar's distal links).
  c.level = [force_N](double r_max) {
    if (!(r_max > 0.0)) return -1.0;
    const double q = force_N / r_max;
    return q >= 1.0 ? (q == 1.0 ? 0.0 : -1.0) : 1.0 - q * q;
  };
  const mechanisms::Moma* m = &mechanism;
  c.value = [m, force_N](Point p) {
    mechanisms::Criteria with_load;
    with_load.load = mechanisms::Load{force_N, 0.0};
    const auto e = m->evaluate({p.x, p.y, 0.0}, with_load);
    const auto* own = own_mode(e);
    return own && !own->reactions_N.empty() ? own->reactions_N.at(0) : nan;
  };
  return c;
}

CriterionField moma_velocity_ratio(const mechanisms::Moma& mechanism) {
  const MomaTransmission impl(mechanism, MomaTransmission::What::ratio2);
  CriterionField c;
  c.name = "velocity_ratio";
  c.unit = "|dq|/|dP|";
  c.key = "moma.vratio";
  c.surrogate = std::make_shared<certified::TemplateField<MomaTransmission>>(impl);
  c.level = [](double ratio) { return ratio * ratio; };  // σ_max <= t  <=>  σ_max² <= t²
  const mechanisms::Moma* m = &mechanism;
  c.value = [m](Point p) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, {});
    const auto* own = own_mode(e);
    return own && own->velocity_ratio ? *own->velocity_ratio : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField moma_condition_number(const mechanisms::Moma& mechanism) {
  const MomaTransmission impl(mechanism, MomaTransmission::What::kappa);
  CriterionField c;
  c.name = "condition_number";
  c.unit = "";  // dimensionless
  c.key = "moma.kappa";
  c.threshold_min = 1.0;
  c.surrogate = std::make_shared<certified::TemplateField<MomaTransmission>>(impl);
  c.level = kappa_level;
  const mechanisms::Moma* m = &mechanism;
  c.value = [m](Point p) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, {});
    const auto* own = own_mode(e);
    return own ? own->condition_number : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

namespace {

// Capability criteria::CriterionFields of the MOMA.
class MomaFields final : public CriterionFields {
 public:
  explicit MomaFields(const mechanisms::Moma* m) : m_(m) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& /*reaction_legs*/) const override {
    if (name == "pressure_angle") return {moma_pressure_angle(*m_)};
    if (name == "velocity_ratio") return {moma_velocity_ratio(*m_)};
    if (name == "condition_number") return {moma_condition_number(*m_)};
    if (!criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
    return {moma_reaction(*m_, criteria.load->force_N)};
  }

 private:
  const mechanisms::Moma* m_;
};

}  // namespace

std::shared_ptr<const CriterionFields> moma_fields(const mechanisms::Moma& mechanism) {
  return std::make_shared<MomaFields>(&mechanism);
}

}  // namespace pkmws::criteria
