// softpack-coarse's LAMMPS subcommands (issue 34, docs/lammps.md), apart from softpack_coarse.cpp:
//
//   softpack-coarse export --lammps --config C --medium M --out DIR
//       the soft model of medium M and its compression as a LAMMPS input (coarse/lammps_export.hpp);
//   softpack-coarse lammps-curve --config C --medium M --dir DIR --out F.h5
//       that run read back (DIR/curve.dat, DIR/log.lammps) as a results file of the soft model, the
//       engine's layout (coarse/result_file.hpp), for the comparison with the engine's runs.
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <string>

#include "coarse/lammps_export.hpp"
#include "coarse/result_file.hpp"
#include "core/error.hpp"

namespace softpack::apps::coarse_app {

struct LammpsCommands {
  CLI::App* export_cmd = nullptr;
  CLI::App* curve_cmd = nullptr;
  std::string config, medium, out, dir;
  bool lammps = false;

  void add(CLI::App& app) {
    export_cmd = app.add_subcommand("export", "a medium's soft model and its compression for another engine: --lammps (coarse/lammps_export.hpp)");
    export_cmd->add_option("--config", config, "settings, e.g. data/many-body-v6/profiles/reference.yaml")->required();
    export_cmd->add_option("--medium", medium, "medium file (softpack-coarse medium)")->required();
    export_cmd->add_flag("--lammps", lammps, "as a LAMMPS data file and input script (the only format, required)")->required();
    export_cmd->add_option("--out", dir, "folder of medium.data, in.compression, laws.json ...")->required();
    curve_cmd = app.add_subcommand("lammps-curve", "a LAMMPS run of an exported compression read back as a results file of the soft model");
    curve_cmd->add_option("--config", config, "the settings it was exported from")->required();
    curve_cmd->add_option("--medium", medium, "its medium file")->required();
    curve_cmd->add_option("--dir", dir, "the run's folder (curve.dat, log.lammps)")->required();
    curve_cmd->add_option("--out", out, "results file (HDF5)")->required();
  }

  /// Runs the one given; false when neither was.
  bool run(const std::string& program) const {
    if (*export_cmd) {
      const CoarseGrainSettings s = read_coarse_grain_settings(config);
      const MediumFile mf = read_medium_file(medium);
      if (mf.settings != s.medium_text)
        throw InputError(fmt::format("{}: made with other settings than {} (rerun softpack-coarse medium)", medium, config));
      write_lammps_export(s, config, mf, dir);
      fmt::print(stderr, "{} export: seed {}, {} grains and {} soft-particles -> {}/in.compression\n", program, mf.seed, mf.medium.grain_x.size(),
                 mf.medium.sites.size(), dir);
      return true;
    }
    if (*curve_cmd) {
      const CoarseGrainSettings s = read_coarse_grain_settings(config);
      const MediumFile mf = read_medium_file(medium);
      if (mf.settings != s.medium_text)
        throw InputError(fmt::format("{}: made with other settings than {} (rerun softpack-coarse medium)", medium, config));
      const LammpsRun r = read_lammps_run(dir, s, mf);
      CoarseResult result = coarse_result(r.run, mf.medium, CoarseModel::soft, mf.seed, s);
      result.threads = r.ranks;
      result.code_version += fmt::format(" (softpack-lammps, {} MPI ranks)", r.ranks);
      result.beyond_range = -1, result.max_dn = std::nan("");  // not counted by LAMMPS's run
      write_coarse_result(out, result);
      fmt::print(stderr, "{} lammps-curve: {} rows, {} steps on {} ranks in {:.1f} s -> {}\n", program, r.run.rows.size(), r.run.steps, r.ranks,
                 r.run.time.wall, out);
      return true;
    }
    return false;
  }
};

}  // namespace softpack::apps::coarse_app
