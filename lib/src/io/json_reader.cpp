#include "io/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace pkmws::io::detail {

nlohmann::json parse_json_text(const std::string& text) {
  // The callback sees every event of nlohmann's (iterative) parser; a stack of
  // open containers gives each error its path and each object its key set.
  struct Open {
    bool array = false;
    std::size_t index = 0;  // arrays: the element being read
    std::string key;        // objects: the member being read
    std::set<std::string> keys;
  };
  std::vector<Open> open;
  auto path = [&open](const std::string& last_key) {
    std::string p;
    for (std::size_t i = 0; i < open.size(); ++i) {
      const bool top = i + 1 == open.size();
      if (open[i].array) {
        p += "[" + std::to_string(open[i].index) + "]";
      } else {
        p += (p.empty() ? "" : ".") + (top && !last_key.empty() ? last_key : open[i].key);
      }
    }
    return p.empty() ? std::string("document") : p;
  };
  auto element_done = [&open] {
    if (!open.empty() && open.back().array) ++open.back().index;
  };
  using Event = nlohmann::json::parse_event_t;
  auto callback = [&](int /*depth*/, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (open.size() >= max_json_depth) {
          std::string where = path("");
          if (where.size() > 60) where = where.substr(0, 28) + "..." + where.substr(where.size() - 28);
          throw InputError(where + ": nested deeper than " + std::to_string(max_json_depth) +
                           " levels of arrays and objects");
        }
        open.push_back({event == Event::array_start, 0, {}, {}});
        break;
      case Event::key: {
        std::string k = parsed.get<std::string>();
        if (!open.back().keys.insert(k).second) throw InputError(path(k) + ": duplicate key");
        open.back().key = std::move(k);
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        element_done();
        break;
      case Event::value:
        element_done();
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, callback);
  } catch (const nlohmann::json::exception& e) {  // syntax errors, numbers out of range
    // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    const std::string what = e.what();
    const auto pos = what.find("] ");
    throw InputError("malformed JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
  }
}

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
