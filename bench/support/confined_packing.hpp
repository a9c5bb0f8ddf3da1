// The benchmark scene: a soft-particle-like packing of ~5000 spheres (polydispersity 10,
// power law b = 3.5) compressed inside a shell of radius Rs = 0.016 m, with the paper's
// material. The packing is made once (random sequential addition, then grown and relaxed
// until it jams: tests/support) and written as `x y z r` lines, so that softpack and LAMMPS
// run the very same spheres.
#pragma once
#include <string>
#include <vector>

#include "scene/scene_def.hpp"

namespace softpack::bench {

struct Sphere {
  Vec3 x;
  double r;
};

struct BenchParameters {
  double Rs = 0.016;            ///< shell radius [m]
  double r_max = 0.2 * 0.016;   ///< largest radius [m]
  double polydispersity = 10;   ///< r_max / r_min
  double exponent = 3.5;        ///< b of P(r) ~ r^-b
  double solid_fraction = 0.70; ///< after compression (jammed at this polydispersity)
  double restitution = 0.5;
  double safety = 0.2;          ///< dt = safety * Rayleigh time
  double skin = 1.0;            ///< Verlet skin / r_min
  double level_ratio = 2.0;     ///< hierarchical grid: the best of 2, 3, 4, 6 for this scene (docs/physics.md §8)
};

/// Makes (or reads from `cache`, when it exists) a packing of about n spheres.
std::vector<Sphere> confined_packing(int n, const BenchParameters& p, const std::string& cache);

std::vector<Sphere> read_spheres(const std::string& path);
void write_spheres(const std::string& path, const std::vector<Sphere>& spheres);

/// The scene softpack runs on these spheres: paper material, Hertz, and (when `friction`)
/// Tsuji friction with rotation; Tsuji damping; the shell; the spheres in spatial order
/// (neighbor/spatial_order.hpp).
SceneDef bench_scene(const std::vector<Sphere>& spheres, const BenchParameters& p, bool friction);

}  // namespace softpack::bench
