// Strict reading of one JSON object with the field's path in every error
// message. declare_fields() names every field the object may have and reports
// a key outside that list at once (before any "missing required field", so a
// misspelt key is named, with the valid ones); finish() reports fields that
// were never read. Private to the library.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/geometry/types.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::io::detail {

/// The deepest nesting of arrays and objects a mechanism file may have (the
/// format needs a handful of levels; deeper input is refused before it is built).
inline constexpr std::size_t max_json_depth = 64;

/// Parses a JSON text strictly: a duplicate key in an object is an error naming
/// the key's path ("legs[1].rod_length: duplicate key"), nesting deeper than
/// max_json_depth is an error naming where, and syntax errors give line and
/// column. Throws InputError (without the file's name). The parse is
/// iterative, so no input can exhaust the stack.
nlohmann::json parse_json_text(const std::string& text);

/// "field[i]": the path of an array element in messages.
inline std::string item(const std::string& field, std::size_t i) { return field + "[" + std::to_string(i) + "]"; }

class JsonReader {
 public:
  /// A finite number from a raw JSON value; errors name `where`.
  static double as_number(const nlohmann::json& value, const std::string& where);

  /// `path` names this object in messages ("" for the document, "legs[0]", ...).
  JsonReader(const nlohmann::json& object, std::string path);

  bool has(const std::string& key) const;
  /// Required fields (throw InputError when missing or of the wrong type).
  double number(const std::string& key);
  double positive(const std::string& key);      // > 0
  double non_negative(const std::string& key);  // >= 0
  int integer(const std::string& key);
  int sign(const std::string& key);             // -1 or +1
  std::string string(const std::string& key);
  std::string one_of(const std::string& key, const std::vector<std::string>& allowed);
  geometry::Point point(const std::string& key);           // [x, y]
  std::vector<geometry::Point> points(const std::string& key, std::size_t count);
  std::vector<double> numbers(const std::string& key, std::size_t count);
  /// [min, max] with min < max.
  std::array<double, 2> interval(const std::string& key);
  JsonReader object(const std::string& key);
  std::vector<JsonReader> objects(const std::string& key, std::size_t count);
  /// The raw value (marked as read).
  const nlohmann::json& raw(const std::string& key);

  /// Optional variants: std::nullopt when the key is absent.
  std::optional<double> optional_number(const std::string& key);
  std::optional<double> optional_positive(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);

  /// Declares the fields this object may have (in the order messages list
  /// them) and throws InputError naming the first key that is not one of them:
  /// "legs[1].rod_lenght: unknown field (expected one of: reference, ...)".
  /// Call it before reading any field.
  void declare_fields(std::vector<std::string> fields);

  /// Throws InputError naming the first field that was never read.
  void finish() const;

  /// "path.key" (or "key" at the top level).
  std::string field(const std::string& key) const;
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

 private:
  const nlohmann::json& get(const std::string& key);
  [[noreturn]] void unknown_field(const std::string& key) const;

  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
  std::vector<std::string> declared_;
};

}  // namespace pkmws::io::detail
