// The relaxation protocols as plain data (parsed with the scenes and profiles, scene/scene_yaml),
// run by relax/relaxation.hpp and validated by scene/validate.hpp:
//
// * paper (§4 of the paper): `stops` times, run for `wait` seconds then set every free
//   sphere's translational and angular velocity to zero; then run `final_wait` more seconds.
// * converged: run in chunks of `check_interval` seconds until the largest unbalanced force
//   over the mean contact force is below `force_tolerance` and the kinetic over the elastic
//   energy below `energy_tolerance`, or give up after `max_time` (reported, not hidden).
//   With `zero_velocities_at_checks` the velocities are zeroed after each unconverged check,
//   as in the paper protocol, which removes the slow rattlers the paper describes.
#pragma once
#include <variant>

namespace softpack {

struct PaperRelaxationDef {
  int stops = 0;            ///< the paper uses 6
  double wait = 0.0;        ///< [s], the paper uses 0.3
  double final_wait = 0.0;  ///< [s], "at least" 0.3 in the paper
};

struct ConvergedRelaxationDef {
  double force_tolerance = 0.0;
  double energy_tolerance = 0.0;
  double check_interval = 0.0;  ///< [s]
  double max_time = 0.0;        ///< [s]
  bool zero_velocities_at_checks = false;
};

using RelaxationDef = std::variant<PaperRelaxationDef, ConvergedRelaxationDef>;

}  // namespace softpack
