// pkmws, the front door: the few calls most programs need — load a mechanism
// file, its workspace, its area, the criteria at a pose, its boundary in an
// exchange format — as free functions, in the manner of Clipper2's clipper.h.
// Everything else (capabilities, level sets, sweeps, figures) is in the layer
// headers below it (docs/architecture.md). Errors: pkmws::InputError, one line
// naming the field or the reason.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/core/error.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws {

/// A mechanism file, parsed and validated (docs/format.md).
using MechanismFile = io::MechanismFile;

/// Reads and validates a mechanism file; throws InputError naming the field.
MechanismFile load(const std::filesystem::path& file);

/// The area the file asks for, with what it is: the workspace's (exact, or
/// certified bounds where its boundary is not made of arcs and segments), or,
/// for a file with `criteria`, the certified area of the criteria-limited
/// workspace.
struct Area {
  double lower = 0.0;
  double upper = 0.0;
  bool exact = false;     // lower == upper up to the double rounding of one exact area
  bool limited = false;   // the file's criteria limit the workspace
  std::string units;      // area in units² ("m" or "mm")
};
/// `relative_tolerance`: the width asked for a certified area, relative to it.
Area area(const MechanismFile& file, double relative_tolerance = 1e-6);

/// The file's workspace, its criteria limits aside: exact (inner == outer), or
/// an inner and an outer enclosure where its boundary is not made of arcs and
/// segments. A mechanism without one (a lone Π-joint): InputError naming the
/// file, with the mechanism's reason.
certified::CertifiedRegion workspace(const MechanismFile& file);

/// The region the file describes, as `area` measures it: exact (inner ==
/// outer) or an inner and an outer enclosure. Criteria-limited regions are
/// built from their certified cells at `relative_tolerance`.
certified::CertifiedRegion region(const MechanismFile& file, double relative_tolerance = 1e-4);

/// Every criterion at the pose (x, y) in the file's unit, for every working
/// or assembly mode; `phi_rad` defaults to the file's orientation (3-DOF).
std::vector<mechanisms::Evaluation> evaluate(const MechanismFile& file, double x, double y,
                                             std::optional<double> phi_rad = {});

/// The boundary of region(file) in `format` (docs/format.md), the outer or
/// inner enclosure where the region is certified; the file states which.
std::string export_boundary(const MechanismFile& file, io::ExportFormat format, io::Bound bound = io::Bound::outer);
/// The same, written to `out` all or nothing.
void export_boundary(const MechanismFile& file, io::ExportFormat format, const std::filesystem::path& out,
                     io::Bound bound = io::Bound::outer);

}  // namespace pkmws
