#include "pkmws/io/mechanism_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "io/document.hpp"
#include "io/load_bodies.hpp"
#include "io/registry.hpp"

namespace pkmws::io {

namespace {

using detail::find_kind;
using detail::kinds;

// The top-level fields a document may have: the common ones and its kind's, or
// every kind's when `mechanism` does not name one (its own error comes next).
std::vector<std::string> top_level_fields(const nlohmann::json& document) {
  std::vector<std::string> fields = {"name", "mechanism", "units", "description", "source", "criteria"};
  auto add = [&](const std::vector<std::string>& more) {
    for (const auto& f : more) {
      if (std::find(fields.begin(), fields.end(), f) == fields.end()) fields.push_back(f);
    }
  };
  const auto m = document.find("mechanism");
  const detail::Kind* kind = m != document.end() && m->is_string() ? find_kind(m->get<std::string>()) : nullptr;
  if (kind) {
    add(kind->fields);
  } else {
    for (const auto& k : kinds()) add(k.fields);
  }
  add({"bodies"});
  return fields;
}

mechanisms::Criteria read_criteria(detail::JsonReader& doc, std::vector<int>& reaction_legs) {
  mechanisms::Criteria c;
  if (!doc.has("criteria")) return c;
  auto r = doc.object("criteria");
  r.declare_fields({"max_pressure_angle_deg", "max_reaction_N", "load", "max_velocity_ratio", "max_condition_number",
                    "characteristic_length", "reaction_legs", "min_singularity_distance"});
  if (r.has("reaction_legs")) {
    const auto& v = r.raw("reaction_legs");
    if (!v.is_array() || v.empty()) r.fail("reaction_legs", "expected a non-empty list of leg numbers (1-based)");
    for (const auto& e : v) {
      if (!e.is_number_integer() || e.get<long long>() < 1 || e.get<long long>() > 3) {
        r.fail("reaction_legs", "expected leg numbers 1, 2 or 3");
      }
      reaction_legs.push_back(static_cast<int>(e.get<long long>()));
    }
  }
  if (r.has("max_pressure_angle_deg")) {
    const double a = r.number("max_pressure_angle_deg");
    if (!(a > 0.0 && a < 90.0)) r.fail("max_pressure_angle_deg", "must lie in (0, 90) degrees");
    c.max_pressure_angle_deg = a;
  }
  c.max_reaction_N = r.optional_positive("max_reaction_N");
  c.max_velocity_ratio = r.optional_positive("max_velocity_ratio");
  if (r.has("max_condition_number")) {
    const double k = r.number("max_condition_number");
    if (!(k >= 1.0) || !std::isfinite(k)) r.fail("max_condition_number", "must be at least 1 (a condition number is >= 1)");
    c.max_condition_number = k;
  }
  c.characteristic_length = r.optional_positive("characteristic_length");
  if (r.has("min_singularity_distance")) {
    const double d = r.number("min_singularity_distance");
    if (!(d > 0.0) || !std::isfinite(d)) {
      r.fail("min_singularity_distance", "must be a positive length in the file's units (the distance from P to the "
                                         "type-2 singular curve)");
    }
    c.min_singularity_distance = d;
  }
  if (r.has("load")) {
    auto l = r.object("load");
    l.declare_fields({"force_N", "moment_Nm"});
    mechanisms::Load load;
    load.force_N = l.non_negative("force_N");
    load.moment_Nm = l.has("moment_Nm") ? l.non_negative("moment_Nm") : 0.0;
    l.finish();
    c.load = load;
  }
  if (c.max_reaction_N && !c.load) r.fail("max_reaction_N", "needs criteria.load");
  r.finish();
  return c;
}

}  // namespace

MechanismFile parse_mechanism(const nlohmann::json& document, const std::string& origin) {
  detail::JsonReader doc(document, "");
  doc.declare_fields(top_level_fields(document));
  MechanismFile file;
  file.path = origin;
  file.document = std::make_shared<const Document>(Document{document});
  file.name = doc.string("name");
  std::vector<std::string> names;
  for (const auto& k : kinds()) names.push_back(k.keyword);
  file.mechanism = doc.one_of("mechanism", names);
  file.units = doc.one_of("units", {"mm", "m"});
  file.description = doc.optional_string("description").value_or("");
  if (doc.has("source")) {
    const auto& s = doc.raw("source");
    if (!s.is_object() && !s.is_string()) doc.fail("source", "expected an object or a string");
    file.source = s.dump();
  }
  file.criteria = read_criteria(doc, file.reaction_legs);
  file.model = find_kind(file.mechanism)->load(doc);
  if (doc.has("bodies")) file.bodies = detail::load_bodies(doc, file.model);
  if (file.criteria.characteristic_length && file.model->dof() != 3) {
    throw InputError("criteria.characteristic_length: applies to the 3-DOF mechanisms (three_rpr, three_rrp, "
                     "three_prp), not " + file.mechanism);
  }
  for (int leg : file.reaction_legs) {
    if (leg > file.model->dof() || file.model->dof() < 2) {
      throw InputError("criteria.reaction_legs: leg " + std::to_string(leg) + " does not exist (the mechanism has " +
                       std::to_string(file.model->dof() < 2 ? 1 : file.model->dof()) + " legs)");
    }
  }
  doc.finish();
  return file;
}

MechanismFile parse_mechanism_text(std::string_view json_text, const std::string& origin) {
  nlohmann::json document;
  try {
    document = detail::parse_json_text(std::string(json_text));
  } catch (const InputError& e) {
    throw InputError(origin + ": " + e.what());
  }
  try {
    return parse_mechanism(document, origin);
  } catch (const InputError& e) {
    throw InputError(origin + ": " + e.what());
  }
}

const nlohmann::json& document_json(const MechanismFile& file) {
  static const nlohmann::json none;
  return file.document ? file.document->json : none;
}

std::string document_text(const MechanismFile& file) { return document_json(file).dump(); }

nlohmann::json source_json(const MechanismFile& file) {
  return file.source.empty() ? nlohmann::json() : nlohmann::json::parse(file.source);
}

MechanismFile load_mechanism(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(path.string() + ": no such file");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path.string() + ": is a directory, expected a mechanism file");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_mechanism_text(buffer.str(), path.string());
}

}  // namespace pkmws::io
