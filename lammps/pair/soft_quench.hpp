// The per-grain velocity quench of the engine's relaxations (scene/relaxation_def.hpp, `quench`;
// docs/physics.md) as a LAMMPS fix (issue 34), for the coarse-grain compression's rest between
// increments (docs/coarse-grain.md, `relax`):
//
//   fix ID group softpack/quench [yes|no]
//   fix_modify ID quench yes|no
//
// While on (the argument, default yes; fix_modify switches it between runs), after every step (its
// end, after the second half kick of fix nve/sphere, with the forces of the new positions) an atom
// of the group whose force opposes its velocity, F·v < 0, has its velocity set to zero, and its spin
// when T·ω < 0 — as the engine's `half_kick` then `quench` do for every free sphere.
#pragma once
#include "pair/lammps_headers.hpp"

namespace softpack::lammps {

class FixSoftQuench : public LAMMPS_NS::Fix {
 public:
  static constexpr const char* kStyle = "softpack/quench";
  FixSoftQuench(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  static LAMMPS_NS::Fix* create(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) { return new FixSoftQuench(lmp, narg, arg); }

  int setmask() override { return LAMMPS_NS::FixConst::END_OF_STEP; }
  void end_of_step() override;
  int modify_param(int narg, char** arg) override;
  bool on = true;
};

}  // namespace softpack::lammps
