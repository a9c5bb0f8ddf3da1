// The bodies of a scene and the clock: what a time step advances. Spheres (state/particles.hpp),
// plane walls and shells with their motion, the loads the spheres put on the walls at the last
// force evaluation, the time and the step count. The tangential springs, the rest of a run's
// state, live with the contacts (neighbor/contact_list.hpp); state/simulation_state.hpp is the
// saved form of both.
#pragma once
#include <vector>

#include "scene/scene_def.hpp"
#include "state/particles.hpp"
#include "walls/plane_wall.hpp"
#include "walls/spherical_shell.hpp"

namespace softpack {

/// Force and torque a wall receives from the spheres; the torque is about the wall's
/// reference point (the plane's point, the shell's centre).
struct WallLoad {
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
};

struct World {
  Particles p;
  std::vector<PlaneWall> planes;
  std::vector<SphericalShell> shells;
  std::vector<WallLoad> plane_loads, shell_loads;  ///< of the last force evaluation
  double time = 0.0;  ///< [s]
  long steps = 0;
};

/// The world a scene starts from: masses m = 4/3 pi r^3 rho, moments of inertia I = 2/5 m r^2
/// (rotation only), walls at rest.
World make_world(const SceneDef& scene);

}  // namespace softpack
