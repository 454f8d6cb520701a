// Text helpers shared by the SVG, DXF and chart writers. Private.
#pragma once

#include <string>
#include <string_view>

namespace pkmws::io::detail {

/// Escapes &, <, > and " for XML text and attribute values.
inline std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace pkmws::io::detail
