// The active set as plain data (parsed with the relaxation protocols, scene/scene_yaml; validated
// by scene/validate.hpp; run by sim/active_set.hpp). A free sphere at rest sleeps: it is not
// integrated, and its contacts with other sleeping spheres are not evaluated (their forces,
// constant while neither moves, are kept as a sum per sphere). It wakes as soon as its net force
// grows beyond `wake_force`: a neighbour that moves, a contact that closes or opens, or a wall
// that arrives changes that force.
//
// Forces are measured against the scale of the state, the mean normal force over the closed
// contacts at the last sleep check (sim/residuals.hpp: the unit of the relaxation's force ratio).
#pragma once

namespace softpack {

struct ActiveSetDef {
  /// A sphere falls asleep at a check when |F| and |T| / r are at most this fraction of the
  /// mean contact force ...
  double sleep_force = 0.0;
  /// ... and |v| and |w| r at most this speed [m/s] (0 after a stop of the paper protocol). With
  /// no closed contact the scale is 0: only spheres with no force at all sleep.
  double sleep_speed = 0.0;
  /// It wakes, at the end of any step, when |F| or |T| / r exceeds this fraction (>= sleep_force).
  double wake_force = 0.0;
  /// Simulated time between sleep checks [s]; the paper protocol also checks after every stop.
  double check_interval = 0.0;
};

}  // namespace softpack
