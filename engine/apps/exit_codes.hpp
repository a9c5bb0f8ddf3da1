// What every executable does with an error that ends it: one line on stderr, prefixed with the
// program's name, and an exit code that tells the kind (README, "Running a scene"):
//   2  bad input (InputError: a file, key or value; the message names it)
//   3  numerical error (NumericalError: the watchdog stopped a run, sim/watchdog.hpp)
//   1  internal error (anything else: a bug)
// Call it inside a catch (...) block: it rethrows the exception in flight to classify it.
#pragma once
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string_view>

#include "core/error.hpp"

namespace softpack {

enum ExitCode : int { kExitInternal = 1, kExitInput = 2, kExitNumerical = 3 };

inline int exit_on_error(std::string_view program) {
  try {
    throw;
  } catch (const InputError& e) {
    fmt::print(stderr, "{}: error: {}\n", program, e.what());
    return kExitInput;
  } catch (const NumericalError& e) {  // no output file is written after it
    fmt::print(stderr, "{}: numerical error: {}\n", program, e.what());
    return kExitNumerical;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: internal error: {}\n", program, e.what());
    return kExitInternal;
  } catch (...) {
    fmt::print(stderr, "{}: internal error: unknown exception\n", program);
    return kExitInternal;
  }
}

}  // namespace softpack
