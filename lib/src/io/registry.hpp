// The registry of mechanism modules: each module folder (lib/src/mechanisms/<name>/)
// has a load.cpp defining <name>_kinds(), and lib/src/mechanisms/modules.def
// lists the folders, one line each. Nothing else names a mechanism kind. Private.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "io/json_reader.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::io::detail {

using MechanismPtr = std::shared_ptr<const mechanisms::Mechanism>;

/// One file keyword (`mechanism`): its loader and its own top-level fields.
/// A loader reads its parameters from the document reader (common fields are
/// read by parse_mechanism) and validates every value, throwing InputError
/// with the field path.
struct Kind {
  std::string keyword;
  std::function<MechanismPtr(JsonReader&)> load;
  std::vector<std::string> fields;
};

#define PKMWS_MODULE(name) std::vector<Kind> name##_kinds();
#include "mechanisms/modules.def"
#undef PKMWS_MODULE

/// Every kind of every registered module, sorted by keyword.
const std::vector<Kind>& kinds();
/// Registers the kinds of a module compiled outside the library (a test's toy
/// mechanism, a plugin): call before the first load, e.g. from a static
/// initialiser; returns true. Throws std::invalid_argument on a keyword that
/// is already registered.
bool register_kinds(std::vector<Kind> more);
/// The kind with this keyword, or nullptr.
const Kind* find_kind(const std::string& keyword);

}  // namespace pkmws::io::detail
