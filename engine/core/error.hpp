// Exceptions that carry a message meant for the user: which file, which key, which value,
// and what is allowed. Executables print what() and exit non-zero:
//
//   exit 2  InputError      "softpack-<name>: error: ..."            bad input, the user must fix it
//   exit 3  NumericalError  "softpack-<name>: numerical error: ..."  the run went wrong (sim/watchdog.hpp)
//   exit 1  anything else   "softpack-<name>: internal error: ..."
#pragma once
#include <stdexcept>
#include <string>

namespace softpack {

/// Bad input: a configuration key, value or file that the user must fix.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// `e` as an error of the file `path`: its message prefixed with the path, unless it already
/// starts with it (a reader that placed it, with line and column).
inline InputError in_file(const std::string& path, const InputError& e) {
  const std::string msg = e.what();
  return InputError(msg.rfind(path, 0) == 0 ? msg : path + ": " + msg);
}

/// The simulation left the physical regime (a non-finite value, an overlap beyond the allowed
/// fraction of a radius, an energy blow-up): the run stops before it writes wrong results. The
/// message is the watchdog's diagnostic: step, time, sphere ids, overlap, dt and its stable limit.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace softpack
