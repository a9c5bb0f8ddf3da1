// The command line of softpack-normal and softpack-tangential: the same options but one each
// (--hertz-check for the normal stage, --normal-checkpoints for the tangential one), then
// run_stage (measure/stage.hpp).
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "measure/stage.hpp"

namespace softpack {

inline int stage_main(int argc, char** argv, const std::string& stage) {
  StageOptions o;
  o.stage = stage;
  CLI::App app{"softpack-" + stage + ": the " + stage + " contact-law sweep of one scene and one seed"};
  app.add_option("--config", o.config_path, "profile file, e.g. experiments/paper.yaml")->required();
  app.add_option("--scene", o.scene, "soft-solid or soft-soft")->required();
  app.add_option("--seed", o.seed, "seed of this measurement (recorded in the results)")->required();
  app.add_option("--packing", o.packing, "packing file of the first soft-particle");
  app.add_option("--second-packing", o.second_packing, "soft-soft: packing file of the second soft-particle (another seed)");
  app.add_option("--checkpoints", o.checkpoints, "directory of this stage's point files (resume from them)")->required();
  if (stage == "normal")
    app.add_flag("--hertz-check", o.hertz_check, "replace the soft-particle by one solid sphere of radius Rs (validation)");
  else
    app.add_option("--normal-checkpoints", o.normal_checkpoints, "point files of the normal stage (its states are sheared)")
        ->required();
  app.add_option("--out", o.out, "results file (HDF5)")->required();
  app.add_flag("--quiet", o.quiet, "no progress lines");
  app.add_option("--stop-after", o.stop_after, "stop after this many new points (tests of the resume)")->group("");
  CLI11_PARSE(app, argc, argv);
  return run_stage(o);
}

}  // namespace softpack
