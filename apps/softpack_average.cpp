// softpack-average: mean and standard error over the seeds of one scene's sweep results
// (analysis/average.hpp), to the average files: HDF5 for softpack-fit, text columns for gnuplot
// (formats/average_file.hpp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <optional>

#include "analysis/average.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "core/stopwatch.hpp"
#include "core/error.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/version.hpp"
#include "formats/average_file.hpp"
#include "formats/sweep_file.hpp"
#include "packing/packing_profile.hpp"

namespace softpack::apps::average_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-average: average the sweep results of one scene over the seeds"};
  AverageProvenance p;
  std::string out_dir;
  app.add_option("--scene", p.scene, "soft-solid or soft-soft (recorded)")->required();
  app.add_option("--profile", p.profile, "profile name (recorded)")->required();
  app.add_option("--normal", p.normal_inputs, "normal results of every seed")->required();
  app.add_option("--tangential", p.tangential_inputs, "tangential results of every seed (left out: a normal-only profile)");
  std::string config_path;
  app.add_option("--config", config_path,
                 "the profile the results must have been computed with (make gives it); without it, they must agree with "
                 "each other");
  app.add_option("--out-dir", out_dir,
                 "writes <scene>.h5, normal-<scene>.dat, tangential-<scene>.dat, kt-<scene>.dat (the last two with --tangential)")
      ->required();
  if (const auto code = parse_command_line(app, argc, argv, "softpack-average")) return *code;
  try {
    const Stopwatch watch;
    if (p.scene != "soft-solid" && p.scene != "soft-soft")
      throw InputError(fmt::format("--scene: '{}' is not allowed; allowed: soft-solid, soft-soft", p.scene));
    std::optional<ConfigNode> root;
    if (!config_path.empty()) {
      root = ConfigNode::load_file(config_path);
      p.stamp = profile_stamp(*root, "average");
    }
    // The columns of each seed the averages read: each seed once, of one packing each, all of one
    // configuration (with --config, the profile's).
    const auto read = [&](const std::vector<std::string>& paths, const std::string& stage, std::vector<SeedFile>& files) {
      std::vector<SweepColumns> columns;
      for (const auto& path : paths) {
        SweepResults r = read_sweep_results_file(path, stage, p.scene);
        files.push_back({path, r.seed, recorded_stage_text(r.provenance.config), r.provenance.stamp, r.packing_sha256});
        columns.push_back(std::move(r));
      }
      check_distinct_seeds(files, "--" + stage);
      if (root)
        check_one_configuration(files, "--" + stage, stage, stage_text(*root, stage), profile_stamp(*root, stage), config_path);
      else
        check_one_configuration(files, "--" + stage, stage);
      return columns;
    };
    std::vector<SeedFile> normal_files, tangential_files;
    const std::vector<SweepColumns> normal = read(p.normal_inputs, "normal", normal_files);
    const NormalAverage n = average_normal(normal);
    std::optional<TangentialAverage> t;
    if (!p.tangential_inputs.empty()) {
      const std::vector<SweepColumns> tangential = read(p.tangential_inputs, "tangential", tangential_files);
      check_same_seeds(normal_files, tangential_files);
      t = average_tangential(tangential);
    }
    p.code_version = code_version();
    p.seconds = watch.elapsed().wall;
    p.cpu_seconds = process_cpu_seconds();
    write_average_files(out_dir, n, t ? &*t : nullptr, p);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-average");
  }
}

}  // namespace softpack::apps::average_app
