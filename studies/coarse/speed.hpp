// The speed-up measured side by side (issue 33's target: the soft model at least 300 times faster
// than the resolved one, "measured side by side in one run"; paper/many-body.md, "Next: the
// speed-up side by side"). On one medium, in one process, one after the other: the resolved model,
// the soft model with the pairwise laws (the reference settings) and with the many-body laws (the
// many-body settings), each the whole compression, unloading and shear of the settings; the time
// of each is the CPU time of its simulation (CompressionRun::time, as the study reports count it:
// the scene's construction and the steps), each paying the grains' damping setup as a process of
// its own would (Simulation::forget_setup_caches), on the threads SOFTPACK_THREADS gives (make runs it
// on one). The soft runs, a second or so each,
// are repeated `repeats` times, interleaved, and their least time taken; the resolved run is
// made once, first for the seeds at even positions of the plan's list and last for the others, so
// that a drift of the machine's speed does not favour one model.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "coarse/probe_settings.hpp"

namespace softpack {

/// One medium's three models side by side.
struct SpeedSeed {
  std::uint64_t seed = 0;
  bool resolved_first = true;
  double resolved = 0.0, pairwise = 0.0, many_body = 0.0;  ///< CPU time [s] (the soft models': the least of the repeats)
  long steps_resolved = 0, steps_pairwise = 0, steps_many_body = 0;
  int repeats = 0;
};

/// Runs the three models on DIR/reference/media/seed-S.h5 (S one of the media seeds of the law's
/// `version`; DIR/profiles/reference.yaml: the resolved and the pairwise soft model's settings,
/// DIR/profiles/many-body.yaml: the many-body soft model's, whose medium must be the same) and
/// writes DIR/speed/seed-S.dat. progress(model, its run k, strain done, strain in all) after each
/// recorded row of each run.
using SpeedProgress = std::function<void(const std::string&, int, double, double)>;
SpeedSeed write_speed_seed(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& dir, int version, std::uint64_t seed, int repeats,
                           const SpeedProgress& progress = {});

/// DIR/speed/speed.md from each DIR/speed/seed-S.dat of the media seeds of the law's `version`: per
/// seed the three times and the speed-ups resolved / soft, and their means over the seeds with
/// standard errors.
void write_speed_report(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& dir, int version);

}  // namespace softpack
