// The parameter model (pkmws/io/parameters.hpp).
#include "pkmws/io/parameters.hpp"

#include "io/document.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace pkmws::io {

namespace {

using nlohmann::json;

// A file path "legs[1].rod_length" as keys and indices.
struct Step {
  std::string key;  // empty: an array index
  std::size_t index = 0;
};

std::vector<Step> parse_path(const std::string& path, const std::string& where) {
  std::vector<Step> steps;
  std::size_t i = 0;
  const auto bad = [&] { throw InputError(where + ": '" + path + "' is not a field path like legs[1].rod_length"); };
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) bad();
      const std::string digits = path.substr(i + 1, close - i - 1);
      if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) bad();
      steps.push_back({"", std::stoul(digits)});
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    std::size_t end = path.find_first_of(".[", i);
    if (end == std::string::npos) end = path.size();
    if (end == i) bad();
    steps.push_back({path.substr(i, end - i), 0});
    i = end;
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size()) bad();
    }
  }
  if (steps.empty()) bad();
  return steps;
}

template <class Json>
Json& walk_path(Json& document, const std::string& path, const std::string& where, const std::string& missing) {
  const std::vector<Step> steps = parse_path(path, where);
  Json* node = &document;
  for (const Step& s : steps) {
    if (s.key.empty()) {
      if (!node->is_array() || s.index >= node->size()) throw InputError(where + ": '" + path + "' " + missing);
      node = &node->at(s.index);
    } else {
      if (!node->is_object() || !node->contains(s.key)) throw InputError(where + ": '" + path + "' " + missing);
      node = &node->at(s.key);
    }
  }
  return *node;
}

}  // namespace

json& field_at(json& document, const std::string& path, const std::string& where, const std::string& missing) {
  return walk_path(document, path, where, missing);
}

const json& field_at(const json& document, const std::string& path, const std::string& where,
                     const std::string& missing) {
  return walk_path(document, path, where, missing);
}


namespace {

// The unit of a number from its field name (docs/format.md's unit columns;
// tests/python/test_parameters.py checks them against those tables).
std::string unit_of(const std::string& key, const std::string& length) {
  static const std::set<std::string> dimensionless = {"branch", "working_mode", "sense", "reaction_legs", "k",
                                                      "max_velocity_ratio", "max_condition_number", "efficiency"};
  auto ends = [&](const char* suffix) {
    const std::string s(suffix);
    return key.size() >= s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0;
  };
  if (dimensionless.count(key)) return "1";
  if (ends("_deg")) return "deg";
  if (ends("_Nm")) return "N m";
  if (ends("_N")) return "N";
  if (key == "max_speed") return length + "/s";
  return length;
}

bool integer_field(const std::string& key) {
  return key == "branch" || key == "working_mode" || key == "sense" || key == "reaction_legs";
}

void collect(const json& node, const std::string& path, const std::string& key, const std::string& length,
             std::vector<Parameter>& out) {
  if (node.is_object()) {
    for (const auto& [k, v] : node.items()) {
      if (path.empty() && k == "source") continue;  // free-form notes, not parameters
      collect(v, path.empty() ? k : path + "." + k, k, length, out);
    }
  } else if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i) collect(node[i], path + "[" + std::to_string(i) + "]", key, length, out);
  } else if (node.is_number()) {
    out.push_back({path, node.get<double>(), integer_field(key) ? "integer" : "number", unit_of(key, length)});
  }
}

}  // namespace

std::vector<Parameter> parameters(const MechanismFile& file) {
  std::vector<Parameter> out;
  collect(document_json(file), "", "", file.units, out);
  return out;
}

double parameter(const MechanismFile& file, const std::string& path) {
  const json& node = field_at(document_json(file), path, file.path, "is not a field of the file");
  if (!node.is_number()) throw InputError(file.path + ": '" + path + "' is not a number of the file");
  return node.get<double>();
}

Parameter parameter_info(const MechanismFile& file, const std::string& path) {
  (void)parameter(file, path);  // its errors: not a field path, not a number
  for (Parameter& p : parameters(file)) {
    if (p.path == path) return p;
  }
  throw InputError(file.path + ": '" + path + "' is not a parameter of the file (e.g. a number in `source`)");
}

MechanismFile with_parameters(const MechanismFile& file, const std::vector<std::pair<std::string, double>>& values) {
  json doc = document_json(file);
  for (const auto& [path, value] : values) {
    json& node = field_at(doc, path, file.path, "is not a field of the file");
    if (!node.is_number()) throw InputError(file.path + ": '" + path + "' is not a number of the file");
    if (!std::isfinite(value)) throw InputError(file.path + ": '" + path + "': must be a finite number");
    if (node.is_number_integer() && value == std::floor(value) && std::abs(value) < 9.0e15) {
      node = static_cast<long long>(value);
    } else {
      node = value;
    }
  }
  try {
    return parse_mechanism(doc, file.path);
  } catch (const InputError& e) {
    throw InputError(file.path + ": " + e.what());
  }
}

MechanismFile with_parameter(const MechanismFile& file, const std::string& path, double value) {
  return with_parameters(file, {{path, value}});
}

}  // namespace pkmws::io
