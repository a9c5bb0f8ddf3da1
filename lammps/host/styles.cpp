#include "host/styles.hpp"

#include "pair/lammps_headers.hpp"
#include "pair/pair_soft_particle.hpp"
#include "pair/soft_history.hpp"
#include "pair/soft_quench.hpp"
#include "pair/soft_wall.hpp"

namespace softpack::lammps {

void register_styles(LAMMPS_NS::LAMMPS* lmp) {
  (*lmp->force->pair_map)[PairSoftParticle::kStyle] = &PairSoftParticle::create;
  (*lmp->modify->fix_map)[FixSoftHistory::kStyle] = &FixSoftHistory::create;
  (*lmp->modify->fix_map)[FixSoftWall::kStyle] = &FixSoftWall::create;
  (*lmp->modify->fix_map)[FixSoftQuench::kStyle] = &FixSoftQuench::create;
}

}  // namespace softpack::lammps
