// The active Π-joint's figures as chart data ([Milutinovic] figures 8-12, 15-17).
#pragma once

#include <string>
#include <vector>

#include "mechanisms/pi_joint/pi_joint.hpp"
#include "pkmws/io/plot.hpp"

namespace pkmws::mechanisms {

/// One of the paper's figures as data: `number` is the [Milutinovic] figure number,
/// `stem` a file name ("pi_joint_fig08_length"), `chart` the series.
struct PiJointFigure {
  int number = 0;
  std::string stem;
  io::LineChart chart;
};

/// The curves of [Milutinovic] figures 8-12 (the paper's generic study: a = 1 m,
/// k in {0.3, 0.4, 0.5} (and 1.0, 1.5 in figure 8)) and figures 15-17 (the
/// prototype `joint` over its θ range with its actuator: output angular
/// resolution, angular velocity at the maximal linear speed, static torque at
/// the maximal force). Figures 15-17 need `joint.params().actuator`; without it
/// only figures 8-12 are returned. `samples` points per curve.
std::vector<PiJointFigure> pi_joint_figures(const PiJoint& joint, int samples = 241);

}  // namespace pkmws::mechanisms
