// The parameter model: a mechanism file's numbers addressed by their field
// paths ("legs[1].rod_length", "stroke[0]", "orientation_deg"), with type and
// unit, readable and settable; a set value is validated by the loader, so its
// errors are the loader's one-line messages. What sweeps, optimisers and the
// Python module vary (docs/format.md (parameters)).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::io {

/// One number of a mechanism file.
struct Parameter {
  std::string path;   // e.g. "legs[1].rod_length"
  double value = 0.0;
  /// "number", or "integer" for signs, modes and leg numbers (branch,
  /// working_mode, sense, reaction_legs).
  std::string type;
  /// "mm"/"m" (the file's length unit), "deg", "N", "N m", "mm/s", "1" (dimensionless).
  std::string unit;
};

/// Every number of the file (its mechanism's fields, criteria and bodies; not
/// `source`), object keys in sorted order (the document as parsed).
std::vector<Parameter> parameters(const MechanismFile& file);

/// The number at `path`; throws InputError "<file>: '<path>' is not a field
/// path like legs[1].rod_length" or "... is not a number of the file".
double parameter(const MechanismFile& file, const std::string& path);
/// The number at `path` with its type and unit (the same errors as parameter()).
Parameter parameter_info(const MechanismFile& file, const std::string& path);

/// The file with the number at `path` set to `value`, loaded anew (the
/// loader's validation and messages). The path must exist in the file.
MechanismFile with_parameter(const MechanismFile& file, const std::string& path, double value);
/// The file with several numbers set at once (then loaded anew, once: a
/// combination may be valid where one change alone is not). Non-finite values
/// are refused: "<file>: '<path>': must be a finite number".
MechanismFile with_parameters(const MechanismFile& file, const std::vector<std::pair<std::string, double>>& values);

}  // namespace pkmws::io
