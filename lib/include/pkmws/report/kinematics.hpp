// `pkmws ik`, `dk`, `eval`: every working and assembly mode at a pose or joint
// values, in the output vocabulary of docs/format.md (joints keyed by name,
// lengths in the file's unit, angles in degrees; docs/schema/ik.output.schema.json,
// docs/schema/dk.output.schema.json, docs/schema/eval.output.schema.json).
// Poses and joint values come in as the mechanism takes them (radians).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/mechanisms/capability.hpp"
#include "pkmws/mechanisms/mechanism.hpp"
#include "pkmws/report/explain.hpp"

namespace pkmws::report {

/// What every kinematics report starts with: the file and its joints.
struct MechanismHeader {
  std::string name, mechanism, units;
  int dof = 0;
  std::vector<mechanisms::JointInfo> joints;  // in the order dk takes them
};
MechanismHeader header_of(const io::MechanismFile& file);

struct IkReport {
  MechanismHeader header;
  mechanisms::Pose pose;
  std::vector<mechanisms::JointSolution> solutions;  // one per working mode
};
IkReport ik(const io::MechanismFile& file, const mechanisms::Pose& pose);

struct DkReport {
  MechanismHeader header;
  std::vector<double> joints;                        // the joint values asked (radians, lengths)
  std::vector<mechanisms::PoseSolution> solutions;   // one per assembly mode
  /// Per solution, the path of its figure (dk_figure) or "" (no prefix, or a 1-DOF mechanism).
  std::vector<std::string> figures;
  /// The eliminant, where the mechanism has one (capability Elimination).
  std::optional<mechanisms::Elimination::Report> elimination;
};
/// `figure_prefix`: figures at PREFIX_<k>.svg (k from 1), named in the report, drawn by dk_figure.
DkReport dk(const io::MechanismFile& file, const std::vector<double>& joints, const std::string& figure_prefix = "");
/// The figure of assembly mode k ([Mitsi] figure 4): the mechanism at its pose,
/// the actuators where the joint values put them, over the constant-orientation
/// workspace at that pose.
std::string dk_figure(const io::MechanismFile& file, const DkReport& report, std::size_t k);

struct EvalReport {
  MechanismHeader header;
  mechanisms::Pose pose;
  /// Task-space distance to the type-2 singularity at this orientation, or
  /// nothing with the reason: to the working mode's singular set inside the
  /// workspace, certified within ± distance_error (criteria::singularity_distance_at),
  /// or else to the singularity curves the mechanism draws (no bound).
  std::optional<double> distance_to_type2_singularity;
  std::optional<double> distance_error;
  std::string distance_source;  // what the distance is measured to
  std::string distance_reason;
  std::vector<mechanisms::Evaluation> modes;  // every criterion per working mode
  bool has_load = false;                      // the file's criteria give a load (reactions)
  /// Files with bodies: which parts collide at this platform position.
  std::optional<ExplainReport> bodies;
};
EvalReport eval(const io::MechanismFile& file, const mechanisms::Pose& pose);

/// `--json` output (indented, no trailing newline) and text output (lines ending in a newline).
std::string to_json_text(const IkReport& report);
std::string to_text(const IkReport& report);
std::string to_json_text(const DkReport& report);
std::string to_text(const DkReport& report);
std::string to_json_text(const EvalReport& report);
std::string to_text(const EvalReport& report);

}  // namespace pkmws::report
