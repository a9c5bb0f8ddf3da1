// The command line of softpack-normal, softpack-tangential and softpack-sliding: the same options
// (--hertz-check for the normal and sliding stages, --normal-checkpoints for the tangential and
// sliding ones), then
// run_stage (measure/stage.hpp) with a progress line per point (with the time left), a summary
// line, and the exit codes of apps/exit_codes.hpp (apps/command_line.hpp for the command line's).
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "measure/stage.hpp"

namespace softpack {

inline int stage_main(int argc, char** argv, const std::string& stage) {
  StageOptions o;
  o.stage = stage;
  bool quiet = false;
  CLI::App app{"softpack-" + stage + ": the " + stage + " contact-law sweep of one scene and one seed"};
  app.add_option("--config", o.config_path, "profile file, e.g. experiments/paper.yaml")->required();
  app.add_option("--scene", o.scene, "soft-solid or soft-soft")->required();
  app.add_option("--seed", o.seed, "seed of this measurement (recorded in the results), 0 <= seed <= 2^63 - 1")
      ->required()
      ->check(seed_check());
  app.add_option("--packing", o.packing, "packing file of the first soft-particle");
  app.add_option("--second-packing", o.second_packing, "soft-soft: packing file of the second soft-particle (another seed)");
  app.add_option("--checkpoints", o.checkpoints, "directory of this stage's point files (resume from them)")->required();
  if (stage != "tangential")
    app.add_flag("--hertz-check", o.hertz_check, "replace the soft-particle by one solid sphere of radius Rs (validation)");
  if (stage != "normal")
    app.add_option("--normal-checkpoints", o.normal_checkpoints,
                   stage == "tangential" ? "point files of the normal stage (its states are sheared)"
                                         : "point files of the normal stage (its states are slid)")
        ->required();
  app.add_option("--out", o.out, "results file (HDF5)")->required();
  app.add_option("--stamp", o.stamp,
                 "the stage's stamp make planned this run with (softpack-config PROFILE stamp " + stage +
                     "): refused when the profile has changed since");
  app.add_flag("--quiet", quiet, "no progress lines");
  add_threads_option(app);
  app.add_option("--stop-after", o.stop_after, "stop after this many new points (tests of the resume)")->group("");
  const std::string program = "softpack-" + stage;
  if (const auto code = parse_command_line(app, argc, argv, program)) return *code;

  // On a terminal each progress line replaces the previous one; in a log they follow each other.
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  bool line_open = false;  // a progress line waits for its newline (terminal)
  double computed_seconds = 0.0, last_seconds = 0.0;
  std::size_t computed = 0;
  std::string last_stage = stage;
  const auto progress = [&](const std::string& of, std::size_t k, std::size_t n, const PointResult& r, bool reused) {
    if (of != last_stage) computed_seconds = 0.0, computed = 0, last_stage = of;  // the time left of each sweep
    if (!reused) computed_seconds += r.seconds(), last_seconds = r.seconds(), ++computed;
    if (quiet || (reused && of != stage)) return;  // normal states the tangential stage reuses: not worth a line
    // The points get slower as the contact deepens: the time left at the pace of the last point
    // (or of the mean, if that is slower), not of the mean alone, which ran ahead by half.
    const double pace = computed ? std::max(computed_seconds / static_cast<double>(computed), last_seconds) : 0.0;
    const double eta = pace * static_cast<double>(n - k - 1);
    // The relaxation's force ratio (residual over mean contact force) says how well a loaded point
    // came to rest; before the wall carries anything it is no measure of that, so it is not shown.
    const std::string ratio = r.force.x() == 0.0 && r.force.y() == 0.0 ? std::string(", not loaded yet")
                              : r.checks.empty()                     ? std::string()
                                                                     : fmt::format(", force ratio {:.1e}", r.checks.back().residuals.force_ratio());
    const std::string what = of == "normal"    ? fmt::format("{}delta_n {:.4f}", of != stage ? "normal state " : "", r.delta_n)
                             : of == "sliding" ? fmt::format("delta_n {:.4f} ht {:.3e} m", r.delta_n, r.ht)
                                               : fmt::format("delta_n {:.4f} alpha {:+.3f} deg", r.delta_n, r.alpha_deg);
    const std::string awake = r.awake_fraction ? fmt::format(", {:.0f}% awake", 100.0 * *r.awake_fraction) : "";
    fmt::print(stderr, "{}{} {} seed {}: point {}/{} {}: Fn {:.4e} N, Ft {:+.3e} N{}{}{}{}", tty ? "\r\033[K" : "",
               program, o.scene, o.seed, k + 1, n, what, r.force.x(), r.force.y(), ratio, awake,
               reused ? " (checkpoint)" : fmt::format(", {:.1f} s, ETA {:.0f} s", r.seconds(), eta), tty ? "" : "\n");
    line_open = tty;
  };
  try {
    const StageSummary s = run_stage(o, progress);
    if (!quiet && tty) fmt::print(stderr, "\n");
    if (quiet) return 0;
    if (s.stopped)
      fmt::print(stderr, "{}: stopped after {} new points as asked\n", program, o.stop_after);
    else
      fmt::print(stderr, "{}: {} points in {:.1f} s -> {}\n", program, s.points, s.seconds, o.out);
    return 0;
  } catch (...) {
    if (line_open) fmt::print(stderr, "\n");
    return exit_on_error(program);
  }
}

}  // namespace softpack
