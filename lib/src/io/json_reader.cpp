#include "io/json_reader.hpp"

#include <algorithm>
#include <cmath>

namespace pkmws::io::detail {

JsonReader::JsonReader(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw InputError((path_.empty() ? std::string("document") : path_) +
                     ": expected a JSON object");
  }
}

std::string JsonReader::field(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void JsonReader::fail(const std::string& key, const std::string& problem) const {
  throw InputError(field(key) + ": " + problem);
}

bool JsonReader::has(const std::string& key) const { return object_.contains(key); }

const nlohmann::json& JsonReader::get(const std::string& key) {
  auto it = object_.find(key);
  if (it == object_.end()) fail(key, "missing required field");
  read_.insert(key);
  return *it;
}

const nlohmann::json& JsonReader::raw(const std::string& key) { return get(key); }

double JsonReader::as_number(const nlohmann::json& value, const std::string& where) {
  if (!value.is_number()) throw InputError(where + ": expected a number");
  const double v = value.get<double>();
  if (!std::isfinite(v)) throw InputError(where + ": expected a finite number");
  return v;
}

double JsonReader::number(const std::string& key) { return as_number(get(key), field(key)); }

double JsonReader::positive(const std::string& key) {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, "must be positive (got " + nlohmann::json(v).dump() + ")");
  return v;
}

double JsonReader::non_negative(const std::string& key) {
  const double v = number(key);
  if (v < 0.0) fail(key, "must not be negative (got " + nlohmann::json(v).dump() + ")");
  return v;
}

int JsonReader::integer(const std::string& key) {
  const auto& v = get(key);
  if (!v.is_number_integer() || v.get<long long>() != static_cast<long long>(v.get<int>())) {
    fail(key, "expected an integer");
  }
  return v.get<int>();
}

int JsonReader::sign(const std::string& key) {
  const auto& v = get(key);
  if (!v.is_number_integer() || (v != nlohmann::json(1) && v != nlohmann::json(-1))) {
    fail(key, "expected -1 or 1");
  }
  return v.get<int>();
}

std::string JsonReader::string(const std::string& key) {
  const auto& v = get(key);
  if (!v.is_string()) fail(key, "expected a string");
  return v.get<std::string>();
}

std::string JsonReader::one_of(const std::string& key, const std::vector<std::string>& allowed) {
  std::string v = string(key);
  for (const auto& a : allowed) {
    if (a == v) return v;
  }
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail(key, "unknown value \"" + v + "\" (expected one of: " + list + ")");
}

std::vector<double> JsonReader::numbers(const std::string& key, std::size_t count) {
  const auto& v = get(key);
  if (!v.is_array() || v.size() != count) {
    fail(key, "expected an array of " + std::to_string(count) + " numbers");
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i) {
    out.push_back(as_number(v[i], item(field(key), i)));
  }
  return out;
}

geometry::Point JsonReader::point(const std::string& key) {
  const auto v = numbers(key, 2);
  return {v[0], v[1]};
}

std::vector<geometry::Point> JsonReader::points(const std::string& key, std::size_t count) {
  const auto& v = get(key);
  if (!v.is_array() || v.size() != count) {
    fail(key, "expected an array of " + std::to_string(count) + " points [x, y]");
  }
  std::vector<geometry::Point> out;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string where = item(field(key), i);
    if (!v[i].is_array() || v[i].size() != 2) throw InputError(where + ": expected [x, y]");
    out.push_back({as_number(v[i][0], where + "[0]"), as_number(v[i][1], where + "[1]")});
  }
  return out;
}

std::array<double, 2> JsonReader::interval(const std::string& key) {
  const auto v = numbers(key, 2);
  if (!(v[0] < v[1])) fail(key, "expected [min, max] with min < max");
  return {v[0], v[1]};
}

JsonReader JsonReader::object(const std::string& key) {
  const auto& v = get(key);
  if (!v.is_object()) fail(key, "expected an object");
  return JsonReader(v, field(key));
}

std::vector<JsonReader> JsonReader::objects(const std::string& key, std::size_t count) {
  const auto& v = get(key);
  if (!v.is_array() || v.size() != count) {
    fail(key, "expected an array of " + std::to_string(count) + " objects");
  }
  std::vector<JsonReader> out;
  for (std::size_t i = 0; i < count; ++i) {
    out.emplace_back(v[i], item(field(key), i));
  }
  return out;
}

std::optional<double> JsonReader::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

std::optional<double> JsonReader::optional_positive(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return positive(key);
}

std::optional<std::string> JsonReader::optional_string(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

void JsonReader::unknown_field(const std::string& key) const {
  std::string list;
  for (const auto& f : declared_) list += (list.empty() ? "" : ", ") + f;
  throw InputError(field(key) + ": unknown field" + (list.empty() ? "" : " (expected one of: " + list + ")"));
}

void JsonReader::declare_fields(std::vector<std::string> fields) {
  declared_ = std::move(fields);
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (std::find(declared_.begin(), declared_.end(), it.key()) == declared_.end()) unknown_field(it.key());
  }
}

void JsonReader::finish() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (!read_.count(it.key())) unknown_field(it.key());
  }
}

}  // namespace pkmws::io::detail
