// Exceptions that carry a message meant for the user: which file, which key, which value,
// and what is allowed. Executables print what() and exit non-zero.
#pragma once
#include <stdexcept>
#include <string>

namespace softpack {

/// Bad input: a configuration key, value or file that the user must fix.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace softpack
