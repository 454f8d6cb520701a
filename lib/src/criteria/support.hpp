// What the criterion fields of several mechanisms share (private; included by
// the modules' criteria.cpp only).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/certified/interval.hpp"
#include "pkmws/certified/template_field.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/mechanisms/mechanism.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::criteria::detail {

inline constexpr double pi = std::numbers::pi;
inline constexpr double deg = pi / 180.0;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// |p - c|² over a box (tight: separable).
inline certified::Interval dist2(const geometry::Box& b, geometry::Point c) {
  return certified::sqr(certified::Interval(b.min.x, b.max.x) - certified::Interval(c.x)) +
         certified::sqr(certified::Interval(b.min.y, b.max.y) - certified::Interval(c.y));
}

// dq/dP of a two-actuator point platform, by rows m_i = (x_i, y_i) / d_i: a
// row that grows without bound at a leg's type-1 singularity is given as a
// bounded numerator over a denominator d_i -> 0 there (d_i = 1 otherwise).
template <class T> struct Rows2 {
  T x0, y0, x1, y1;
  T d0 = T(1.0), d1 = T(1.0);
  T n0() const { return x0 * x0 + y0 * y0; }  // |numerators|²
  T n1() const { return x1 * x1 + y1 * y1; }
  T cross() const { return x0 * y1 - y0 * x1; }
  T frobenius2() const { return n0() / (d0 * d0) + n1() / (d1 * d1); }  // F = σ_1² + σ_2²
  T det() const { return cross() / (d0 * d1); }                          // ± σ_1 σ_2
};

// σ_max² = (F + sqrt(F² - 4 det²)) / 2: the squared velocity ratio (worst
// direction); C² where the singular values differ (F² - 4 det² > 0).
template <class T> T sigma_max2(const Rows2<T>& m) {
  using certified::max;
  using certified::sqrt;
  using std::sqrt;
  const T f = m.frobenius2(), d = m.det();
  return 0.5 * (f + sqrt(max((f - 2.0 * d) * (f + 2.0 * d), 0.0)));
}

// The condition number κ = σ_1 / σ_2 >= 1 satisfies κ + 1/κ = F / |det|, so
// κ <= t  <=>  -(det / F)² <= -1 / (t + 1/t)²: a surrogate smooth wherever
// F > 0, also across type-2 singularities (det = 0, κ infinite).
// det / F = cross d0 d1 / (n0 d1² + n1 d0²): bounded also where a row is not,
// so boxes at a type-1 singularity (κ infinite, q -> 0) are decided.
template <class T> T kappa_surrogate(const Rows2<T>& m) {
  const T q = m.cross() * (m.d0 * m.d1) / (m.n0() * (m.d1 * m.d1) + m.n1() * (m.d0 * m.d0));
  return -(q * q);
}
inline double kappa_level(double t) {
  if (!(t >= 1.0)) return -std::numeric_limits<double>::infinity();  // empty: κ >= 1
  const double k = t + 1.0 / t;
  return -1.0 / (k * k);
}

// Whether the singular values of dq/dP differ over a box (σ_max² is C² there).
inline bool distinct_singular_values(const Rows2<certified::Interval>& m) {
  const certified::Interval f = m.frobenius2(), d = m.det();
  return ((f - 2.0 * d) * (f + 2.0 * d)).lo > 0.0;
}

}  // namespace pkmws::criteria::detail

namespace pkmws::criteria {

// The names every module's criterion fields use (their criteria.cpp only).
using certified::CellState;
using certified::Interval;
using certified::Jet;
using detail::deg;
using detail::dist2;
using detail::kappa_level;
using detail::kappa_surrogate;
using detail::Rows2;
using detail::sigma_max2;
using detail::nan;
using detail::pi;
using geometry::Box;
using geometry::Point;

// ---------------------------------------------------------------------------
// The criteria of a two-leg point platform (MOMA, five-bar): the pressure angle
// α = acos|sin ε| and the reaction f / |sin ε| from cos ε of the legs' last
// links (two-force members, [Briot]), the velocity ratio σ_max and the
// condition number of dq/dP from its rows. A Model gives
//   template <class T> T cos_eps(const T& x, const T& y) const;
//   template <class T> Rows2<T> rows(const T& x, const T& y) const;
//   CellState domain(const Box&) const;  // both legs off their type-1 singularity: C² there
//   CellState within(const Box&) const;  // box ⊆ the workspace
// The criteria's values come from the mechanism's own evaluation in the file's
// working mode (the first answer of evaluate()).
//   template <class T> T singular_det(const T& x, const T& y) const;  // u_1 x u_2 of the last links
//   double eps_scale() const;  // |u_1| |u_2|: sin ε = singular_det / eps_scale
// Surrogates: cos²ε, σ_max², κ's, det A, and the transmission limits' cos ε,
// -cos ε and -|det A| (sine_bound_fields).
template <class Model> struct PointPlatformField {
  enum class What { cos2eps, ratio2, kappa, det, coseps, negcoseps, negabssin };
  Model model;
  What what = What::cos2eps;
  template <class T> T eval(const T& x, const T& y) const {
    if (what == What::det) return model.singular_det(x, y);
    if (what == What::ratio2) return detail::sigma_max2(model.rows(x, y));
    if (what == What::kappa) return detail::kappa_surrogate(model.rows(x, y));
    if (what == What::coseps) return model.cos_eps(x, y);
    if (what == What::negcoseps) return -model.cos_eps(x, y);
    if (what == What::negabssin) {
      using certified::abs;
      using std::abs;
      return -abs(model.singular_det(x, y));
    }
    return certified::sqr(model.cos_eps(x, y));
  }
  // σ_max² also needs distinct singular values; |det A| is smooth only off det A = 0.
  certified::CellState domain(const geometry::Box& b) const {
    const certified::CellState d = model.domain(b);
    if (d == certified::CellState::inside && what == What::ratio2 &&
        !detail::distinct_singular_values(
            model.rows(certified::Interval(b.min.x, b.max.x), certified::Interval(b.min.y, b.max.y)))) {
      return certified::CellState::undecided;  // near an isotropic point
    }
    if (d == certified::CellState::inside && what == What::negabssin &&
        model.singular_det(certified::Interval(b.min.x, b.max.x), certified::Interval(b.min.y, b.max.y)).contains_zero()) {
      return certified::CellState::undecided;
    }
    return d;
  }
};

// The surrogate `what` of a point platform (or of its chart) as a ScalarField.
template <class Model>
std::shared_ptr<const certified::ScalarField> platform_surrogate(const Model& model,
                                                                 typename PointPlatformField<Model>::What what) {
  return std::make_shared<certified::TemplateField<PointPlatformField<Model>>>(PointPlatformField<Model>{model, what});
}

// The field of criterion `name` ("pressure_angle", "reaction" with the load's
// force, "velocity_ratio", "condition_number") of a point platform; `kind`
// prefixes its key.
template <class Model>
CriterionField point_platform_field(const Model& model, const mechanisms::Mechanism& mechanism, const std::string& kind,
                                    const std::string& name, double force_N = 0.0) {
  using What = typename PointPlatformField<Model>::What;
  const What what = name == "velocity_ratio"     ? What::ratio2
                    : name == "condition_number" ? What::kappa
                                                 : What::cos2eps;
  CriterionField c;
  c.name = name;
  c.surrogate = platform_surrogate(model, what);
  c.within_test = [model](const geometry::Box& b) { return model.within(b); };
  mechanisms::Criteria with_load;
  if (name == "reaction") with_load.load = mechanisms::Load{force_N, 0.0};
  const mechanisms::Mechanism* m = &mechanism;
  // The criterion in the file's working mode (NaN outside the workspace).
  const auto at = [m, with_load](geometry::Point p, auto pick) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, with_load);
    return !e.empty() && e.front().reachable ? pick(e.front()) : detail::nan;
  };
  if (what == What::ratio2) {
    c.unit = "|dq|/|dP|";
    c.key = kind + ".vratio";
    c.level = [](double ratio) { return ratio * ratio; };  // σ_max <= t  <=>  σ_max² <= t²
    c.value = [at](geometry::Point p) {
      return at(p, [](const mechanisms::Evaluation& e) { return e.velocity_ratio ? *e.velocity_ratio : detail::nan; });
    };
  } else if (what == What::kappa) {
    c.unit = "";  // dimensionless
    c.key = kind + ".kappa";
    c.threshold_min = 1.0;
    c.level = detail::kappa_level;
    // κ from the surrogate s = −(det/F)², κ + 1/κ = F/|det| (docs/theory/level_sets.md),
    // in the working mode's workspace: the evaluation's κ without every mode's
    // joints, SVDs and reasons (the GCI samples it once per grid cell).
    c.value = [m, s = c.surrogate](geometry::Point p) {
      if (!m->reachable({p.x, p.y, 0.0})) return detail::nan;
      const double v = s->value(p);
      if (!(v <= 0.0)) return detail::nan;
      if (v == 0.0) return std::numeric_limits<double>::infinity();
      const double r = 1.0 / std::sqrt(-v);  // κ + 1/κ >= 2
      return r <= 2.0 ? 1.0 : 0.5 * (r + std::sqrt((r - 2.0) * (r + 2.0)));
    };
  } else if (name == "reaction") {
    c.unit = "N";
    c.key = kind + ".cos2eps";
    // R = f / |sin ε| <= R_max  <=>  cos²ε <= 1 - (f / R_max)² (docs/theory/five_bar.md).
    c.level = [force_N](double r_max) {
      if (!(r_max > 0.0)) return -1.0;
      const double q = force_N / r_max;
      return q >= 1.0 ? (q == 1.0 ? 0.0 : -1.0) : 1.0 - q * q;
    };
    c.value = [at](geometry::Point p) {
      return at(p, [](const mechanisms::Evaluation& e) { return e.reactions_N.empty() ? detail::nan : e.reactions_N[0]; });
    };
  } else {
    c.unit = "deg";
    c.key = kind + ".cos2eps";
    c.threshold_max = 90.0;
    // α <= α_max  <=>  |cos ε| <= sin α_max  <=>  cos²ε <= sin²α_max ([Briot]).
    c.level = [](double alpha_deg) {
      const double s = std::sin(std::clamp(alpha_deg, 0.0, 90.0) * detail::deg);
      return s * s;
    };
    c.value = [at](geometry::Point p) {
      return at(p, [](const mechanisms::Evaluation& e) { return e.pressure_angle_deg.at(0); });
    };
  }
  return c;
}

// The type-2 singular determinant of a point platform: det A = u_1 x u_2, A's
// rows the last links' directions u_i (two-force members, [Briot]); zero where
// the links are aligned (docs/theory/level_sets.md, distance to the type-2 singularity).
// A field whose level is 0 whatever the threshold (a determinant's zero set,
// an assembly-mode sign), from an Impl as TemplateField takes it.
template <class Impl>
CriterionField zero_level_field(const Impl& impl, std::string name, std::string unit, std::string key,
                                certified::WithinTest within) {
  CriterionField c;
  c.name = std::move(name);
  c.unit = std::move(unit);
  c.key = std::move(key);
  c.surrogate = std::make_shared<certified::TemplateField<Impl>>(impl);
  c.level = [](double) { return 0.0; };
  c.value = [impl](geometry::Point p) { return impl.template eval<double>(p.x, p.y); };
  c.within_test = std::move(within);
  return c;
}

template <class Model>
CriterionField point_platform_singular(const Model& model, const std::string& kind) {
  using What = typename PointPlatformField<Model>::What;
  return zero_level_field(PointPlatformField<Model>{model, What::det}, "singularity_distance", "length", kind + ".det",
                          [model](const geometry::Box& b) { return model.within(b); });
}

// The surrogates of a point platform's criteria in a chart, by key (the keys
// point_platform_field gives: kind + ".cos2eps", ".vratio", ".kappa", ".det"),
// from a chart Model written like a plane's.
template <class ChartModel>
std::function<std::shared_ptr<const certified::ScalarField>(const std::string&)> point_platform_chart_fields(
    ChartModel model, std::string kind) {
  return [model = std::move(model), kind = std::move(kind)](const std::string& key) -> std::shared_ptr<const certified::ScalarField> {
    using What = typename PointPlatformField<ChartModel>::What;
    const std::pair<const char*, What> suffixes[] = {
        {".cos2eps", What::cos2eps}, {".vratio", What::ratio2}, {".kappa", What::kappa}, {".det", What::det},
        {".coseps", What::coseps},   {".negcoseps", What::negcoseps}, {".negabssin", What::negabssin}};
    for (const auto& [suffix, what] : suffixes) {
      if (key == kind + suffix) {
        return platform_surrogate(model, what);
      }
    }
    return nullptr;
  };
}

// A transmission limit |sin ε| >= q (the pressure angle α <= t: q = cos t,
// [Briot]; the reaction f / |sin ε| <= R: q = f / R) as the better
// conditioned of two smooth forms of the same set, in place of the cos²ε of
// `base` (docs/theory/level_sets.md, "Transmission limits"): on the curve
// |sin ε| = q, ∇cos ε = -sin ε ∇ε has the factor q and ∇sin ε = cos ε ∇ε the
// factor √(1 - q²), while cos²ε's gradient 2 |sin ε cos ε| |∇ε| is small at
// both ends (cos²ε has a maximum on the singularity, a minimum where ε = 90°):
//  - q >= 1/√2 (α <= 45°): cos ε <= √(1 - q²) and -cos ε <= √(1 - q²);
//  - q < 1/√2: -|det A| <= -q l_1 l_2 (det A = l_1 l_2 sin ε, smooth off the
//    singularity det A = 0, which the curve keeps away from).
// `threshold` (the limit) picks the form; the levels hold for any threshold.
template <class Model>
std::vector<CriterionField> sine_bound_fields(const Model& model, CriterionField base, const std::string& kind,
                                              double threshold, std::function<double(double)> q_of) {
  using What = typename PointPlatformField<Model>::What;
  if (q_of(threshold) >= std::sqrt(0.5)) {
    CriterionField minus = base;
    base.key = kind + ".coseps";
    base.surrogate = platform_surrogate(model, What::coseps);
    base.level = [q_of](double t) {
      const double q = q_of(t);
      return q > 1.0 ? -1.0 : std::sqrt((1.0 - q) * (1.0 + q));  // q > 1: empty
    };
    minus.key = kind + ".negcoseps";
    minus.surrogate = platform_surrogate(model, What::negcoseps);
    minus.level = base.level;
    return {base, minus};
  }
  base.key = kind + ".negabssin";
  base.surrogate = platform_surrogate(model, What::negabssin);
  base.level = [q_of, scale = model.eps_scale()](double t) { return -q_of(t) * scale; };
  return {base};
}

// The capability CriterionFields of a point platform (valid while the mechanism lives).
template <class Model> class PointPlatformFields final : public CriterionFields {
 public:
  PointPlatformFields(Model model, const mechanisms::Mechanism* m, std::string kind)
      : model_(std::move(model)), m_(m), kind_(std::move(kind)) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& /*reaction_legs*/) const override {
    if (name == "reaction" && !criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
    const double force = criteria.load ? criteria.load->force_N : 0.0;
    CriterionField f = point_platform_field(model_, *m_, kind_, name, force);
    if (name == "pressure_angle" && criteria.max_pressure_angle_deg) {
      return sine_bound_fields(model_, std::move(f), kind_, *criteria.max_pressure_angle_deg, [](double alpha_deg) {
        return std::cos(std::clamp(alpha_deg, 0.0, 90.0) * detail::deg);
      });
    }
    if (name == "reaction" && criteria.max_reaction_N) {
      return sine_bound_fields(model_, std::move(f), kind_, *criteria.max_reaction_N, [force](double r_max) {
        return r_max > 0.0 ? force / r_max : std::numeric_limits<double>::infinity();
      });
    }
    return {f};
  }
  CriterionField singular_determinant(const mechanisms::Criteria& /*criteria*/) const override {
    return point_platform_singular(model_, kind_);
  }
  std::optional<Charts> charts(const geometry::Region& workspace) const override {
    if constexpr (requires { model_.charts(workspace); }) {
      return model_.charts(workspace);
    } else {
      return std::nullopt;
    }
  }

 private:
  Model model_;
  const mechanisms::Mechanism* m_;
  std::string kind_;
};

}  // namespace pkmws::criteria
