// The fields a sweep file and an optimisation file share (the base file, a
// parameter's paths, the task polygon, the accuracy of the metrics), read by
// one set of functions so that both report the same one-line errors
// (docs/design_space.md). Private to the library.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_reader.hpp"
#include "pkmws/design/sweep.hpp"

namespace pkmws::design::reading {

/// Parses the JSON object of a spec file (`what`: "sweep", "optimisation")
/// or throws io::InputError naming the file.
nlohmann::json read_spec_file(const std::filesystem::path& file, const std::string& what);

/// `base` (relative to `dir`): sets spec.base_file and spec.base_document;
/// the base must load on its own. Returns the base document (for read_paths).
nlohmann::json read_base(io::detail::JsonReader& r, const std::filesystem::path& dir, SweepSpec& spec);

/// `path` of a parameter: one field path or an array of tied paths, each a
/// number of the base document; `name` defaults to the first path.
void read_paths(io::detail::JsonReader& p, nlohmann::json& base_document, SweepParameter& parameter);

/// `task`: {"center", "size"} or {"polygon"} (when present).
void read_task(io::detail::JsonReader& r, SweepSpec& spec);

/// `rectangle_precision`, `criteria_tolerance`, `interference_depth`, `gci_cells` (when present).
void read_accuracy(io::detail::JsonReader& r, SweepSpec& spec);

/// The base document with each parameter's paths set to `values` (as many
/// parameters as values are given); throws io::InputError naming the path.
nlohmann::json design_document(const SweepSpec& spec, const std::vector<double>& values);

}  // namespace pkmws::design::reading
