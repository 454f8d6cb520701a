// Mechanism files (docs/format.md): JSON with `name`, `mechanism`, `units`, the
// mechanism's parameters and optional `criteria`, `source`, `description`.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pkmws/core/error.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::bodies {
class BodyRig;  // pkmws/bodies/bodies.hpp
}

namespace pkmws::io {

using InputError = pkmws::InputError;  // pkmws/core/error.hpp

/// The validated JSON document of a file (private: lib/src/io/document.hpp);
/// nlohmann-json stays out of the public headers.
struct Document;

/// A parsed mechanism file: the design it states (path, model, criteria,
/// reaction legs: mechanisms::Design) and what else the file holds.
struct MechanismFile : mechanisms::Design {
  std::string name;
  std::string mechanism;        // the file's `mechanism` keyword
  std::string units;            // "mm" or "m"
  std::string description;
  std::string source;           // `source` (paper, figure, notes) as JSON text, "" if absent
  std::shared_ptr<const Document> document;  // the validated document as read (document_text)
  /// The optional `bodies` (docs/format.md (bodies); moma and five_bar), null when absent.
  std::shared_ptr<const bodies::BodyRig> bodies;
};

/// Parse and validate; throws InputError with the field's path on any problem.
MechanismFile load_mechanism(const std::filesystem::path& path);
/// Parse and validate a document given as JSON text; `origin` names it in messages.
MechanismFile parse_mechanism_text(std::string_view json_text, const std::string& origin);
/// The file's validated document as JSON text (compact; what `pkmws info --json` prints).
std::string document_text(const MechanismFile& file);

}  // namespace pkmws::io
