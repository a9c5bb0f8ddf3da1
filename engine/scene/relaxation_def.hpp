// The relaxation protocols as plain data (parsed with the scenes and profiles, scene/scene_yaml),
// run by relax/relaxation.hpp and validated by scene/validate.hpp:
//
// * paper (§4 of the paper): `stops` times, run for `wait` seconds then set every free
//   sphere's translational and angular velocity to zero; then run `final_wait` more seconds.
//   With `settle` the stops end early, once the measured force (the force on the second body of
//   a sweep) has changed from one stop to the next by less than `relative` of its size or by
//   less than `absolute` newtons: the paper's protocol with as many stops as the measurement needs,
//   at most `stops`.
// * converged: run in chunks of `check_interval` seconds until the largest unbalanced force
//   over the mean contact force is below `force_tolerance` and the kinetic over the elastic
//   energy below `energy_tolerance`, or give up after `max_time` (reported, not hidden).
//   With `zero_velocities_at_checks` the velocities are zeroed after each unconverged check,
//   as in the paper protocol, which removes the slow rattlers the paper describes.
//
// Either protocol may `quench` (default false): during the relaxation, after every step, a free
// sphere whose power F·v is negative (it moves against its net force, past the bottom of its
// well) has its velocity set to zero, and its spin when T·ω < 0 — the per-grain velocity quench
// of quenched molecular dynamics. It takes out kinetic energy where the damping is weak (few,
// barely overlapped contacts) without touching the grains that are still being accelerated.
//
// Either protocol may run with an `active_set` (scene/active_set_def.hpp): grains at rest sleep,
// and cost nothing, until a force wakes them.
#pragma once
#include <optional>
#include <variant>

#include "scene/active_set_def.hpp"

namespace softpack {

struct PaperRelaxationDef {
  int stops = 0;            ///< the paper uses 6
  double wait = 0.0;        ///< [s], the paper uses 0.3
  double final_wait = 0.0;  ///< [s], "at least" 0.3 in the paper
  bool quench = false;      ///< per-grain velocity quench (above)
  struct Settle {
    double relative = 0.0;  ///< of the measured force's size
    double absolute = 0.0;  ///< [N]
  };
  std::optional<Settle> settle = std::nullopt;  ///< none: every stop (the paper)
  std::optional<ActiveSetDef> active_set = std::nullopt;  ///< none: every grain integrated every step
};

struct ConvergedRelaxationDef {
  double force_tolerance = 0.0;
  double energy_tolerance = 0.0;
  double check_interval = 0.0;  ///< [s]
  double max_time = 0.0;        ///< [s]
  bool zero_velocities_at_checks = false;
  bool quench = false;  ///< per-grain velocity quench (above)
  std::optional<ActiveSetDef> active_set = std::nullopt;  ///< none: every grain integrated every step
};

using RelaxationDef = std::variant<PaperRelaxationDef, ConvergedRelaxationDef>;

}  // namespace softpack
