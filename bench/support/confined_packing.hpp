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
/// Tsuji friction with rotation; Tsuji damping; the shell of radius p.Rs; the spheres in spatial
/// order (neighbor/spatial_order.hpp), or as given when `spatial` is false.
SceneDef bench_scene(const std::vector<Sphere>& spheres, const BenchParameters& p, bool friction, bool spatial = true);

/// The scaling scene: about n spheres of radius r on a face-centred cubic lattice filling a cube,
/// neighbours overlapping by `overlap` r, between six planes that press each face's layer as
/// much as its missing neighbours would (lattice_scene): twelve contacts inside, whose forces
/// cancel, so that the packing stays at rest and its contacts persist. Shuffled with a fixed
/// seed (a generator's order is no better). Made in seconds for a million.
struct Lattice {
  std::vector<Sphere> spheres;
  double r = 0.0, overlap = 0.0, side = 0.0;  ///< the centres span [0, side] along each axis
};
Lattice lattice_cube(long n, double r, double overlap);
/// bench_scene's physics on a lattice, with its six planes instead of the shell.
SceneDef lattice_scene(const Lattice& lattice, const BenchParameters& p, bool friction, bool spatial);

}  // namespace softpack::bench
