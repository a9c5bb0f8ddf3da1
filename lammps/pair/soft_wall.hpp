// A plane wall for the soft-particles of pair style softpack/soft (issue 34): the engine's plane
// (walls/plane_wall.hpp, forces/wall_contacts.hpp) in LAMMPS. The pair style evaluates its
// contacts with the same model as its pairs (a soft-particle on a plane: the soft-solid law at the
// particle's radius), counts them in the many-body law's states and tensors, and sums the wall's
// load, which the fix outputs (f_ID[1..3], the force on the wall [N], summed over ranks; f_ID[4..6]
// its position [m], which a region of LAMMPS's own walls can follow: docs/lammps.md):
//
//   fix ID group softpack/wall AXIS SIDE POSITION [velocity VX VY VZ]
//   fix_modify ID velocity VX VY VZ      (between runs: its velocity from the next step on)
//
// AXIS x, y or z; SIDE lo (the atoms above POSITION, the normal +AXIS) or hi (below, -AXIS); the
// plane moves at the constant velocity given (default at rest), its position advanced at each
// step's start, before the forces (as the engine's drivers move a wall within the step). Only the
// group's soft-particles meet it; solid grains meet LAMMPS's own walls (fix wall/gran).
#pragma once
#include "contact/soft_particle_law.hpp"
#include "pair/lammps_headers.hpp"

namespace softpack::lammps {

class FixSoftWall : public LAMMPS_NS::Fix {
 public:
  static constexpr const char* kStyle = "softpack/wall";
  FixSoftWall(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixSoftWall() override { delete[] extlist; }  // LAMMPS's Fix leaves it to the fix that made it
  static LAMMPS_NS::Fix* create(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) { return new FixSoftWall(lmp, narg, arg); }

  int setmask() override;
  void initial_integrate(int vflag) override;
  double compute_vector(int k) override;
  int modify_param(int narg, char** arg) override;
  /// Its position, the velocity its contacts see and its load, in restart files (a fix of the same
  /// ID and style given after read_restart takes them).
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

  // What the pair style reads and sums (pair/pair_soft_particle.cpp).
  Vec3 point = Vec3::Zero(), normal = Vec3::UnitZ(), velocity = Vec3::Zero();
  /// The velocity its contacts see: that of its last step's displacement (0 before its first step,
  /// as the engine's driven walls: a run's first forces are those of walls at rest).
  Vec3 surface_velocity = Vec3::Zero();
  Vec3 load = Vec3::Zero();        ///< the force on the wall from this rank's atoms, this step [N]
  Vec3 load_total = Vec3::Zero();  ///< the same from all ranks (sum_load, collective), its output
  void sum_load();
  /// h = r - (x - point)·normal (> 0 in contact).
  double overlap(const double* x, double r) const { return r - ((x[0] - point.x()) * normal.x() + (x[1] - point.y()) * normal.y() + (x[2] - point.z()) * normal.z()); }
  int group_bit() const { return groupbit; }
};

}  // namespace softpack::lammps
