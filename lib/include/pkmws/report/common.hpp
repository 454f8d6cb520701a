// The report layer (docs/architecture.md): what each command answers, as plain
// structs, their JSON text and their text form, produced by the library so that
// the command line only parses options and prints, and the Python module gives
// the same numbers. This header: what every report shares.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::report {

/// How a certified computation is bounded and followed (the command line's
/// `--max-time` and progress line): `bound` adds a deadline and a progress
/// reporter for `stage` ("level 2 of 3") to level-set options; no `bound`: the
/// options as given, never stopped.
struct Budget {
  std::function<certified::LevelSetOptions(certified::LevelSetOptions, const std::string& stage)> bound;
  /// What a result cut short by the deadline says about itself (`stopped`).
  std::string stopped_note;
  certified::LevelSetOptions apply(certified::LevelSetOptions o, const std::string& stage = "") const {
    return bound ? bound(std::move(o), stage) : o;
  }
};

/// Length unit squared, e.g. "mm²".
std::string area_unit(const io::MechanismFile& file);

/// Bounds of an area measured on an exact boundary: the double rounding of
/// Green's theorem (64 ulp of the area on either side).
struct AreaBounds {
  double lower = 0.0;
  double upper = 0.0;
};
AreaBounds exact_area_bounds(double area);

/// The contract of every JSON report applied to a JSON document (its text):
/// no bare null — a null (or an array holding one) at `key` comes with
/// `key`_reason, or lies in an object that has a `reason`; a null without one
/// gets a generic reason. Returns the text indented by 2 (the commands whose
/// reports are still assembled by the command line print through this).
std::string json_with_null_reasons(const std::string& json_text);

/// A pose inside `region` for drawing the mechanism: the largest component's
/// centroid or the centre of its largest inscribed circle, or points around it,
/// the first reachable and non-singular; the file's orientation (3-DOF).
mechanisms::Pose sample_pose(const io::MechanismFile& file, const geometry::Region& region);

/// A number in decimal notation only: an optional sign, digits with an
/// optional point, an optional exponent ("12", "-0.5", ".5", "1e-3"); no
/// spaces, hexadecimal, "inf" or "nan". std::nullopt with the reason in
/// `problem` otherwise (as the command line reads every number).
std::optional<double> decimal_number(const std::string& text, std::string& problem);
/// decimal_number, or InputError "`what`: <the reason>".
double parse_number(const std::string& text, const std::string& what);

}  // namespace pkmws::report
