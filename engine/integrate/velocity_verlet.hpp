// The two integration phases of velocity Verlet over the free spheres (a driven sphere's motion
// is prescribed by its driver, drivers/drivers.hpp):
//
//   kick_drift  v += F/m dt/2,  w += T/I dt/2, then x += v dt (a step's first half, one pass)
//   half_kick   v += F/m dt/2,  w += T/I dt/2                  (its second half)
//
// and the optional phase of a quenched relaxation (relax/, scene/relaxation_def.hpp):
//
//   quench      v = 0 where F·v < 0,  w = 0 where T·w < 0
#pragma once
#include <cstdint>
#include <vector>

#include "neighbor/neighbours.hpp"
#include "state/particles.hpp"
#include "state/world.hpp"

namespace softpack {

/// With an active set (sim/active_set.hpp) only some spheres move: those listed (the awake
/// ones; driven ones among them are still skipped), while the sleeping ones stand still, with
/// the two largest squared displacements since the last neighbour build among them.
struct Movers {
  const std::vector<std::int32_t>* awake = nullptr;
  Neighbours::LargestTwo asleep_moved;
};

/// `movers`: null for every free sphere. `then_quench`: and quench() (in the same pass without
/// movers: the same values).
void half_kick(Particles& p, double dt, const Movers* movers = nullptr, bool then_quench = false);

/// The half kick, then x += v dt, sphere by sphere. Also starts the step's record of
/// displacements since the last neighbour build (neighbours.moved(); the drivers add their
/// spheres' to it); sleeping spheres' count too.
void kick_drift(Particles& p, double dt, Neighbours& neighbours, const Movers* movers = nullptr);

/// Per-grain velocity quench of the free spheres (after the second half kick).
void quench(Particles& p);

/// The free shells (walls/spherical_shell.hpp): velocity += load/m dt/2 and, with `rotation`,
/// spin += torque/I dt/2 (I = 2/3 m Rs^2); kinematic shells are left to their drivers.
void half_kick_shells(std::vector<SphericalShell>& shells, const std::vector<WallLoad>& loads, double dt, bool rotation);
/// centre += velocity dt for the free shells.
void drift_shells(std::vector<SphericalShell>& shells, double dt);

}  // namespace softpack
