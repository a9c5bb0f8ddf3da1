// The two integration phases of velocity Verlet over the free spheres (a driven sphere's motion
// is prescribed by its driver, drivers/drivers.hpp):
//
//   half_kick   v += F/m dt/2,  w += T/I dt/2
//   drift       x += v dt
//
// and the optional phase of a quenched relaxation (relax/, scene/relaxation_def.hpp):
//
//   quench      v = 0 where F·v < 0,  w = 0 where T·w < 0
#pragma once
#include <cstdint>

#include "neighbor/neighbours.hpp"
#include "state/particles.hpp"

namespace softpack {

// `asleep` (one byte per sphere, or null): the spheres an active set holds at rest
// (sim/active_set.hpp), skipped like the driven ones.
void half_kick(Particles& p, double dt, const std::uint8_t* asleep = nullptr);

/// Also starts the step's record of displacements since the last neighbour build
/// (neighbours.moved(); the drivers add their spheres' to it).
void drift(Particles& p, double dt, Neighbours& neighbours, const std::uint8_t* asleep = nullptr);

/// Per-grain velocity quench of the free spheres (after the second half kick).
void quench(Particles& p);

}  // namespace softpack
