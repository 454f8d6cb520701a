// The text side of the reports, private to the library: printf into a string.
#pragma once

#include <string>

namespace pkmws::report::detail {

/// printf's formatting into a std::string (any length).
[[gnu::format(printf, 1, 2)]] std::string format(const char* fmt, ...);

}  // namespace pkmws::report::detail
