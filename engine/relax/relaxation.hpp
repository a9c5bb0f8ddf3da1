// Relaxation protocols: bring a deformed scene to rest before measuring forces.
//
// * paper (§4 of the paper): `stops` times, run for `wait` seconds then set every free
//   sphere's translational and angular velocity to zero; then run `final_wait` more seconds.
// * converged: run in chunks of `check_interval` seconds until the largest unbalanced force
//   over the mean contact force is below `force_tolerance` and the kinetic over the elastic
//   energy below `energy_tolerance`, or give up after `max_time` (reported, not hidden).
//   With `zero_velocities_at_checks` the velocities are zeroed after each unconverged check,
//   as in the paper protocol, which removes the slow rattlers the paper describes.
//
// Both report the steps and simulated time they used and the residuals after each stop/check.
#pragma once
#include <functional>
#include <optional>
#include <variant>
#include <vector>

#include "sim/simulation.hpp"

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

/// State after one stop (paper) or check (converged).
struct RelaxationCheck {
  double time = 0.0;  ///< simulated time since the relaxation began [s]
  long steps = 0;     ///< steps since the relaxation began
  Measurement residuals;
};

struct RelaxationReport {
  long steps = 0;
  double simulated_time = 0.0;
  /// converged protocol: whether both tolerances were met; paper protocol: no criterion.
  std::optional<bool> converged;
  std::vector<RelaxationCheck> checks;
};

/// Validates the definition (InputError naming relaxation.<key>).
void validate(const RelaxationDef& def);

/// Runs the protocol; `on_check` (optional) sees each check as it happens, for progress.
RelaxationReport relax(Simulation& sim, const RelaxationDef& def,
                       const std::function<void(const RelaxationCheck&)>& on_check = {});

}  // namespace softpack
