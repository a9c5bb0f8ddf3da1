// softpack-coarse's LAMMPS subcommands (issue 34, docs/lammps.md), apart from softpack_coarse.cpp:
//
//   softpack-coarse export --lammps --config C --medium M --out DIR
//       the soft model of medium M and its compression as a LAMMPS input (coarse/lammps_export.hpp);
//   softpack-coarse lammps-curve --config C --medium M --dir DIR --out F.h5
//       that run read back (DIR/curve.dat, DIR/log.lammps) as a results file of the soft model, the
//       engine's layout (coarse/result_file.hpp), for the comparison with the engine's runs;
//   softpack-coarse lammps-check --plan experiments/lammps.yaml --dir DIR
//       those runs against the engine's by the plan's rule (coarse/lammps_check.hpp).
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <string>

#include "coarse/lammps_check.hpp"
#include "coarse/lammps_export.hpp"
#include "coarse/result_file.hpp"
#include "core/error.hpp"

namespace softpack::apps::coarse_app {

struct LammpsCommands {
  CLI::App* export_cmd = nullptr;
  CLI::App* curve_cmd = nullptr;
  CLI::App* check_cmd = nullptr;
  std::string config, medium, out, dir, plan;
  bool lammps = false, list_runs = false, list_study = false;

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
    check_cmd = app.add_subcommand("lammps-check", "LAMMPS's runs against the engine's by the plan's rule (coarse/lammps_check.hpp)");
    check_cmd->add_option("--plan", plan, "the plan, e.g. experiments/lammps.yaml")->required();
    check_cmd->add_option("--dir", dir, "the LAMMPS runs' folder (SETTING/npR/seed-S.h5), where report/ goes, e.g. data/lammps")->required();
    check_cmd->add_flag("--runs", list_runs, "instead: print the plan's runs, SETTING/npR/seed-S (for make)");
    check_cmd->add_flag("--study", list_study, "instead: print the folder of the study whose engine runs it reads, and that of its media (for make)");
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
      result.threads = r.ranks, result.engine = "lammps";
      result.code_version += fmt::format(" (softpack-lammps, {} MPI ranks)", r.ranks);
      result.beyond_range = -1, result.max_dn = std::nan("");  // not counted by LAMMPS's run
      write_coarse_result(out, result);
      fmt::print(stderr, "{} lammps-curve: {} rows, {} steps on {} ranks in {:.1f} s -> {}\n", program, r.run.rows.size(), r.run.steps, r.ranks,
                 r.run.time.wall, out);
      return true;
    }
    if (*check_cmd && (list_runs || list_study)) {
      const LammpsCheckPlan p = read_lammps_check_plan(plan);
      // A study's settings share their media (studies/report/study_base.hpp); the first setting's are
      // the ones a clone has.
      if (list_study) fmt::print("{} {}/{}/media\n", p.study, p.study, p.settings.front());
      if (list_runs) {
        for (const std::string& setting : p.settings)
          for (const int ranks : p.ranks)
            for (const std::uint64_t seed : p.seeds) fmt::print("{}/np{}/seed-{} ", setting, ranks, seed);
        fmt::print("\n");
      }
      return true;
    }
    if (*check_cmd) {
      for (const LammpsVerdict& v : write_lammps_check(read_lammps_check_plan(plan), plan, dir))
        fmt::print(stderr, "{} lammps-check: {} on {} ranks: σzz {} of {} points, K0 {} of {} within the bound, accepted: {}\n", program, v.setting,
                   v.ranks, v.sigma_agreeing, v.sigma_points, v.k0_agreeing, v.k0_points, v.accepted() ? "yes" : "no");
      fmt::print(stderr, "{} lammps-check: {}/report/check.md\n", program, dir);
      return true;
    }
    return false;
  }
};

}  // namespace softpack::apps::coarse_app
