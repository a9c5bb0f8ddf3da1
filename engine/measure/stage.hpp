// The command-line stages softpack-normal and softpack-tangential share this: read the
// profile and the packings, check that they belong together, build the scene, run the sweep
// with progress lines, write the results file.
#pragma once
#include <cstdint>
#include <string>

namespace softpack {

struct StageOptions {
  std::string stage;  ///< "normal" or "tangential"
  std::string config_path, scene, packing, second_packing;
  std::string checkpoints;         ///< point files of this stage
  std::string normal_checkpoints;  ///< tangential: the normal stage's point files
  std::string out;
  long long seed = -1;
  bool quiet = false;
  bool hertz_check = false;  ///< replace the soft-particle by a solid sphere of radius Rs
  long stop_after = 0;       ///< testing: stop after this many new points
};

/// Runs a stage; returns the exit code (0; 2 for bad input; 3 when the watchdog stopped a run,
/// sim/watchdog.hpp; 1 for an internal error) after printing any error.
int run_stage(const StageOptions& o);

}  // namespace softpack
