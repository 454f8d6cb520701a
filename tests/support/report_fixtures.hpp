// Fixtures of the report tests (tests/report): files whose answers are known in
// closed form, and the JSON text of a report parsed back.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::test {

/// The tests' toy mechanism (tests/toy_rp: one RP leg) with its base at (1, 2)
/// and stroke [3, 7]: the workspace is the annulus 3 <= |P - (1, 2)| <= 7 mm,
/// area 40π, perimeter 20π, one hole, centroid (1, 2), inscribed circle radius 2.
io::MechanismFile toy_annulus_file();

/// A report's JSON text, parsed (the test fails on a parse error).
nlohmann::json parsed(const std::string& json_text);

/// A fresh, empty scratch directory for the current test (removed first if it exists).
std::filesystem::path fresh_dir();

/// Writes a toy annulus file (tests/toy_rp) `stroke[0] <= |P - base| <= stroke[1]`
/// as `dir/stem.json`; returns its path.
std::filesystem::path write_toy(const std::filesystem::path& dir, const std::string& stem, double base_x,
                                double base_y, double rho_min, double rho_max, const std::string& units = "mm");

/// Writes `text` to `path`; returns the path.
std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text);

/// The lines of `text` (without their line breaks).
std::vector<std::string> lines_of(const std::string& text);

}  // namespace pkmws::test
