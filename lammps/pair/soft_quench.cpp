#include "pair/soft_quench.hpp"

#include <fmt/format.h>

#include <cstring>
#include <string>

namespace softpack::lammps {

namespace {

// yes or no, else LAMMPS's error naming the fix and what is allowed.
bool switch_of(LAMMPS_NS::Error* error, const char* text, const char* where) {
  if (std::strcmp(text, "yes") == 0) return true;
  if (std::strcmp(text, "no") == 0) return false;
  error->all(FLERR, fmt::format("{} {}: '{}' is not allowed; allowed: yes, no", where, FixSoftQuench::kStyle, text));
  return false;
}

}  // namespace

FixSoftQuench::FixSoftQuench(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  if (narg != 3 && narg != 4) error->all(FLERR, fmt::format("fix {}: expected fix ID group {} [yes|no]", kStyle, kStyle));
  if (narg == 4) on = switch_of(error, arg[3], "fix");
  nevery = 1;
}

int FixSoftQuench::modify_param(int narg, char** arg) {
  if (std::strcmp(arg[0], "quench") != 0) return 0;  // LAMMPS's "Illegal fix_modify command"
  if (narg < 2) error->all(FLERR, fmt::format("fix_modify {}: expected quench yes|no", id));
  on = switch_of(error, arg[1], "fix_modify");
  return 2;
}

void FixSoftQuench::end_of_step() {
  if (!on) return;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const int* mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    if (f[i][0] * v[i][0] + f[i][1] * v[i][1] + f[i][2] * v[i][2] < 0.0) v[i][0] = v[i][1] = v[i][2] = 0.0;
    if (omega && torque && torque[i][0] * omega[i][0] + torque[i][1] * omega[i][1] + torque[i][2] * omega[i][2] < 0.0)
      omega[i][0] = omega[i][1] = omega[i][2] = 0.0;
  }
}

}  // namespace softpack::lammps
