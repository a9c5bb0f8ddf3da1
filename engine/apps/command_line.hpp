// The command line of every executable, read the same way. CLI11's own errors (an unknown
// option, a missing required one, a value that does not convert or that a check refuses) are
// bad input like any other (apps/exit_codes.hpp): one line "<program>: error: <what>; see
// <program> --help" on stderr and exit code 2, instead of CLI11's codes (104, 105, 106, ...) and
// its two lines. --help prints the usage on stdout and exits 0.
//
//   if (const auto code = parse_command_line(app, argc, argv, "softpack-pack")) return *code;
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "apps/exit_codes.hpp"
#include "core/random.hpp"

namespace softpack {

/// Parses the command line; the exit code when the program must stop (0 after --help, 2 for
/// a bad command line), std::nullopt when it may go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, std::string_view program) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help (and --help-all): the usage, on stdout
    std::string what = e.what();
    for (char& c : what)
      if (c == '\n' || c == '\r') c = ' ';  // one line
    fmt::print(stderr, "{}: error: {}; see {} --help\n", program, what, program);
    return kExitInput;
  }
}

/// The check of a --seed option: a seed as core/random.hpp's parse_seed() reads it, exactly
/// (0 <= seed <= 2^63 - 1, decimal digits), before CLI11 converts it (which would clamp 2^64 to
/// 2^63 - 1 and accept "+3", " 3" or "0x10").
inline CLI::Validator seed_check() {
  return CLI::Validator(
      [](std::string& text) {
        std::string error;
        return parse_seed(text, error) ? std::string() : error;
      },
      "SEED");
}

}  // namespace softpack
