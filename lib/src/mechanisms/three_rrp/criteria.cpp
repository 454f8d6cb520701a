// 3-RRP / 3-PRP criterion fields at the file orientation ([Briot]'s planar
// method on [Mitsi]'s chains; docs/theory/level_sets.md): pressure angles and
// reactions from the twists with one actuator free (columns of A⁻¹), the
// velocity ratio and condition number of the homogenised dq/dx' = B⁻¹A, and
// the assembly-mode constraint.
#include "mechanisms/three_rrp/criteria.hpp"

#include "criteria/singular3.hpp"
#include "criteria/support.hpp"

namespace pkmws::criteria {

namespace {

// Chain i at orientation φ: side line i is {X : n_i . (X - P - c_i) = 0} with
// n_i = R(φ) n'_i, c_i = R(φ) B'_i, so A_i's level on it,
// ℓ_i = n_i . (P + c_i - O_i) = n_i . P + k_i, is linear in P
// (ThreeRrp::inverse_chain). A_i ([Mitsi] eq. 1-2 put on side line i; three_rrp.hpp):
//   3-PRP: A_i = O_i + (ℓ_i / (n_i . d_i)) d_i,                 B_ii = n_i . d_i;
//   3-RRP: A_i = O_i + ℓ_i n_i + σ_i w_i J n_i, w_i = sqrt(r_i² - ℓ_i²),
//          B_ii = r_i u(φ_i) x n_i = -σ_i w_i (working mode σ_i).
// Rows of A ([Briot]'s wrenches, |n_i| = 1): a_i = [n_i, (A_i - P) x n_i].
struct ThreeRrpChains {
  bool crank = true;
  std::array<Point, 3> n, base, dir;
  std::array<double, 3> k{}, r{}, nd{};
  std::array<std::optional<std::array<double, 2>>, 3> limits;
  static constexpr double sigma = 1.0;  // the working mode "+++" (evaluate()'s first answer)
  // 0 = R_i,max, 1 = |v_A_i|², 2 = -det_sign det A, 3 = σ_max² of dq/dx', 4 = -σ_min²/σ_max².
  int what = 0;
  int leg = 0;
  double det_sign = 1.0, f = 0.0, m = 0.0, length = 1.0;

  ThreeRrpChains(const mechanisms::ThreeRrp& mech, int leg_index, int quantity)
      : crank(mech.drive() == mechanisms::ThreeRrpDrive::crank), what(quantity), leg(leg_index) {
    const double phi = mech.orientation(), cp = std::cos(phi), sp = std::sin(phi);
    const auto rot = [&](Point v) { return Point{cp * v.x - sp * v.y, sp * v.x + cp * v.y}; };
    for (std::size_t i = 0; i < 3; ++i) {
      const mechanisms::ThreeRrpChain& ch = mech.chains()[i];
      n[i] = rot(mech.triangle().normal[i]);
      base[i] = ch.base;
      const Point c = rot(mech.triangle().vertices[i]);
      k[i] = n[i].x * (c.x - ch.base.x) + n[i].y * (c.y - ch.base.y);
      r[i] = ch.crank_length;
      dir[i] = {std::cos(ch.direction), std::sin(ch.direction)};
      nd[i] = n[i].x * dir[i].x + n[i].y * dir[i].y;
      limits[i] = ch.limits;
    }
  }
  // What fixes jacobian_cubic (the roots' cache key; `length` may be set later).
  detail::CubicKey cubic_key() const {
    detail::CubicKey key{};
    for (std::size_t i = 0; i < 3; ++i) {
      const std::array<double, 8> v{n[i].x, n[i].y, base[i].x, base[i].y, dir[i].x, dir[i].y, k[i], r[i]};
      std::copy(v.begin(), v.end(), key.begin() + static_cast<std::ptrdiff_t>(8 * i));
    }
    key[24] = nd[0];
    key[25] = nd[1];
    key[26] = nd[2];
    key[27] = length;
    key[28] = crank ? 1.0 : 0.0;
    return key;
  }

  template <class T> struct Parts {
    T a[3][3];
    T weight[3];  // B_ii²
    T ax[3], ay[3];  // A_i - P
  };
  template <class T> Parts<T> parts(const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    Parts<T> p;
    for (std::size_t i = 0; i < 3; ++i) {
      const T level = n[i].x * x + n[i].y * y + T(k[i]);
      if (crank) {
        const T w2 = T(r[i] * r[i]) - sqr(level);
        const T w = sqrt(max(w2, 0.0));
        p.ax[i] = (T(base[i].x) - x) + level * n[i].x - sigma * n[i].y * w;
        p.ay[i] = (T(base[i].y) - y) + level * n[i].y + sigma * n[i].x * w;
        p.weight[i] = w2;
      } else {
        const T s = level / nd[i];
        p.ax[i] = (T(base[i].x) - x) + s * dir[i].x;
        p.ay[i] = (T(base[i].y) - y) + s * dir[i].y;
        p.weight[i] = T(nd[i] * nd[i]);
      }
      p.a[i][0] = T(n[i].x);
      p.a[i][1] = T(n[i].y);
      p.a[i][2] = p.ax[i] * n[i].y - p.ay[i] * n[i].x;  // (A_i - P) x n_i
    }
    return p;
  }
  // p(μ) = det(μ I - MᵀM), M = dq/dx' = B⁻¹A with the angular column divided by L
  // (row i of dq/dx is a_i / B_ii; criteria/singular3.hpp).
  template <class T> detail::Cubic<T> jacobian_cubic(const T& x, const T& y) const {
    Parts<T> p = parts(x, y);
    for (auto& row : p.a) row[2] = row[2] / length;
    if (!crank) {
      // 3-PRP: B_ii = n_i . d_i is constant, so the rows are scaled once and
      // the invariants need no division (of jets, the costly part).
      for (std::size_t i = 0; i < 3; ++i) {
        const double b = std::abs(nd[i]);
        for (T& entry : p.a[i]) entry = entry / b;
      }
      return detail::gram_invariants(p.a);
    }
    return detail::gram_invariants(p.a, p.weight);
  }
  template <class T> T eval(const T& x, const T& y) const {
    using certified::abs;
    using certified::sqr;
    using certified::sqrt;
    using std::abs;
    using std::sqrt;
    if (what >= 3) {
      const auto cubic = [this](const auto& u, const auto& v) { return jacobian_cubic(u, v); };
      const detail::CubicKey key = cubic_key();
      const auto [l1, l3] = detail::cubic_roots_field(cubic, x, y, what == 4, &key);
      if (what == 3) return l1;
      return -(l3 / l1);
    }
    const Parts<T> p = parts(x, y);
    // Column i of A⁻¹ is (a_j x a_k) / det ((i, j, k) cyclic): the twist with
    // only actuator i free ([Briot]), t_i = (v_P, ω).
    const auto i = static_cast<std::size_t>(leg);
    const std::size_t j = (i + 1) % 3, kk = (i + 2) % 3;
    const T w0 = p.a[j][1] * p.a[kk][2] - p.a[j][2] * p.a[kk][1];
    const T w1 = p.a[j][2] * p.a[kk][0] - p.a[j][0] * p.a[kk][2];
    const T w2 = p.a[j][0] * p.a[kk][1] - p.a[j][1] * p.a[kk][0];
    const T det = p.a[i][0] * w0 + p.a[i][1] * w1 + p.a[i][2] * w2;
    if (what == 2) return -det_sign * det;
    if (what == 1) {
      // v_A_i = v_P + ω J (A_i - P); [Briot]: cos α_i = |n_i . v_A_i| / |v_A_i| = 1 / |v_A_i|.
      const T vx = w0 - w2 * p.ay[i], vy = w1 + w2 * p.ax[i];
      return (sqr(vx) + sqr(vy)) / sqr(det);
    }
    // docs/theory/three_dof.md: R_i,max = f |v_P,i| + |m| |ω_i|.
    return (f * sqrt(sqr(w0) + sqr(w1)) + m * abs(w2)) / abs(det);
  }
  // ScalarField::side: the conditioning fields' sign tests (criteria/singular3.hpp).
  CellState side(const Box& b, double level) const {
    if (what < 3) return CellState::undecided;
    return detail::conditioning_side(*this, Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y), what == 4, level);
  }
  // ScalarField::excluded: for the conditioning fields, the cranks' reach
  // alone (their smoothness test, the roots' enclosures, never says `outside`).
  bool excluded(const Box& b) const {
    if (what < 3) return domain(b) == CellState::outside;
    if (!crank) return false;
    const Parts<Interval> p = parts(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y));
    for (const Interval& w2 : p.weight) {
      if (w2.hi <= 0.0) return true;
    }
    return false;
  }
  // Smooth: cranks off their type-1 singularity (w_i > 0), and det A ≠ 0
  // (pressure angle, reaction) or the roots used simple (velocity ratio, κ).
  CellState domain(const Box& b) const {
    const Interval x(b.min.x, b.max.x), y(b.min.y, b.max.y);
    const Parts<Interval> p = parts(x, y);
    if (crank) {
      for (const Interval& w2 : p.weight) {
        if (w2.hi <= 0.0) return CellState::outside;
        if (w2.lo <= 0.0) return CellState::undecided;
      }
    }
    if (what == 2) return CellState::inside;
    if (what >= 3) {
      const auto cubic = [this](const auto& u, const auto& v) { return jacobian_cubic(u, v); };
      const detail::CubicKey key = cubic_key();
      const bool simple = detail::simple_roots_over_box(cubic, x, y, what == 4, &key);
      return simple ? CellState::inside : CellState::undecided;
    }
    ThreeRrpChains d = *this;
    d.what = 2;
    d.det_sign = 1.0;
    return d.eval<Interval>(x, y).contains_zero() ? CellState::undecided : CellState::inside;
  }
  // Box ⊆ workspace: every chain's A_i reaches side line i within its joint range.
  CellState within(const Box& b) const {
    const Interval x(b.min.x, b.max.x), y(b.min.y, b.max.y);
    bool inside = true;
    for (std::size_t i = 0; i < 3; ++i) {
      const Interval level = Interval(n[i].x) * x + Interval(n[i].y) * y + Interval(k[i]);
      if (crank) {
        if (level.lo > r[i] || level.hi < -r[i]) return CellState::outside;
        // A crank with limits: its angle over the box is not enclosed here (exact clipping decides).
        inside = inside && level.lo > -r[i] && level.hi < r[i] && !limits[i];
      } else if (limits[i]) {
        const Interval s = level / Interval(nd[i]);
        if (s.hi < (*limits[i])[0] || s.lo > (*limits[i])[1]) return CellState::outside;
        inside = inside && s.lo >= (*limits[i])[0] && s.hi <= (*limits[i])[1];
      }
    }
    return inside ? CellState::inside : CellState::undecided;
  }
};

// The criterion as `pkmws eval` gives it in the fields' working mode (its first answer).
template <class Pick>
std::function<double(Point)> evaluated(const mechanisms::ThreeRrp& mechanism, mechanisms::Criteria criteria, Pick pick) {
  const mechanisms::ThreeRrp* m = &mechanism;
  return [m, criteria, pick](Point p) {
    const auto e = m->evaluate({p.x, p.y, m->orientation()}, criteria);
    return !e.empty() && e.front().reachable ? pick(e.front()) : nan;
  };
}

CriterionField make(const ThreeRrpChains& impl, const mechanisms::ThreeRrp& mechanism, std::string name,
                    std::string key) {
  CriterionField c;
  c.name = std::move(name);
  c.key = std::string(mechanism.kind()) + "." + key;
  c.surrogate = std::make_shared<certified::TemplateField<ThreeRrpChains>>(impl);
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

double length_of(const mechanisms::ThreeRrp& mechanism, const mechanisms::Criteria& criteria) {
  return criteria.characteristic_length.value_or(mechanism.characteristic_length());
}

}  // namespace

CriterionField three_rrp_pressure_angle(const mechanisms::ThreeRrp& mechanism, int leg) {
  if (leg < 0 || leg > 2) throw std::invalid_argument("three_rrp_pressure_angle: leg must be 0, 1 or 2");
  CriterionField c = make(ThreeRrpChains(mechanism, leg, 1), mechanism, "pressure_angle", "va2_" + std::to_string(leg));
  c.unit = "deg";
  c.threshold_max = 90.0;
  // [Briot]: cos α_i = 1 / |v_A_i|  =>  α_i <= α  <=>  |v_A_i|² <= 1 / cos²α.
  c.level = [](double alpha_deg) {
    const double ca = std::cos(std::clamp(alpha_deg, 0.0, 90.0) * deg);
    return ca > 0.0 ? 1.0 / (ca * ca) : std::numeric_limits<double>::infinity();
  };
  const auto i = static_cast<std::size_t>(leg);
  c.value = evaluated(mechanism, {}, [i](const mechanisms::Evaluation& e) { return e.pressure_angle_deg.at(i); });
  return c;
}

CriterionField three_rrp_reaction(const mechanisms::ThreeRrp& mechanism, const mechanisms::Load& load, int leg) {
  if (leg < 0 || leg > 2) throw std::invalid_argument("three_rrp_reaction: leg must be 0, 1 or 2");
  ThreeRrpChains impl(mechanism, leg, 0);
  impl.f = load.force_N;
  impl.m = std::abs(load.moment_Nm);
  CriterionField c = make(impl, mechanism, "reaction", "reaction" + std::to_string(leg));
  c.unit = "N";
  c.level = [](double r) { return r; };
  mechanisms::Criteria with_load;
  with_load.load = load;
  const auto i = static_cast<std::size_t>(leg);
  c.value = evaluated(mechanism, with_load, [i](const mechanisms::Evaluation& e) { return e.reactions_N.at(i); });
  return c;
}

CriterionField three_rrp_velocity_ratio(const mechanisms::ThreeRrp& mechanism, const mechanisms::Criteria& criteria) {
  ThreeRrpChains impl(mechanism, 0, 3);
  impl.length = length_of(mechanism, criteria);
  CriterionField c = make(impl, mechanism, "velocity_ratio", "vratio");
  c.characteristic_length = impl.length;
  c.unit = "|dq|/|dx'|";
  c.level = [](double t) { return t * t; };
  mechanisms::Criteria with_length;
  with_length.characteristic_length = impl.length;
  c.value = evaluated(mechanism, with_length,
                      [](const mechanisms::Evaluation& e) { return e.velocity_ratio ? *e.velocity_ratio : nan; });
  return c;
}

CriterionField three_rrp_condition_number(const mechanisms::ThreeRrp& mechanism, const mechanisms::Criteria& criteria) {
  ThreeRrpChains impl(mechanism, 0, 4);
  impl.length = length_of(mechanism, criteria);
  CriterionField c = make(impl, mechanism, "condition_number", "kappa");
  c.characteristic_length = impl.length;
  c.unit = "";
  c.threshold_min = 1.0;
  // κ <= t  <=>  σ_min² / σ_max² >= 1 / t².
  c.level = [](double t) { return t >= 1.0 ? -1.0 / (t * t) : -std::numeric_limits<double>::infinity(); };
  mechanisms::Criteria with_length;
  with_length.characteristic_length = impl.length;
  c.value = evaluated(mechanism, with_length, [](const mechanisms::Evaluation& e) { return e.condition_number; });
  return c;
}

namespace {

// Capability criteria::CriterionFields of the 3-RRP / 3-PRP at the file orientation.
class ThreeRrpFields final : public CriterionFields {
 public:
  explicit ThreeRrpFields(const mechanisms::ThreeRrp* m) : m_(m) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& reaction_legs) const override {
    const mechanisms::ThreeRrp& mech = *m_;
    std::vector<CriterionField> out;
    if (name == "velocity_ratio") out.push_back(three_rrp_velocity_ratio(mech, criteria));
    if (name == "condition_number") out.push_back(three_rrp_condition_number(mech, criteria));
    if (out.empty()) {
      std::vector<int> legs = reaction_legs;
      if (legs.empty()) legs = {1, 2, 3};
      for (int leg : legs) {
        if (name == "reaction") {
          if (!criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
          out.push_back(three_rrp_reaction(mech, *criteria.load, leg - 1));
        } else {
          out.push_back(three_rrp_pressure_angle(mech, leg - 1));
        }
      }
    }
    // The platform stays in the assembly mode of the workspace box's centre
    // (it cannot cross the type-2 singularity, det A = 0), as for the 3-RPR.
    const geometry::Box b = mech.bounds();
    ThreeRrpChains assembly(mech, 0, 2);
    const Point centre{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)};
    const double d = assembly.eval<double>(centre.x, centre.y);
    if (!(d != 0.0) || !std::isfinite(d)) {
      throw std::invalid_argument(std::string(mech.kind()) + " level sets: the centre of the workspace box is type-2 "
                                  "singular (no assembly mode to keep)");
    }
    assembly.det_sign = -d > 0.0 ? 1.0 : -1.0;  // eval() gave -det at det_sign = 1
    CriterionField c = make(assembly, mech, "assembly_mode", "assembly");
    c.level = [](double) { return 0.0; };
    c.value = [assembly](Point p) { return assembly.eval<double>(p.x, p.y); };
    out.push_back(std::move(c));
    return out;
  }
  // det A of the working mode +++ at the file's orientation ([Briot]'s rows
  // a_i = [n_i, (A_i - P) x n_i]); zero on the type-2 singular curve.
  CriterionField singular_determinant(const mechanisms::Criteria& /*criteria*/) const override {
    const mechanisms::ThreeRrp& mech = *m_;
    ThreeRrpChains impl(mech, 0, 2);
    impl.det_sign = 1.0;
    CriterionField c = make(impl, mech, "singularity_distance", "det");
    c.unit = "length";
    c.level = [](double) { return 0.0; };
    c.value = [impl](Point p) { return impl.eval<double>(p.x, p.y); };
    return c;
  }

 private:
  const mechanisms::ThreeRrp* m_;
};

}  // namespace

std::shared_ptr<const CriterionFields> three_rrp_fields(const mechanisms::ThreeRrp& mechanism) {
  return std::make_shared<ThreeRrpFields>(&mechanism);
}

}  // namespace pkmws::criteria
