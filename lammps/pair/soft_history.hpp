// The soft-particle pairs' tangential springs in LAMMPS (issue 34): a fix that keeps, per atom, the
// springs of its open contacts keyed by the partner's tag, and carries them with the atom between
// ranks (pack_exchange) and into restart files (pack_restart) — LAMMPS's own history fix is not
// among Debian's headers. The pair style softpack/soft creates it (fix ID SOFTPACK_HISTORY) and runs
// with newton_pair off: a contact across two ranks is then computed on both, each keeping its own
// atom's copy, and both copies follow the same arithmetic (the pair oriented by tag, smaller first),
// so they stay the same bits. A spring is the engine's ξ of the pair (body 1 the smaller tag).
//
// It also makes a second run, or a run from a restart file, the continuation of the first: LAMMPS's
// run setup computes the forces again, with full-step velocities, where the step that ended the
// run had half-step ones (the damping, the Coulomb limit and the springs read them). So each atom
// keeps the pair style's force and torque on it from the last step and, at a run's end or in a
// restart written during a run, the state they belong to: its position, velocity, spin, radius,
// mass and type, and the pair style's signature (its settings, roles and walls, the number of
// atoms, the step). A setup that finds every atom and the signature the same (every rank checked)
// takes those forces instead of computing them and leaves the springs as they are. Anything
// changed between runs: the forces are computed, as LAMMPS does.
#pragma once
#include <cstdint>
#include <cstdio>
#include <functional>

#include "pair/lammps_headers.hpp"

namespace softpack::lammps {

class FixSoftHistory : public LAMMPS_NS::Fix {
 public:
  static constexpr const char* kStyle = "SOFTPACK/HISTORY";
  static constexpr const char* kId = "SOFTPACK_HISTORY";
  /// fix ID group SOFTPACK/HISTORY [K]: K springs per atom at most (default kDefaultCapacity).
  FixSoftHistory(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixSoftHistory() override;
  static LAMMPS_NS::Fix* create(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) { return new FixSoftHistory(lmp, narg, arg); }
  static constexpr int kDefaultCapacity = 64;

  int setmask() override { return LAMMPS_NS::FixConst::POST_RUN; }
  void post_run() override;
  /// The signature its kept forces belong to, in restart files.
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;
  int capacity() const { return capacity_; }
  /// The pair style's signature now (set by the pair style): its settings, roles, walls, the
  /// number of atoms, the step.
  std::function<std::uint64_t()> signature;
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int i) override { return 2 + kLast + 4 * count_[i]; }
  int maxsize_restart() override { return 2 + kLast + 4 * capacity_; }
  double memory_usage() override;

  /// Atom i's spring with the atom of tag `partner`: a pointer to its 3 doubles, or null.
  double* find(int i, LAMMPS_NS::tagint partner);
  /// The same, made (zero) when absent; an error when atom i has `capacity` springs already.
  double* find_or_add(int i, LAMMPS_NS::tagint partner);
  /// Marks atom i's spring k as used this step (`touched`); prune() drops the others (the
  /// contacts that opened: the engine clears their spring).
  void touch(int i, const double* spring);
  void prune(int nlocal);

  /// Atom i's force and torque from the pair style at the last step (6 values), which the pair
  /// style clears (clear_last) and sums into at each step.
  double* last(int i) { return last_[i]; }
  void clear_last(int nlocal);
  /// In a run's setup: whether every atom on every rank is where and as fast as its kept forces'
  /// step left it (collective); then add_last() adds them to f and torque. Either way the kept
  /// state is spent: a later setup computes unless a run's end or a restart keeps it again.
  bool continues();  // and the signature now equals the kept one
  void add_last(double** f, double** torque);

 private:
  int capacity_ = kDefaultCapacity;
  int* count_ = nullptr;
  LAMMPS_NS::tagint** partner_ = nullptr;
  double** spring_ = nullptr;  ///< 3 per partner
  char** touched_ = nullptr;
  /// Per atom: the pair style's F and T at the last step (0-5), the state they belong to (x 6-8,
  /// v 9-11, omega 12-14, radius 15, mass 16, type 17), and whether it is set (18).
  static constexpr int kLast = 19;
  double** last_ = nullptr;
  std::uint64_t kept_signature_ = 0;
  void keep_state(int i);
};

}  // namespace softpack::lammps
