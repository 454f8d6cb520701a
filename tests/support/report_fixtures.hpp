// Fixtures of the report tests (tests/report): files whose answers are known in
// closed form, and the JSON text of a report parsed back.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::test {

/// The tests' toy mechanism (tests/toy_rp: one RP leg) with its base at (1, 2)
/// and stroke [3, 7]: the workspace is the annulus 3 <= |P - (1, 2)| <= 7 mm,
/// area 40π, perimeter 20π, one hole, centroid (1, 2), inscribed circle radius 2.
io::MechanismFile toy_annulus_file();

/// A report's JSON text, parsed (the test fails on a parse error).
nlohmann::json parsed(const std::string& json_text);

}  // namespace pkmws::test
