// The one error type for bad input, shared by every layer: the loader, the
// parameter model, the analyses that refuse a question ("not available for
// this mechanism") and the command line, which prints it as one line and
// exits with status 2.
#pragma once

#include <stdexcept>

namespace pkmws {

/// Bad input: the message is one line naming the problem (and the field path).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pkmws
