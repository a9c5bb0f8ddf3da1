#include "pair/soft_history.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace softpack::lammps {

using LAMMPS_NS::tagint;
using LAMMPS_NS::ubuf;

FixSoftHistory::FixSoftHistory(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  if (narg > 4) error->all(FLERR, std::string("fix SOFTPACK/HISTORY: expected fix ID group SOFTPACK/HISTORY [K]"));  // a std::string: the literal overload is fmt-typed (pair/lammps_headers.hpp)
  if (narg == 4) {
    char* end = nullptr;
    const long k = std::strtol(arg[3], &end, 10);
    if (end == arg[3] || *end != '\0' || k < 1 || k > 100000)
      error->all(FLERR, fmt::format("fix SOFTPACK/HISTORY: '{}' springs per atom is not allowed; allowed: 1 to 100000", arg[3]));
    capacity_ = static_cast<int>(k);
  }
  restart_peratom = 1;
  restart_global = 1;
  create_attribute = 1;
  maxexchange = kLast + 1 + 4 * capacity_;
  grow_arrays(atom->nmax);
  atom->add_callback(LAMMPS_NS::Atom::GROW);
  atom->add_callback(LAMMPS_NS::Atom::RESTART);
  for (int i = 0; i < atom->nlocal; ++i) {
    count_[i] = 0;
    for (int k = 0; k < kLast; ++k) last_[i][k] = 0.0;
  }
}

FixSoftHistory::~FixSoftHistory() {
  atom->delete_callback(id, LAMMPS_NS::Atom::GROW);
  atom->delete_callback(id, LAMMPS_NS::Atom::RESTART);
  memory->destroy(count_);
  memory->destroy(partner_);
  memory->destroy(spring_);
  memory->destroy(touched_);
  memory->destroy(last_);
}

void FixSoftHistory::grow_arrays(int nmax) {
  memory->grow(count_, nmax, "softpack/history:count");
  memory->grow(partner_, nmax, capacity_, "softpack/history:partner");
  memory->grow(spring_, nmax, 3 * capacity_, "softpack/history:spring");
  memory->grow(touched_, nmax, capacity_, "softpack/history:touched");
  memory->grow(last_, nmax, kLast, "softpack/history:last");
}

void FixSoftHistory::copy_arrays(int i, int j, int) {
  count_[j] = count_[i];
  std::memcpy(partner_[j], partner_[i], sizeof(tagint) * static_cast<std::size_t>(count_[i]));
  std::memcpy(spring_[j], spring_[i], sizeof(double) * 3 * static_cast<std::size_t>(count_[i]));
  std::memcpy(touched_[j], touched_[i], static_cast<std::size_t>(count_[i]));
  std::memcpy(last_[j], last_[i], sizeof(double) * kLast);
}

int FixSoftHistory::pack_exchange(int i, double* buf) {
  int m = 0;
  for (int k = 0; k < kLast; ++k) buf[m++] = last_[i][k];
  buf[m++] = ubuf(count_[i]).d;
  for (int k = 0; k < count_[i]; ++k) {
    buf[m++] = ubuf(partner_[i][k]).d;
    for (int a = 0; a < 3; ++a) buf[m++] = spring_[i][3 * k + a];
  }
  return m;
}

int FixSoftHistory::unpack_exchange(int nlocal, double* buf) {
  int m = 0;
  for (int k = 0; k < kLast; ++k) last_[nlocal][k] = buf[m++];
  count_[nlocal] = static_cast<int>(ubuf(buf[m++]).i);
  if (count_[nlocal] < 0 || count_[nlocal] > capacity_)
    error->one(FLERR, fmt::format("fix SOFTPACK/HISTORY: an atom brings {} springs, more than the {} kept per atom; allowed: pair_style "
                                  "softpack/soft ... history K with K >= {} (after unfix {})",
                                  count_[nlocal], capacity_, count_[nlocal], kId));
  for (int k = 0; k < count_[nlocal]; ++k) {
    partner_[nlocal][k] = static_cast<tagint>(ubuf(buf[m++]).i);
    for (int a = 0; a < 3; ++a) spring_[nlocal][3 * k + a] = buf[m++];
    touched_[nlocal][k] = 0;
  }
  return m;
}

// LAMMPS's convention for a fix's per-atom restart values: the first is their count, a plain double
// (the fixes before this one are skipped by it).
int FixSoftHistory::pack_restart(int i, double* buf) {
  if (update->whichflag != 0) keep_state(i);  // written during a run, at a step's end: its forces belong to this state
  const int m = pack_exchange(i, buf + 1) + 1;
  buf[0] = m;
  return m;
}

void FixSoftHistory::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

double FixSoftHistory::memory_usage() {
  return static_cast<double>(atom->nmax) * (sizeof(int) + capacity_ * (sizeof(tagint) + 3 * sizeof(double) + 1));
}

double* FixSoftHistory::find(int i, tagint partner) {
  for (int k = 0; k < count_[i]; ++k)
    if (partner_[i][k] == partner) return &spring_[i][3 * k];
  return nullptr;
}

double* FixSoftHistory::find_or_add(int i, tagint partner) {
  if (double* s = find(i, partner)) return s;
  if (count_[i] == capacity_)
    error->one(FLERR, fmt::format("fix SOFTPACK/HISTORY: atom {} has {} open contacts, the most it keeps; allowed: a larger K "
                                  "(pair_style softpack/soft ... history K)",
                                  atom->tag[i], capacity_));
  const int k = count_[i]++;
  partner_[i][k] = partner;
  touched_[i][k] = 0;
  for (int a = 0; a < 3; ++a) spring_[i][3 * k + a] = 0.0;
  return &spring_[i][3 * k];
}

void FixSoftHistory::touch(int i, const double* spring) { touched_[i][(spring - spring_[i]) / 3] = 1; }

void FixSoftHistory::set_arrays(int i) {
  count_[i] = 0;
  for (int k = 0; k < kLast; ++k) last_[i][k] = 0.0;
}

void FixSoftHistory::keep_state(int i) {
  for (int a = 0; a < 3; ++a) last_[i][6 + a] = atom->x[i][a], last_[i][9 + a] = atom->v[i][a], last_[i][12 + a] = atom->omega ? atom->omega[i][a] : 0.0;
  last_[i][15] = atom->radius[i], last_[i][16] = atom->rmass[i], last_[i][17] = atom->type[i];
  last_[i][18] = 1.0;
}

void FixSoftHistory::post_run() {
  for (int i = 0; i < atom->nlocal; ++i) keep_state(i);
  if (signature) kept_signature_ = signature();
}

void FixSoftHistory::write_restart(FILE* fp) {
  if (update->whichflag != 0 && signature) kept_signature_ = signature();
  if (comm->me != 0) return;
  double value = 0.0;
  static_assert(sizeof(value) == sizeof(kept_signature_));
  std::memcpy(&value, &kept_signature_, sizeof(value));
  const int size = static_cast<int>(sizeof(double));
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(&value, sizeof(double), 1, fp);
}

void FixSoftHistory::restart(char* buf) { std::memcpy(&kept_signature_, buf, sizeof(kept_signature_)); }

void FixSoftHistory::clear_last(int nlocal) {
  for (int i = 0; i < nlocal; ++i)
    for (int k = 0; k < 6; ++k) last_[i][k] = 0.0;
}

bool FixSoftHistory::continues() {
  // With newton on a ghost's share is not kept: computed as LAMMPS does.
  int same = !force->newton_pair && signature && signature() == kept_signature_ ? 1 : 0;
  for (int i = 0; i < atom->nlocal && same; ++i) {
    same = last_[i][18] == 1.0 && last_[i][15] == atom->radius[i] && last_[i][16] == atom->rmass[i] && last_[i][17] == atom->type[i];
    for (int a = 0; a < 3 && same; ++a)
      same = last_[i][6 + a] == atom->x[i][a] && last_[i][9 + a] == atom->v[i][a] && last_[i][12 + a] == (atom->omega ? atom->omega[i][a] : 0.0);
  }
  int all = 0;
  MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, world);
  for (int i = 0; i < atom->nlocal; ++i) last_[i][18] = 0.0;
  return all == 1;
}

void FixSoftHistory::add_last(double** f, double** torque) {
  for (int i = 0; i < atom->nlocal; ++i)
    for (int a = 0; a < 3; ++a) {
      f[i][a] += last_[i][a];
      if (torque) torque[i][a] += last_[i][3 + a];
    }
}

void FixSoftHistory::prune(int nlocal) {
  for (int i = 0; i < nlocal; ++i) {
    const int n = count_[i];
    if (std::memchr(touched_[i], 0, static_cast<std::size_t>(n)) == nullptr) {  // every spring touched: none goes
      std::memset(touched_[i], 0, static_cast<std::size_t>(n));
      continue;
    }
    int kept = 0;
    for (int k = 0; k < count_[i]; ++k) {
      if (!touched_[i][k]) continue;
      partner_[i][kept] = partner_[i][k];
      for (int a = 0; a < 3; ++a) spring_[i][3 * kept + a] = spring_[i][3 * k + a];
      touched_[i][kept] = 0;
      ++kept;
    }
    count_[i] = kept;
  }
}

}  // namespace softpack::lammps
