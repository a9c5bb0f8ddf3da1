// The simulation state in a point file (formats/sweep_file.hpp, its /state group;
// docs/reading-files.md): the spheres, the walls, the free shells' motion when the scene has free
// shells, and the tangential springs, enough to continue a run bit for bit (sim/simulation.hpp
// restore).
#pragma once
#include "io/hdf5_file.hpp"
#include "state/simulation_state.hpp"

namespace softpack {

/// Writes /state into an open file.
void write_state(h5::File& f, const SimulationState& s);

/// Reads /state; InputError names the file and the dataset when one is missing, of another
/// length than the spheres', or names a sphere the state does not have.
SimulationState read_state(const h5::File& f);

}  // namespace softpack
