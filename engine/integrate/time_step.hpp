// Time step from the Rayleigh critical step of the smallest, softest sphere:
//
//   t_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766),   G = E / (2 (1 + nu))
//
// (the time a Rayleigh surface wave needs to cross a hemisphere; the coefficients are the
// standard fit of the Rayleigh wave speed, Li et al., Powder Technol. 2005). t_R is the
// stable limit: a requested step above it is refused. With `safety` the step is safety * t_R.
#pragma once
#include <string>

#include "scene/scene_def.hpp"

namespace softpack {

double rayleigh_time(double r, const Material& m);

struct StableLimit {
  double t_rayleigh = 0.0;  ///< smallest Rayleigh time over all spheres [s]
  int particle = -1;        ///< the sphere that sets it
};

StableLimit stable_limit(const SceneDef& scene);

/// The step the scene asks for; throws InputError naming integration.dt and the limit when
/// the requested step exceeds it.
double choose_time_step(const SceneDef& scene);

}  // namespace softpack
