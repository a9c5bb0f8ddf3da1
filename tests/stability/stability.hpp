// Shared pieces of the stability suite (tests/stability/): the scenes of experiments/stability/,
// and the checks every case makes: nothing NaN or infinite, the energy of a state.
#pragma once
#include <string>

#include "scene/scene_yaml.hpp"
#include "sim/simulation.hpp"

namespace softpack::stability {

/// Path of a scene of the suite: experiments/stability/<name>.
std::string scene_path(const std::string& name);
/// Loads (parses and validates) experiments/stability/<name>.
SceneFile load(const std::string& name);

/// Empty when every position, velocity, force (spin and torque with rotation), wall load and
/// residual of the simulation is finite; otherwise what is not, for the failure message.
std::string non_finite(const Simulation& sim);

/// Kinetic (translation and rotation, free spheres) plus elastic (Hertz and tangential springs)
/// energy [J].
double mechanical_energy(const Simulation& sim);

/// Prints "[ measured ] what = value" (the values the tolerances were set from, for the logs)
/// and records it as a property of the running test (ctest --output-junit keeps it).
void measured(const std::string& what, double value);

/// Hertz stiffness kn = sqrt(R12) / D of two spheres of the scene's material `m` (Eq. 3-4).
double hertz_kn(const Material& m, double R12);

}  // namespace softpack::stability
