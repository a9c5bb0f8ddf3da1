// Building blocks for test scenes: materials, deterministic random numbers, sphere clouds.
#pragma once
#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "scene/scene_def.hpp"

namespace softpack::testing {

/// The paper's grain: E = 5e5 Pa, nu = 0.3, mu = 0.3; density 2500 kg/m^3 (our choice).
Material paper_grain();
/// A second, stiffer material for two-material checks.
Material stiff_grain();

/// A scene with one material (the paper's grain), Hertz normal law, no other effect, the
/// time step at 0.2 of the Rayleigh limit and a neighbour skin of 0.2 r_min.
SceneDef basic_scene();

/// Deterministic random numbers (engine/core/random.hpp).
using Random = softpack::Random;

/// Radius from the truncated power law P(r) ~ r^-b on [r_min, r_max] (inverse CDF).
double power_law_radius(Random& rng, double r_min, double r_max, double b);

/// n spheres at uniform positions in a cube of half-width `half`, overlaps allowed.
std::vector<ParticleDef> random_cloud(Random& rng, int n, double half, double r_min, double r_max, double b);

/// Random sequential addition into a ball of radius Rs: n radii from the power law, largest
/// first, each given `trials` random positions without overlap (dropped if none is found).
/// (A test fixture only; the packing generator proper is softpack-pack.)
std::vector<ParticleDef> random_spheres_in_shell(Random& rng, int n, double Rs, double r_min, double r_max,
                                                 double b, int trials, int body);

/// Grows the radii of a packing confined by `scene`'s walls in steps of `growth` (relative),
/// relaxing with damping after each step, until the solid fraction of the spheres within the
/// ball of radius `R` reaches `fraction`: a compressed, jammed packing with real overlaps.
void compress(SceneDef& scene, double R, double fraction, double growth);

/// Solid fraction of spheres in a ball of radius R (spheres counted whole).
double solid_fraction(const std::vector<ParticleDef>& particles, double R);

}  // namespace softpack::testing
