// The one-line error a mechanism document gives when parsed ("" when it loads).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "io/document.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::test {

inline std::string load_error(const nlohmann::json& doc) {
  try {
    (void)io::parse_mechanism(doc, "test");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace pkmws::test
