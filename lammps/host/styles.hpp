// softpack's styles added to a LAMMPS instance (issue 34): LAMMPS as Debian ships it has no plugin
// loader, so a host program registers them through the instance's own style maps before it reads
// an input (the way LAMMPS's own style_*.h entries are registered).
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace softpack::lammps {

/// What this adds: pair_style softpack/soft (pair/pair_soft_particle.hpp), the fix of its springs,
/// SOFTPACK/HISTORY (pair/soft_history.hpp), which the pair style makes itself, and its walls,
/// fix softpack/wall (pair/soft_wall.hpp), and the per-grain velocity quench, fix softpack/quench
/// (pair/soft_quench.hpp).

/// Adds softpack's styles to `lmp` (before its input is read).
void register_styles(LAMMPS_NS::LAMMPS* lmp);

}  // namespace softpack::lammps
