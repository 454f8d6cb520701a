// `pkmws plot`: the curves of a 1-DOF mechanism as SVG line charts (the
// active Π-joint: [Milutinovic] figures 8-12 and 15-17), asked through the
// capability io::Charts (docs/format.md (command line),
// docs/schema/plot.output.schema.json). `pkmws batch` draws the same charts
// for a file without a planar workspace.
#pragma once

#include <string>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::report {

/// One chart: its file name ("<stem>.svg") and its SVG text.
struct PlotFigure {
  std::string file;
  std::string svg;
};

struct PlotReport {
  std::string name, mechanism, units;
  /// Where the figures go (named in the report; written by the caller).
  std::string output_dir;
  std::vector<PlotFigure> figures;
};

/// The charts of `file`. Throws InputError naming the file when the mechanism
/// has no curve charts (with the capability's reason).
PlotReport plot(const io::MechanismFile& file, const std::string& output_dir);

/// `pkmws plot --json` (indented, no trailing newline): the figures by file name.
std::string to_json_text(const PlotReport& report);
/// `pkmws plot` without --json: one line per figure, "DIR/NAME.svg".
std::string to_text(const PlotReport& report);

}  // namespace pkmws::report
