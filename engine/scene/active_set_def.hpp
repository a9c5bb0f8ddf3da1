// The active set as plain data (parsed with the relaxation protocols, scene/scene_yaml; validated
// by scene/validate.hpp; run by sim/active_set.hpp). A free sphere at rest sleeps: it is not
// integrated, and its contacts with other sleeping spheres are not evaluated (their forces,
// constant while neither moves, are kept as a sum per sphere). It wakes as soon as its net force
// grows beyond `wake_force`: a neighbour that moves, a contact that closes or opens, or a wall
// that arrives changes that force.
//
// Forces are measured against each grain's own: the sum S of its contacts' normal forces at the
// sleep check. A grain at rest has a net force small against S; a grain pushed by a single
// contact (a rattler, a grain the wall grazes) has |F| = S and keeps moving until it is free.
#pragma once

namespace softpack {

struct ActiveSetDef {
  /// A sphere falls asleep at a check when |F| and |T| / r are at most this fraction of S ...
  double sleep_force = 0.0;
  /// ... and |v| and |w| r at most this speed [m/s] (0 after a stop of the paper protocol). A
  /// sphere with no contact (S = 0) sleeps only with no force at all.
  double sleep_speed = 0.0;
  /// It wakes, at the end of any step, when |F| or |T| / r exceeds this fraction of its S at the
  /// check that put it to sleep (>= sleep_force).
  double wake_force = 0.0;
  /// Simulated time between sleep checks [s]; the paper protocol also checks after every stop.
  double check_interval = 0.0;
};

}  // namespace softpack
