// Everything a run needs to continue bit for bit (the checkpoints of the sweeps, written and read
// by formats/sweep_file): the world's positions, velocities, forces and clock, and the non-zero
// tangential springs. Simulation::state() and restore() make and install it.
#pragma once
#include <vector>

#include "core/types.hpp"

namespace softpack {

struct SimulationState {
  double time = 0.0;
  long steps = 0;
  std::vector<Vec3> x, v, w, F, T;  ///< w and T empty without rotation
  std::vector<Vec3> plane_points, shell_centres;
  /// Every shell's velocity, spin and load (force, torque) when one of them is free
  /// (walls/spherical_shell.hpp); empty otherwise.
  std::vector<Vec3> shell_velocities, shell_spins, shell_forces, shell_torques;
  /// Non-zero tangential springs: sphere pairs (i < j), and per wall (sphere, spring).
  struct PairSpring {
    int i = 0, j = 0;
    Vec3 xi = Vec3::Zero();
  };
  struct WallSpring {
    int i = 0;
    Vec3 xi = Vec3::Zero();
  };
  /// Every contact model's (a pair, a sphere on a wall, has one), sorted by spheres.
  std::vector<PairSpring> pair_springs;
  std::vector<std::vector<WallSpring>> plane_springs, shell_springs;
};

}  // namespace softpack
