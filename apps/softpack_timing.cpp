// softpack-timing: where the time of a profile's last run went, per stage and per phase of the
// sweeps' points (report/stage_timing.hpp), from what each output records in its provenance.
// `make timing` passes it the files of the profile.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "report/stage_timing.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "io/atomic_file.hpp"

namespace softpack::apps::timing_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-timing: the wall-clock and CPU time of a profile's outputs, per stage and phase"};
  TimingInputs in;
  std::string title = "Time of the run", json_path;
  CLI::Option_group* files = app.add_option_group("files", "the outputs to time (at least one)");
  files->add_option("--packings", in.packings, "packing files (softpack-pack)");
  files->add_option("--normal", in.normal, "normal sweep results files");
  files->add_option("--tangential", in.tangential, "tangential sweep results files");
  files->add_option("--averages", in.averages, "average files (HDF5, softpack-average)");
  files->add_option("--fits", in.fits, "fit files (JSON, softpack-fit)");
  files->require_option(1, 0);
  app.add_option("--title", title, "first line of the table");
  app.add_option("--json", json_path, "also write the numbers as JSON to this file");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-timing")) return *code;
  try {
    const ProfileTiming t = collect_timing(in);
    fmt::print("{}", timing_table(t, title));
    if (!json_path.empty()) write_file_atomically(json_path, timing_json(t));
    return 0;
  } catch (...) {
    return exit_on_error("softpack-timing");
  }
}

}  // namespace softpack::apps::timing_app
