// softpack-normal: the normal sweep of one contact scene and one seed (paper §4); see
// measure/sweeps.hpp for what it does and docs/measurement.md for the choices.
#include <CLI/CLI.hpp>

#include "measure/stage.hpp"

int main(int argc, char** argv) {
  softpack::StageOptions o;
  o.stage = "normal";
  CLI::App app{"softpack-normal: the normal contact-law sweep of one scene and one seed"};
  app.add_option("--config", o.config_path, "profile file, e.g. experiments/paper.yaml")->required();
  app.add_option("--scene", o.scene, "soft-solid or soft-soft")->required();
  app.add_option("--seed", o.seed, "seed of this measurement (recorded in the results)")->required();
  app.add_option("--packing", o.packing, "packing file of the first soft-particle");
  app.add_option("--second-packing", o.second_packing, "soft-soft: packing file of the second soft-particle (another seed)");
  app.add_option("--checkpoints", o.checkpoints, "directory of this stage's point files (resume from them)")->required();
  app.add_flag("--hertz-check", o.hertz_check, "replace the soft-particle by one solid sphere of radius Rs (validation)");
  app.add_option("--out", o.out, "results file (HDF5)")->required();
  app.add_flag("--quiet", o.quiet, "no progress lines");
  app.add_option("--stop-after", o.stop_after, "stop after this many new points (tests of the resume)")->group("");
  CLI11_PARSE(app, argc, argv);
  return softpack::run_stage(o);
}
