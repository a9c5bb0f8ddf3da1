// Relaxation: bring a deformed scene to rest before measuring forces, with one of the protocols
// of scene/relaxation_def.hpp. Both report the steps and simulated time they used and the
// residuals after each stop/check.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "scene/relaxation_def.hpp"
#include "sim/simulation.hpp"

namespace softpack {

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
  /// With an active set: the sphere-steps integrated over all sphere-steps (the work done).
  std::optional<double> awake_fraction;
};

/// Runs the protocol; `on_check` (optional) sees each check as it happens, for progress;
/// `measured` (optional) gives the measured force, which a paper protocol with `settle` needs
/// (InputError without it).
RelaxationReport relax(Simulation& sim, const RelaxationDef& def,
                       const std::function<void(const RelaxationCheck&)>& on_check = {},
                       const std::function<Vec3()>& measured = {});

}  // namespace softpack
