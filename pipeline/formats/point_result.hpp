// What one measured point of a sweep gives (measure/sweeps.hpp); stored in the sweep point
// files (formats/sweep_file.hpp) and, as columns, in the results files.
#pragma once
#include <optional>
#include <vector>

#include "core/stopwatch.hpp"
#include "core/types.hpp"
#include "relax/relaxation.hpp"

namespace softpack {

/// Where the time of a point went (wall and CPU): moving the body or turning the soft-particle
/// (loading), the relaxation, writing its point file (output, measured by the writer up to its
/// timing datasets).
struct PointTiming {
  Elapsed loading, relaxation, output;
  Elapsed total() const { return loading + relaxation + output; }
};

struct PointResult {
  double delta_n = 0.0, hn = 0.0;    ///< normal deformation, hn = delta_n Rs [m]
  double alpha_deg = 0.0, ht = 0.0;  ///< tangential stage: rotation and ht = pi Rs alpha / 180 [m]; sliding: 0 and the move [m]
  Vec3 force = Vec3::Zero();          ///< on the second body [N]
  Vec3 force_first = Vec3::Zero();    ///< load on the first shell [N] (minus force in balance)
  Vec3 force_between = Vec3::Zero();  ///< elastic force of the first body's spheres on the second's [N]
  long contacts = 0;                  ///< closed contacts at the end
  /// Largest overlap at the end relative to the smaller radius of its contact (a sphere's own
  /// radius against a wall): h / r [-], where the Hertz law holds only for h / r << 1.
  double overlap_max = 0.0;
  double overlap_q99 = 0.0;  ///< the same, the value 99 % of the contacts do not exceed (sim/residuals.hpp, overlap_quantile)
  long relax_steps = 0;
  double relax_time = 0.0;            ///< simulated [s]
  std::vector<RelaxationCheck> checks;
  long steps = 0;                     ///< all steps of the point (loading, rotation, relaxation)
  PointTiming timing;
  /// Wall-clock time of the point's loading and relaxation [s].
  double seconds() const { return timing.loading.wall + timing.relaxation.wall; }
  /// With an active set: the share of sphere-steps of the relaxation that were integrated (not stored).
  std::optional<double> awake_fraction;
  bool reused = false;  ///< not stored: this run took the point from its checkpoint (timing is the computing run's)
};

}  // namespace softpack
