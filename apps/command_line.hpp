// The command line of every executable, read the same way. CLI11's own errors (an unknown
// option, a missing required one, a value that does not convert or that a check refuses) are
// bad input like any other (apps/exit_codes.hpp): one line "<program>: error: <what>; see
// <program> --help" on stderr and exit code 2, instead of CLI11's codes (104, 105, 106, ...) and
// its two lines. --help prints the usage on stdout and exits 0.
//
// No output option (--out, --vtp, --xyz, --gnuplot) may name a file another option reads.
//
//   if (const auto code = parse_command_line(app, argc, argv, "softpack-pack")) return *code;
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"

namespace softpack {

/// The options that name a file the command writes (--out-dir, a folder, is checked by the
/// commands that write into one).
inline bool is_output_option(const CLI::Option& o) {
  return o.check_lname("out") || o.check_lname("vtp") || o.check_lname("xyz") || o.check_lname("gnuplot");
}

/// An output never overwrites one of the command's own inputs (`softpack-normal --packing p.h5
/// --out p.h5` destroyed its packing, exit 0): the exit code 2, with one line naming both options,
/// when a file an output option names is (by path or by inode) an existing file another option
/// names; std::nullopt when all are apart. The command's subcommands too.
inline std::optional<int> check_outputs_apart(const CLI::App& app, std::string_view program) {
  std::vector<std::pair<const CLI::Option*, std::string>> outputs, inputs;
  const auto collect = [&](const CLI::App& a, const auto& self) -> void {
    for (const CLI::Option* o : a.get_options())
      for (const std::string& value : o->results()) (is_output_option(*o) ? outputs : inputs).emplace_back(o, value);
    for (const CLI::App* sub : a.get_subcommands()) self(*sub, self);
  };
  collect(app, collect);
  for (const auto& [out, out_path] : outputs)
    for (const auto& [in, in_path] : inputs) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(in_path, ec)) continue;
      if (in_path == out_path || std::filesystem::equivalent(in_path, out_path, ec)) {
        fmt::print(stderr, "{}: error: {} {}: the same file as {} {}, which this command reads; an output never overwrites an "
                   "input: give it another name\n",
                   program, out->get_name(), out_path, in->get_name(), in_path);
        return kExitInput;
      }
    }
  return std::nullopt;
}

/// No value on the command line holds a control character: a path with a line break was written
/// into the comment lines of the .dat files gnuplot reads, where it began a data row. The exit
/// code 2 with one line naming the option; std::nullopt when every value is clean.
inline std::optional<int> check_no_control_characters(const CLI::App& app, std::string_view program) {
  const auto check = [&](const CLI::App& a, const auto& self) -> std::optional<int> {
    for (const CLI::Option* o : a.get_options())
      for (const std::string& value : o->results())
        for (std::size_t i = 0; i < value.size(); ++i)
          if (const auto c = static_cast<unsigned char>(value[i]); c < 0x20 || c == 0x7f) {
            fmt::print(stderr, "{}: error: {}: the value holds a control character (byte {} is 0x{:02x}{}); allowed: paths and names "
                       "without control characters\n",
                       program, o->get_name().empty() ? "an argument" : o->get_name(), i + 1, c, c == '\n' ? ", a line break" : "");
            return kExitInput;
          }
    for (const CLI::App* sub : a.get_subcommands())
      if (const auto code = self(*sub, self)) return code;
    return std::nullopt;
  };
  return check(app, check);
}

/// Parses the command line; the exit code when the program must stop (0 after --help, 2 for
/// a bad command line), std::nullopt when it may go on.
/// --threads N: the engine's threads for this command (core/parallel.hpp), over SOFTPACK_THREADS;
/// for the commands that run simulations. The result bits do not depend on them.
inline CLI::Option* add_threads_option(CLI::App& app) {
  return app
      .add_option_function<int>(
          "--threads", [](const int& n) { parallel::set_threads(n); },
          fmt::format("threads of the engine (default: SOFTPACK_THREADS, else the cores this process may use, one per {} spheres at "
                      "most, 1 under make -j; the results are the same bits for any count)",
                      parallel::kSpheresPerThread))
      ->check(CLI::Range(1, 1024));
}

/// SOFTPACK_THREADS read now, so that a bad value stops the command before it runs (the engine
/// reads it at its first threaded loop, which a small scene never reaches).
inline std::optional<int> check_threads(std::string_view program) {
  try {
    parallel::threads();
  } catch (const InputError& e) {
    fmt::print(stderr, "{}: error: {}\n", program, e.what());
    return kExitInput;
  }
  return std::nullopt;
}

inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, std::string_view program) {
  try {
    app.parse(argc, argv);
    if (const auto code = check_no_control_characters(app, program)) return code;
    if (const auto code = check_threads(program)) return code;
    return check_outputs_apart(app, program);
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
