// Where the time of a profile's run went (issue 13, "time where it goes"): the wall-clock and CPU
// time each output records in its provenance, gathered per stage and, for the sweeps, per phase
// of their points (loading, relaxation, output; formats/point_result.hpp). Read by
// softpack-timing (`make timing`) and by the accuracy study, whose cost of a measurement is the
// `total` here.
//
// The cost of a sweep is the sum over its points of the time each point recorded, whichever run
// computed it (a resumed sweep costs what its points cost); the stage's own process time (which
// also holds the start-up, the reading of the packings, the points computed in that run only) is
// given beside it. The packings, averages and fits cost their processes' time.
#pragma once
#include <string>
#include <vector>

#include "core/stopwatch.hpp"
#include "formats/point_result.hpp"

namespace softpack {

struct StageTiming {
  std::string stage;  ///< packing, normal, tangential, average, fit
  std::string scene;  ///< sweeps: soft-solid or soft-soft; else ""
  std::vector<std::string> missing;  ///< the files asked for that do not exist (not run yet)
  std::size_t files = 0;
  std::size_t points = 0, reused = 0;  ///< sweeps: points, of which taken from checkpoints by the last run
  Elapsed cost;                        ///< sweeps: sum of the points' totals; else the processes'
  PointTiming phases;                  ///< sweeps: the sum over the points of each phase
  Elapsed process;                     ///< the stage's processes as recorded in the files' provenance
};

struct ProfileTiming {
  std::vector<StageTiming> stages;
  Elapsed total() const;  ///< the sum of the stages' costs
  bool complete() const;  ///< no file is missing
};

/// The files of each stage; a missing file is listed as missing, an unreadable one is an
/// InputError naming it.
struct TimingInputs {
  std::vector<std::string> packings, normal, tangential, averages, fits;
};
ProfileTiming collect_timing(const TimingInputs& in);

/// The table `make timing` prints (markdown), one row per stage and scene, then the total.
std::string timing_table(const ProfileTiming& t, const std::string& title);
/// The same as JSON (for the accuracy study): {"stages": [...], "total": {"wall", "cpu"}, "complete"}.
std::string timing_json(const ProfileTiming& t);

}  // namespace softpack
