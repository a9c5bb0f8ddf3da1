// The soft-particle contact model as a LAMMPS pair style (issue 34): LAMMPS finds the pairs,
// ranks and ghosts; each pair's force is softpack's own model (contact/soft_particle_law.hpp
// SoftParticleModel, the one the engine's loops call), fed with the pair's geometry as the
// engine's sphere-sphere contacts make it (forces/pair_contacts.hpp), body 1 the atom of the
// smaller tag:
//
//   d = x_1 - x_2,  h = R_1 + R_2 - |d|,  n = d / |d|,
//   vc = v_1 - v_2 - (a_1 w_1 + a_2 w_2) x n,  a = R - h/2 (with rotation)
//
// so a pair of LAMMPS is a pair of the engine: the same law file, radius scaling, mixing rule and
// grain rule, the same damping at the contact's current stiffness, the same Tsuji spring (Eq. 8,
// μ_soft) with its history (pair/soft_history.hpp) and torques.
//
//   pair_style softpack/soft LAWFILE [grain_contact wall|reduced-radius] [restitution E]
//              [tangential_ratio X] [friction yes|no] [rotation yes|no]
//              [history_update synchronized|standard] [history K]
//   pair_coeff I J ROLE_I ROLE_J      ROLE: soft (a soft-particle) or grain (a solid sphere);
//                                     at least one soft: grain-grain pairs are `pair granular`'s
//                                     under pair_style hybrid (docs/lammps.md)
//
// With a law file's many_body (law file version 2 on), each soft-particle's state (its contacts'
// caps) and, for a law with a stress term, its stress tensor are summed over its contacts before
// the forces and sent to the ghosts, as the engine's per-body passes (the pattern of LAMMPS's EAM).
// Needs atom_style sphere (radius, rmass), comm_modify vel yes with damping or friction, and
// newton_pair off with friction or the many-body law (pair/soft_history.hpp says why).
// Its planes are fixes softpack/wall (pair/soft_wall.hpp), whose contacts it evaluates with the same
// model, in the same passes. docs/lammps.md lists what is not here yet.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "contact/soft_particle_law.hpp"
#include "pair/lammps_headers.hpp"

namespace softpack::lammps {

class PairSoftParticle : public LAMMPS_NS::Pair {
 public:
  static constexpr const char* kStyle = "softpack/soft";
  explicit PairSoftParticle(LAMMPS_NS::LAMMPS* lmp);
  ~PairSoftParticle() override;
  static LAMMPS_NS::Pair* create(LAMMPS_NS::LAMMPS* lmp) { return new PairSoftParticle(lmp); }

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  int pack_forward_comm(int n, int* list, double* buf, int pbc_flag, int* pbc) override;
  void unpack_forward_comm(int n, int first, double* buf) override;

 private:
  template <class Model, Effects Fx>
  void compute_pairs(const typename Model::Params& params);
  /// fn(i, j, a, b, d, r_sum) for each listed pair in contact with a soft-particle: i the local
  /// atom of the list, a and b the pair by tag (a the smaller), d = x_a - x_b.
  template <class F>
  void each_contact(F&& fn);
  ContactPartners partners(int a, int b, bool rotation) const;
  void body_passes();
  /// fn(i, wall index, h) for each local soft-particle of a wall's group touching it (h > 0).
  template <class F>
  void each_wall_contact(F&& fn);
  ContactPartners wall_partners(int i, bool rotation) const;
  LAMMPS_NS::tagint wall_key(std::size_t w) const;
  std::uint64_t signature() const;
  void allocate();
  [[noreturn]] void fail(const std::string& what) const;

  SoftParticleLaws laws_;
  std::string settings_text_;  ///< the pair_style arguments and the law file's bytes, for the signature
  GrainContactRule grain_rule_ = GrainContactRule::wall;
  ContactSetting setting_{};
  Effects fx_{true, false, true, true};  ///< friction, damping, rotation, synchronized (the engine's defaults)
  int history_capacity_ = 0;              ///< springs per atom (0: the fix's default)
  class FixSoftHistory* history_ = nullptr;
  std::vector<class FixSoftWall*> walls_;  ///< the fixes softpack/wall (init_style)
  SoftParticleModel::Params params_{};
  SoftManyBodyModel::Params many_params_{};  ///< with a law file's many_body
  // The many-body law's per-body values (body_passes), local and ghost atoms.
  std::vector<double> state_;
  std::vector<SymmetricTensor> stress_;
  struct Cap {
    LAMMPS_NS::tagint partner;
    Vec3 u;  ///< from the body's centre towards the contact
    double depth;
  };
  std::vector<std::vector<Cap>> caps_;  ///< per local atom
  std::vector<Vec3> cap_u_;             ///< one body's, for body_state
  std::vector<double> cap_depth_;
  enum class Forward { state, stress } forwarding_ = Forward::state;
  bool dry_run_ = false;  ///< a continuation's setup: the virial only (pair/soft_history.hpp)
  std::vector<int> soft_;          ///< per atom type (1-based): 1 soft, 0 grain, -1 not set
  std::vector<double> max_radius_;  ///< per atom type, over all ranks (init_style)
};

}  // namespace softpack::lammps
