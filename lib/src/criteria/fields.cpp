// Criterion fields (see criteria/fields.hpp; derivations in docs/theory/level_sets.md).
#include "pkmws/criteria/fields.hpp"
#include "pkmws/core/error.hpp"

#include "criteria/singularity_distance.hpp"
#include "detail/parallel.hpp"
#include "pkmws/geometry/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace pkmws::criteria {

std::vector<CriterionField> fields_for(const mechanisms::Design& file, const std::string& name,
                                       std::optional<double> threshold) {
  if (name != "pressure_angle" && name != "reaction" && name != "velocity_ratio" && name != "condition_number") {
    throw InputError("unknown criterion \"" + name +
                     "\" (expected pressure_angle, reaction, velocity_ratio or condition_number)");
  }
  const auto capability = file.model->capability<CriterionFields>();
  if (!capability) throw InputError(file.path + ": certified level sets: " + capability.reason());
  try {
    mechanisms::Criteria criteria = file.criteria;
    if (threshold) {
      if (name == "pressure_angle") criteria.max_pressure_angle_deg = threshold;
      if (name == "reaction") criteria.max_reaction_N = threshold;
      if (name == "velocity_ratio") criteria.max_velocity_ratio = threshold;
      if (name == "condition_number") criteria.max_condition_number = threshold;
    }
    return capability->fields(name, criteria, file.reaction_legs);
  } catch (const std::invalid_argument& e) {
    throw InputError(file.path + ": " + e.what());
  }
}

std::vector<Limit> file_limits(const mechanisms::Design& file) {
  std::vector<Limit> out;
  const auto& c = file.criteria;
  if (c.max_pressure_angle_deg) out.push_back({"pressure_angle", *c.max_pressure_angle_deg});
  if (c.max_reaction_N) out.push_back({"reaction", *c.max_reaction_N});
  if (c.max_velocity_ratio) out.push_back({"velocity_ratio", *c.max_velocity_ratio});
  if (c.max_condition_number) out.push_back({"condition_number", *c.max_condition_number});
  if (c.min_singularity_distance) out.push_back({"singularity_distance", *c.min_singularity_distance});
  return out;
}

namespace {

class LimitedMechanism final : public mechanisms::Mechanism {
 public:
  LimitedMechanism(std::shared_ptr<const mechanisms::Mechanism> base, std::vector<std::pair<CriterionField, double>> f,
                   std::vector<std::vector<geometry::Point>> singular, double singular_distance)
      : base_(std::move(base)), fields_(std::move(f)), singular_(std::move(singular)),
        singular_distance_(singular_distance) {}
  std::string_view kind() const override { return base_->kind(); }
  int dof() const override { return base_->dof(); }
  std::vector<mechanisms::JointInfo> joints() const override { return base_->joints(); }
  std::vector<mechanisms::JointSolution> inverse(const mechanisms::Pose& p) const override { return base_->inverse(p); }
  std::vector<mechanisms::PoseSolution> direct(std::span<const double> q) const override { return base_->direct(q); }
  std::vector<mechanisms::Evaluation> evaluate(const mechanisms::Pose& p, const mechanisms::Criteria& c) const override {
    return base_->evaluate(p, c);
  }
  geometry::Region workspace() const override {
    throw std::runtime_error("a criteria-limited workspace is certified, not exact (pkmws area gives its bounds)");
  }
  bool reachable(const mechanisms::Pose& pose) const override {
    if (!base_->reachable(pose)) return false;
    for (const auto& [field, level] : fields_) {
      const double v = field.surrogate->value({pose.x, pose.y});
      if (!(v <= level)) return false;  // NaN (undefined) counts as outside
    }
    // d(P) >= δ against the traced singular curves (within their bound w).
    if (singular_distance_ > 0.0 && detail::distance_to_curves(singular_, {pose.x, pose.y}) < singular_distance_) {
      return false;
    }
    return true;
  }
  mechanisms::Drawing draw(const mechanisms::Pose& p) const override { return base_->draw(p); }
  double orientation() const override { return base_->orientation(); }
  std::string workspace_label() const override { return base_->workspace_label(); }
  geometry::Box bounds() const override { return base_->bounds(); }

 private:
  std::shared_ptr<const mechanisms::Mechanism> base_;
  std::vector<std::pair<CriterionField, double>> fields_;
  std::vector<std::vector<geometry::Point>> singular_;
  double singular_distance_ = 0.0;
};

}  // namespace

std::shared_ptr<const mechanisms::Mechanism> limited_mechanism(const mechanisms::Design& file) {
  std::vector<std::pair<CriterionField, double>> fields;
  std::vector<std::vector<geometry::Point>> singular;
  double singular_distance = 0.0;
  for (const Limit& l : file_limits(file)) {
    if (l.name == "singularity_distance") {
      // The grid's view: S traced to a tight bound (not certified here).
      const geometry::Region w = criteria_domain(file);
      certified::LevelSetOptions o;
      o.relative_tolerance = 1e-7;
      detail::SingularTubes t = detail::singular_tubes(file, w, l.threshold, w.area(), o, false);
      if (!t.nowhere.empty()) {
        singular = {{w.bbox().min, w.bbox().max}};
        singular_distance = std::numeric_limits<double>::infinity();
      } else {
        singular = std::move(t.curves);
        singular_distance = l.threshold;
      }
      continue;
    }
    for (CriterionField& f : fields_for(file, l.name, l.threshold)) {
      const double level = f.level(l.threshold);
      fields.emplace_back(std::move(f), level);
    }
  }
  return std::make_shared<LimitedMechanism>(file.model, std::move(fields), std::move(singular), singular_distance);
}

std::optional<SingularityDistance> singularity_distance_at(const mechanisms::Design& file, geometry::Point p) {
  const auto fields = file.model->capability<CriterionFields>();
  if (!fields) return std::nullopt;
  try {
    (void)detail::singular_field(file);
  } catch (const std::exception&) {
    return std::nullopt;  // no determinant for this mechanism (or orientation)
  }
  const geometry::Region w = criteria_domain(file);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  // With area_estimate = diag², the traced chords' bound is w = 0.9e-6 diag² / (4 × S's length): about
  // 2e-7 of the diagonal for an S as long as the diagonal.
  const geometry::Box box = w.bbox();
  const double diag = std::hypot(box.width(), box.height());
  const detail::SingularTubes t = detail::singular_tubes(file, w, 0.25 * diag, diag * diag, o, false);
  SingularityDistance d;
  if (!t.nowhere.empty()) {
    d.note = t.nowhere;
    return d;  // S is all of W: d = 0
  }
  if (t.empty_set) {
    d.lower = d.upper = std::numeric_limits<double>::infinity();
    d.note = "no type-2 singular point of the working mode in the workspace";
    return d;
  }
  const double along = detail::distance_to_curves(t.curves, p);
  d.error = t.error;
  d.upper = along + t.error;
  d.lower = std::max(0.0, along - t.error);
  for (const geometry::Box& b : t.undecided) {  // S may pass anywhere in a box it could not trace
    const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x}), dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
    d.lower = std::min(d.lower, std::hypot(dx, dy));
  }
  if (t.curves.empty()) d.upper = std::numeric_limits<double>::infinity();  // only untraced boxes: S may be empty
  return d;
}

std::optional<CriterionFields::WorkspaceSets> workspace_sets(const mechanisms::Design& file) {
  const auto fields = file.model->capability<CriterionFields>();
  return fields ? fields->workspace_sets() : std::nullopt;
}

bool criteria_domain_exact(const mechanisms::Design& file) { return !workspace_sets(file); }

certified::CertifiedRegion workspace_enclosure(const mechanisms::Design& file, double relative_tolerance) {
  if (!workspace_sets(file)) return file.model->workspace_enclosure();
  certified::LevelSetOptions o;
  o.relative_tolerance = relative_tolerance;
  o.build_regions = true;
  return limited_workspace(file, {}, o).region;
}

geometry::Region criteria_domain(const mechanisms::Design& file) {
  if (workspace_sets(file)) return file.model->workspace_enclosure().outer;
  return file.model->workspace();
}

namespace {

// W' ∩ { d >= δ } from W' = out.region (the workspace or its criteria-limited
// part): with tubes T_in ⊇ { d < δ } ⊇ T_out, inner = W'.inner − T_in and
// outer = W'.outer − T_out; the area bounds subtract the tubes' parts
// (area(W' ∩ {d < δ}) is between area(W'.inner ∩ T_out) and area(W'.outer ∩ T_in)).
void limit_singularity_distance(const mechanisms::Design& file, const geometry::Region& within, double delta,
                                const certified::LevelSetOptions& options, LimitedWorkspace& out) {
  certified::CertifiedRegion& r = out.region;
  detail::SingularTubes t = detail::singular_tubes(file, within, delta, r.area_estimate(), options, true);
  if (!t.nowhere.empty()) {
    r = certified::from_exact(geometry::Region{});
    out.note = t.nowhere;
    return;
  }
  if (t.empty_set) {
    out.note = "no type-2 singular point in the workspace: min_singularity_distance does not limit it";
    return;
  }
  const bool exact = r.exact;
  // Each side's Boolean operations (and areas) are independent of the other's: two tasks.
  geometry::Region inner, outer;
  double inner_tube_part = 0.0, outer_tube_part = 0.0;  // area(W'.outer ∩ T_in), area(W'.inner ∩ T_out)
  const geometry::Region& around = r.outer.empty() && r.area_upper > 0.0 ? within : r.outer;  // encloses W'
  pkmws::detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 0;
  pkmws::detail::for_each_block(policy, 2, 2, [&](std::size_t k) {
    if (k == 0) {
      inner = r.inner.subtract(t.inner_tube);
      (void)inner.area();  // the boundary, extracted once (cached)
      if (!exact) inner_tube_part = around.intersect(t.inner_tube).area();
    } else {
      outer = r.outer.subtract(t.outer_tube);
      (void)outer.area();
      if (!exact) outer_tube_part = r.inner.intersect(t.outer_tube).area();
    }
  });
  if (exact) {
    r.area_lower = inner.area();
    r.area_upper = outer.area();
  } else {
    // Regions not built (a deadline): W itself encloses W'.
    r.area_lower = std::max(0.0, r.area_lower - inner_tube_part);
    r.area_upper = std::max(r.area_lower, r.area_upper - outer_tube_part);
    // The regions' own areas bound it too, and area(inner) <= area_lower <=
    // area_upper <= area(outer) must hold: the better of both (with regions
    // that follow W's level curves, the subtraction above can be the looser).
    if (!r.outer.empty()) {
      r.area_lower = std::max(r.area_lower, inner.area());
      r.area_upper = std::max(r.area_lower, std::min(r.area_upper, outer.area()));
    }
  }
  r.inner = inner;
  r.outer = outer;
  r.exact = false;
  out.singular_curves = std::move(t.curves);
  out.singular_undecided = std::move(t.undecided);
  out.singular_error = t.error;
  if (t.stopped) out.detail.stopped = true;
}

// ⋂ {F_k <= level_k} over W = rest ∪ the charts' parts (disjoint): the rest
// traced in (x, y) to 3/4 of the relative tolerance, each chart in its own
// coordinates and area element to an equal share of the remaining quarter of
// the rest's area (an absolute budget: a chart's part may be small). Every
// chart of a module has every field its plane has (else a logic error).
certified::LevelSetResult charted_sublevel_set(const std::vector<certified::Constraint>& cs,
                                               const std::vector<std::string>& keys, const CriterionFields::Charts& charts,
                                               const certified::LevelSetOptions& options) {
  std::vector<std::vector<certified::Constraint>> chart_cs;
  std::vector<std::shared_ptr<const certified::ScalarField>> keep;
  for (const CriterionFields::Chart& chart : charts.charts) {
    std::vector<certified::Constraint> c;
    for (const auto& cut : chart.cuts) c.push_back({cut.field.get(), cut.level});
    for (std::size_t i = 0; i < keys.size(); ++i) {
      auto f = chart.field(keys[i]);
      if (!f) throw std::logic_error("charted_sublevel_set: a chart without the field " + keys[i]);
      c.push_back({f.get(), cs[i].level});
      keep.push_back(std::move(f));
    }
    chart_cs.push_back(std::move(c));
  }
  certified::LevelSetOptions o = options;
  o.relative_tolerance = 0.75 * options.relative_tolerance;
  o.within_disks = charts.rest_disks;
  certified::LevelSetResult total = certified::sublevel_set(cs, charts.rest, charts.rest_test, o);
  const double budget = 0.25 * options.relative_tolerance * std::max(total.region.area_lower, 1e-300) /
                        static_cast<double>(std::max<std::size_t>(1, charts.charts.size()));
  // The charts are independent once their budget is known: traced in
  // parallel (each also in parallel inside), added in order.
  std::vector<certified::LevelSetResult> parts(charts.charts.size());
  pkmws::detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 0;
  std::mutex report;  // progress is reported from one thread at a time
  pkmws::detail::for_each_block(policy, parts.size(), parts.size(), [&](std::size_t k) {
    const CriterionFields::Chart& chart = charts.charts[k];
    certified::LevelSetOptions co = options;
    if (options.progress) {
      co.progress = [&](double fraction) {
        const std::lock_guard lock(report);
        options.progress(fraction);
      };
    }
    co.weight = chart.weight;
    // The charts' parts are thin (a band, a small disk): a coarser cover
    // (16 × 2³ cells over the window) still leaves the curve graphs in its cells.
    co.cover_depth = co.cover_depth > 0 ? std::min(co.cover_depth, 3) : 3;
    // Cells closest to square in the chart's units: its window is far wider
    // than high (a band: ~11 times, a base disk: 2π), and a level curve
    // crossing it then crossed 128 rows of flat cells (DexTAR (+1, +1),
    // α ≤ 80°: 1 800 traced cells per band chart with 16 rows, 500 with 1).
    co.base_rows = std::clamp(static_cast<int>(std::lround(co.base * chart.window.height() / chart.window.width())), 1,
                              co.base);
    // As deep as the flat cells went: the undecided cells left where no depth
    // traces (a tangency at the window's edge) are then no larger than with
    // as many rows as columns (their area had kept the DexTAR's 1e-9 runs at
    // 9e-9: α ≤ 20°, a band chart's 4 cells).
    co.refine_depth = std::min(
        40, co.refine_depth + static_cast<int>(std::ceil(std::log2(static_cast<double>(co.base) / co.base_rows))));
    // The budget in area units: relative to the part's own area it would be
    // far looser than the rest's (the part is small), relative to the
    // window's far tighter (the part fills little of it: the band charts of
    // the DexTAR were traced 55 times narrower than their budget).
    co.relative_tolerance = 1e-15;
    co.absolute_tolerance = budget;
    const geometry::Box w = chart.window;
    parts[k] = certified::sublevel_set(chart_cs[k], geometry::rectangle(w),
                                       [](const geometry::Box&) { return certified::CellState::inside; }, co);
  });
  for (std::size_t k = 0; k < charts.charts.size(); ++k) {
    const CriterionFields::Chart& chart = charts.charts[k];
    const certified::LevelSetResult& r = parts[k];
    total.region.area_lower += std::max(0.0, r.region.area_lower - chart.overlap);
    total.region.area_upper += r.region.area_upper + chart.uncovered;
    total.traced_cells += r.traced_cells;
    total.undecided_cells += r.undecided_cells;
    total.curve_points += r.curve_points;
    total.cell_tests += r.cell_tests;
    total.undecided_area += r.undecided_area;
    total.traced_width += r.traced_width;
    total.retraced_leaves += r.retraced_leaves;
    total.stopped = total.stopped || r.stopped;
    for (std::size_t i = 0; i < r.curves.size(); ++i) {
      // The cuts' curves bound the chart's part inside W: not level curves.
      if (r.curve_constraints[i] < chart.cuts.size()) continue;
      const certified::CurvePiece& piece = r.curves[i];
      certified::CurvePiece mapped;
      mapped.reserve(piece.size());
      for (const geometry::Point& p : piece) mapped.push_back(chart.to_plane(p));
      total.curves.push_back(std::move(mapped));
      total.curve_constraints.push_back(r.curve_constraints[i] - chart.cuts.size());
    }
  }
  return total;
}

}  // namespace

LimitedWorkspace limited_workspace(const mechanisms::Design& file, const std::vector<Limit>& limits,
                                   const certified::LevelSetOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LimitedWorkspace out;
  // A mechanism without the type-2 determinant refuses before its workspace is built.
  for (const Limit& l : limits) {
    if (l.name == "singularity_distance") (void)detail::singular_field(file);
  }
  // W exact, or an exact region cut by level sets traced with the criteria's.
  const std::optional<CriterionFields::WorkspaceSets> sets = workspace_sets(file);
  const geometry::Region within = sets ? sets->within : criteria_domain(file);
  // Group by surrogate: the stricter level per key.
  std::map<std::string, std::pair<CriterionField, double>> by_key;
  std::optional<double> min_distance;
  for (const Limit& l : limits) {
    if (l.name == "singularity_distance") {
      min_distance = min_distance ? std::max(*min_distance, l.threshold) : l.threshold;
      continue;
    }
    for (CriterionField& f : fields_for(file, l.name, l.threshold)) {
      const double level = f.level(l.threshold);
      auto it = by_key.find(f.key);
      if (it == by_key.end()) {
        by_key.emplace(f.key, std::make_pair(f, level));
      } else {
        it->second.second = std::min(it->second.second, level);
      }
    }
  }
  std::string nowhere;
  for (const auto& [key, entry] : by_key) {
    if (nowhere.empty()) nowhere = entry.first.nowhere;
  }
  if (by_key.empty() && !sets) {
    out.region = certified::from_exact(within);
  } else if (!nowhere.empty()) {
    out.region = certified::from_exact(geometry::Region{});
    out.note = nowhere;
  } else {
    std::vector<certified::Constraint> cs;
    std::vector<std::string> keys;  // of the criteria's constraints (after the workspace cuts)
    certified::WithinTest within_test;
    if (sets) {
      for (const auto& cut : sets->cuts) cs.push_back({cut.field.get(), cut.level});
      within_test = sets->within_test;
    }
    for (auto& [key, entry] : by_key) {
      cs.push_back({entry.first.surrogate.get(), entry.second});
      keys.push_back(key);
      if (!within_test) within_test = entry.first.within_test;  // one mechanism: one workspace test
    }
    certified::LevelSetOptions o = options;
    if (min_distance) {  // the tubes are cut from both regions
      o.build_regions = true;
      o.regions = certified::LevelSetOptions::Regions::both;
    }
    // Charts where the fields are singular on W's boundary or at a point of W
    // (the bounds only: regions are built in the plane).
    std::optional<CriterionFields::Charts> charts;
    if (!sets && !o.build_regions && o.charts) {
      if (const auto fields = file.model->capability<CriterionFields>()) charts = fields->charts(within);
    }
    certified::LevelSetResult r =
        charts ? charted_sublevel_set(cs, keys, *charts, o) : certified::sublevel_set(cs, within, within_test, o);
    out.charted = charts.has_value();
    out.region = std::move(r.region);
    // The criteria's level curves (not those of W's cuts, which come first).
    const std::size_t n_cuts = sets ? sets->cuts.size() : 0;
    for (std::size_t i = 0; i < r.curves.size(); ++i) {
      if (r.curve_constraints[i] >= n_cuts) out.curves.push_back(std::move(r.curves[i]));
    }
    r.curves.clear();
    r.curve_constraints.clear();
    out.detail = std::move(r);
  }
  if (min_distance && out.note.empty()) limit_singularity_distance(file, within, *min_distance, options, out);
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace pkmws::criteria
