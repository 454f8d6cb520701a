// The JSON side of mechanism files, private to the library (and its tests):
// the validated document, parsing from a JSON value, and field paths into a
// document. nlohmann-json is not in any public header.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::io {

struct Document {
  nlohmann::json json;
};

/// Parse and validate a document; throws InputError with the field's path.
MechanismFile parse_mechanism(const nlohmann::json& document, const std::string& origin);
/// The file's validated document (null for a file built in code).
const nlohmann::json& document_json(const MechanismFile& file);
/// The file's `source` (null when absent).
nlohmann::json source_json(const MechanismFile& file);

/// The JSON node at a field path of a document; throws InputError
/// "<where>: '<path>' is not a field path like legs[1].rod_length" or
/// "<where>: '<path>' <missing>" when the document has no such node.
nlohmann::json& field_at(nlohmann::json& document, const std::string& path, const std::string& where,
                         const std::string& missing = "is not in the file");
const nlohmann::json& field_at(const nlohmann::json& document, const std::string& path, const std::string& where,
                               const std::string& missing = "is not in the file");

}  // namespace pkmws::io
