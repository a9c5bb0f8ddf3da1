// Time step from the Rayleigh critical step of the smallest, softest sphere:
//
//   t_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766),   G = E / (2 (1 + nu))
//
// (the time a Rayleigh surface wave needs to cross a hemisphere; the coefficients are the
// standard fit of the Rayleigh wave speed, Li et al., Powder Technol. 2005). t_R is the
// stable limit: a requested step above it is refused. With `safety` the step is safety * t_R.
//
// Soft-particle contacts (effects.soft_particles) have a stiffness of their own, dFn/dh of the
// measured law, largest at the end of its measured range: t_soft = sqrt(m / k) (1/ω of the
// stiffest soft contact with the lightest partner, half the explicit scheme's limit 2/ω) is a
// second limit, and the step is safety * min(t_R, t_soft).
#pragma once
#include <limits>
#include <string>

#include "scene/scene_def.hpp"

namespace softpack {

double rayleigh_time(double r, const Material& m);

struct StableLimit {
  double t_rayleigh = 0.0;  ///< smallest Rayleigh time over all spheres [s]
  int particle = -1;        ///< the sphere that sets it
  /// Soft-particle contacts only: sqrt(m/k) of the stiffest one [s] (infinity without them).
  double t_soft = std::numeric_limits<double>::infinity();
  int soft_particle = -1;  ///< the soft-particle that sets it
  double limit() const { return t_soft < t_rayleigh ? t_soft : t_rayleigh; }
};

StableLimit stable_limit(const SceneDef& scene);

/// The step the scene asks for; throws InputError naming integration.dt and the limit when
/// the requested step exceeds it.
double choose_time_step(const SceneDef& scene);

}  // namespace softpack
