// What every executable does with an error that ends it: one line on stderr, prefixed with the
// program's name, and an exit code that tells the kind (README, "Running a scene"):
//   2  bad input (InputError: a file, key or value; the message names it)
//   3  numerical error (NumericalError: the watchdog stopped a run, sim/watchdog.hpp)
//   2  also: an output that cannot be written (std::system_error: a full disk, stdout included)
//   1  internal error (anything else: a bug)
// Call it inside a catch (...) block: it rethrows the exception in flight to classify it.
#pragma once
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string_view>
#include <system_error>

#include "core/error.hpp"

namespace softpack {

enum ExitCode : int { kExitInternal = 1, kExitInput = 2, kExitNumerical = 3 };

/// Writes `text` on stderr and never throws: the message of an error must not itself fail (a
/// full disk behind a redirected stderr made fmt::print throw inside the handler: exit 134).
inline void say_on_stderr(std::string_view text) noexcept {
  if (!text.empty()) (void)std::fwrite(text.data(), 1, text.size(), stderr);
  (void)std::fflush(stderr);
}

inline int exit_on_error(std::string_view program) {
  const auto say = [&](std::string_view kind, std::string_view what) {
    try {
      say_on_stderr(fmt::format("{}: {}: {}\n", program, kind, what));
    } catch (...) {  // no memory for the message: the kind alone
      say_on_stderr(kind);
    }
  };
  try {
    throw;
  } catch (const InputError& e) {
    say("error", e.what());
    return kExitInput;
  } catch (const NumericalError& e) {  // no output file is written after it
    say("numerical error", e.what());
    return kExitNumerical;
  } catch (const std::system_error& e) {  // an output that could not be written (a full disk, a closed pipe)
    say("error", e.what());
    return kExitInput;
  } catch (const std::exception& e) {
    say("internal error", e.what());
    return kExitInternal;
  } catch (...) {
    say("internal error", "unknown exception");
    return kExitInternal;
  }
}

/// What every command's exit passes through (softpack.cpp): a command that succeeded but whose
/// standard output could not be written (`softpack-run > report.json` on a full disk) has
/// failed: its message, exit 2, instead of exit 0 with a short or empty report.
inline int checked_exit(std::string_view program, int code) noexcept {
  std::cout.flush();
  if (std::fflush(stdout) == 0 && !std::ferror(stdout) && std::cout.good()) return code;
  const int err = errno;
  try {
    say_on_stderr(fmt::format("{}: error: standard output: cannot write ({})\n", program, std::strerror(err)));
  } catch (...) {
  }
  return code == 0 ? kExitInput : code;
}

}  // namespace softpack
