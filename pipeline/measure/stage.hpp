// What the stages softpack-normal and softpack-tangential share: read the profile and the
// packings, check that they belong together, build the scene, run the sweep (each point
// reported through a callback), write the results file. The tangential stage shears the normal
// stage's saved states; where they are missing (the normal results were taken from the archive,
// which keeps no checkpoints) it computes them first, in the normal stage's checkpoint folder. The command line, the progress lines
// and the exit codes are the executables' (apps/stage_cli.hpp).
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "formats/point_result.hpp"

namespace softpack {

struct StageOptions {
  std::string stage;  ///< "normal", "tangential" or "sliding"
  std::string config_path, scene, packing, second_packing;
  std::string checkpoints;         ///< point files of this stage
  std::string normal_checkpoints;  ///< tangential, sliding: the normal stage's point files
  std::string out;
  /// The stamp Make planned this run with (workflow/stamps.mk; "" when run by hand): the stage
  /// refuses to run when the profile's stamp now differs (the profile was edited since).
  std::string stamp;
  long long seed = -1;
  bool hertz_check = false;  ///< replace the soft-particle by a solid sphere of radius Rs
  long stop_after = 0;       ///< testing: stop after this many new points
};

/// Called after each point: its stage ("normal" also in the tangential stage, for the normal
/// states it computes), its index, the number of points, the point, and whether it was reused
/// from a checkpoint (else computed).
using StageProgress =
    std::function<void(const std::string& stage, std::size_t k, std::size_t n, const PointResult& r, bool reused)>;

struct StageSummary {
  std::size_t points = 0;  ///< in the results file
  double seconds = 0.0;    ///< of the whole stage
  bool stopped = false;    ///< stopped after `stop_after` new points: no results file
};

/// Runs a stage. Throws InputError for bad input, NumericalError when the watchdog stopped a run
/// (sim/watchdog.hpp; the message starts with "<scene> seed <seed>, " and names the point).
StageSummary run_stage(const StageOptions& o, const StageProgress& progress = {});

}  // namespace softpack
