// A toy mechanism module: one RP leg (a revolute joint at `base`, a prismatic
// joint along the leg) moving a point P. It shows what adding a mechanism
// takes: this folder (kinematics, workspace, loader, drawing) and one
// registration line. Joints: theta (the leg's angle) and rho (its length,
// within `stroke`); the workspace is the annulus stroke[0] <= |P - base| <= stroke[1].
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "io/registry.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::toy {

using namespace mechanisms;
using geometry::Point;

class ToyRp final : public Mechanism {
 public:
  ToyRp(Point base, double rho_min, double rho_max) : base_(base), lo_(rho_min), hi_(rho_max) {}

  std::string_view kind() const override { return "toy_rp"; }
  int dof() const override { return 2; }
  std::vector<JointInfo> joints() const override {
    return {{"theta", true, std::nullopt}, {"rho", false, std::array{lo_, hi_}}};
  }
  std::vector<JointSolution> inverse(const Pose& pose) const override {
    const Point d = Point{pose.x, pose.y} - base_;
    const double rho = std::hypot(d.x, d.y);
    JointSolution s{"+", {std::atan2(d.y, d.x), rho}, true, ""};
    if (rho < lo_ || rho > hi_) {
      s.valid = false;
      s.reason = "rho outside stroke";
    }
    return {s};
  }
  std::vector<PoseSolution> direct(std::span<const double> q) const override {
    PoseSolution s;
    s.mode = "+";
    s.pose = {base_.x + q[1] * std::cos(q[0]), base_.y + q[1] * std::sin(q[0]), 0.0};
    s.valid = q[1] >= lo_ && q[1] <= hi_;
    if (!s.valid) s.reason = "rho outside stroke";
    return {s};
  }
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& /*criteria*/) const override {
    Evaluation e;
    e.mode = "+";
    const auto ik = inverse(pose).front();
    e.reachable = ik.valid;
    e.reason = ik.reason;
    e.joints = ik.joints;
    // dq/dx = [[-dy/rho², dx/rho²], [dx/rho, dy/rho]]: det = -1/rho; singular values 1/rho and 1.
    const double rho = ik.joints[1];
    e.jacobian_det = rho > 0 ? -1.0 / rho : 0.0;
    e.condition_number = rho > 0 ? std::max(rho, 1.0 / rho) : std::numeric_limits<double>::infinity();
    e.singular = !(rho > 0);
    e.singularity = e.singular ? "type1" : "";
    e.pressure_angle_deg = {0.0};
    return {e};
  }
  geometry::Region workspace() const override { return geometry::annulus(base_, lo_, hi_); }
  bool reachable(const Pose& pose) const override {
    const double rho = std::hypot(pose.x - base_.x, pose.y - base_.y);
    return rho >= lo_ && rho <= hi_;
  }
  Drawing draw(const Pose& pose) const override {
    Drawing d;
    d.base_points = {base_};
    d.links = {{base_, {pose.x, pose.y}}};
    d.sliders = {{pose.x, pose.y}};
    d.tool = {pose.x, pose.y};
    return d;
  }
  geometry::Box bounds() const override {
    return {{base_.x - hi_, base_.y - hi_}, {base_.x + hi_, base_.y + hi_}};
  }

 private:
  Point base_;
  double lo_, hi_;
};

io::detail::MechanismPtr load_toy_rp(io::detail::JsonReader& document) {
  const Point base = document.point("base");
  const auto stroke = document.interval("stroke");
  if (!(stroke[0] >= 0.0)) document.fail("stroke", "must start at a length >= 0");
  return std::make_shared<ToyRp>(base, stroke[0], stroke[1]);
}

// The one registration line.
[[maybe_unused]] const bool registered = io::detail::register_kinds({{"toy_rp", load_toy_rp, {"base", "stroke"}}});

}  // namespace pkmws::toy
