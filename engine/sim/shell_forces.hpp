// Sphere-shell contacts of one shell, vectorised over contacts as sim/pair_forces.cpp does for
// sphere pairs: the touching entries are copied into a structure-of-arrays batch, evaluated lane
// by lane in a loop the compiler vectorises, then added to the spheres and to the shell's load
// in list order.
//
// Same physics and the same arithmetic, operation for operation, as the per-contact routines
// advance_spring() and contact_force() of contact/contact_force.hpp with the shell's geometry
// (walls/spherical_shell.hpp): body 1 is the sphere, body 2 the shell, the normal points inward.
// tests/physics/test_shell_forces.cpp keeps that per-contact loop and checks the bits.
#pragma once
#include "core/types.hpp"
#include "neighbor/contact_list.hpp"
#include "sim/pair_forces.hpp"
#include "walls/spherical_shell.hpp"

namespace softpack {

/// Adds the force (and torque) of every touching entry of `list` to its sphere, and minus the
/// force, with its torque about the shell's centre, to `load_force` and `load_torque`. Advances
/// the springs of touching entries by `spring_dt` and clears those of open ones.
void accumulate_shell_forces(WallList& list, const SphericalShell& shell, const PairForceArrays& a,
                             const PairForceEffects& fx, double spring_dt, Vec3& load_force, Vec3& load_torque);

}  // namespace softpack
