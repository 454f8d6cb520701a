// Criterion fields (see criteria/fields.hpp; derivations in docs/theory/level_sets.md).
#include "pkmws/criteria/fields.hpp"
#include "pkmws/core/error.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

namespace pkmws::criteria {

std::vector<CriterionField> fields_for(const mechanisms::Design& file, const std::string& name) {
  if (name != "pressure_angle" && name != "reaction" && name != "velocity_ratio" && name != "condition_number") {
    throw InputError("unknown criterion \"" + name +
                     "\" (expected pressure_angle, reaction, velocity_ratio or condition_number)");
  }
  const auto capability = file.model->capability<CriterionFields>();
  if (!capability) throw InputError(file.path + ": certified level sets: " + capability.reason());
  try {
    return capability->fields(name, file.criteria, file.reaction_legs);
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
  return out;
}

namespace {

class LimitedMechanism final : public mechanisms::Mechanism {
 public:
  LimitedMechanism(std::shared_ptr<const mechanisms::Mechanism> base, std::vector<std::pair<CriterionField, double>> f)
      : base_(std::move(base)), fields_(std::move(f)) {}
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
    return true;
  }
  mechanisms::Drawing draw(const mechanisms::Pose& p) const override { return base_->draw(p); }
  double orientation() const override { return base_->orientation(); }
  std::string workspace_label() const override { return base_->workspace_label(); }
  geometry::Box bounds() const override { return base_->bounds(); }

 private:
  std::shared_ptr<const mechanisms::Mechanism> base_;
  std::vector<std::pair<CriterionField, double>> fields_;
};

}  // namespace

std::shared_ptr<const mechanisms::Mechanism> limited_mechanism(const mechanisms::Design& file) {
  std::vector<std::pair<CriterionField, double>> fields;
  for (const Limit& l : file_limits(file)) {
    for (CriterionField& f : fields_for(file, l.name)) {
      const double level = f.level(l.threshold);
      fields.emplace_back(std::move(f), level);
    }
  }
  return std::make_shared<LimitedMechanism>(file.model, std::move(fields));
}

geometry::Region criteria_domain(const mechanisms::Design& file) { return file.model->workspace(); }

LimitedWorkspace limited_workspace(const mechanisms::Design& file, const std::vector<Limit>& limits,
                                   const certified::LevelSetOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LimitedWorkspace out;
  const geometry::Region within = criteria_domain(file);
  // Group by surrogate: the stricter level per key.
  std::map<std::string, std::pair<CriterionField, double>> by_key;
  for (const Limit& l : limits) {
    for (CriterionField& f : fields_for(file, l.name)) {
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
  if (by_key.empty()) {
    out.region = certified::from_exact(within);
  } else if (!nowhere.empty()) {
    out.region = certified::from_exact(geometry::Region{});
    out.note = nowhere;
  } else {
    std::vector<certified::Constraint> cs;
    certified::WithinTest within_test;
    for (auto& [key, entry] : by_key) {
      cs.push_back({entry.first.surrogate.get(), entry.second});
      if (!within_test) within_test = entry.first.within_test;  // one mechanism: one workspace test
    }
    certified::LevelSetResult r = certified::sublevel_set(cs, within, within_test, options);
    out.region = std::move(r.region);
    out.curves = std::move(r.curves);
    out.detail = std::move(r);
  }
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace pkmws::criteria
