#include "pair/soft_wall.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace softpack::lammps {

namespace {

double number_of(LAMMPS_NS::Error* error, const char* text, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v))
    error->all(FLERR, fmt::format("fix {}: {} '{}' is not a number", FixSoftWall::kStyle, what, text));
  return v;
}

}  // namespace

FixSoftWall::FixSoftWall(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  const std::string usage = fmt::format("fix ID group {} AXIS lo|hi POSITION [velocity VX VY VZ]", kStyle);
  if (narg != 6 && narg != 10) error->all(FLERR, fmt::format("fix {}: expected {}", kStyle, usage));
  const std::string axis = arg[3], side = arg[4];
  if (axis != "x" && axis != "y" && axis != "z") error->all(FLERR, fmt::format("fix {}: axis '{}' is not allowed; allowed: x, y, z", kStyle, axis));
  if (side != "lo" && side != "hi") error->all(FLERR, fmt::format("fix {}: side '{}' is not allowed; allowed: lo, hi", kStyle, side));
  const int a = axis[0] - 'x';
  normal = Vec3::Zero();
  normal[a] = side == "lo" ? 1.0 : -1.0;
  point = Vec3::Zero();
  point[a] = number_of(error, arg[5], "POSITION");
  if (narg == 10) {
    if (std::strcmp(arg[6], "velocity") != 0) error->all(FLERR, fmt::format("fix {}: '{}' is not a keyword; allowed: velocity", kStyle, arg[6]));
    for (int k = 0; k < 3; ++k) velocity[k] = number_of(error, arg[7 + k], "velocity");
  }
  // f_ID[1..3] the load (extensive), f_ID[4..6] the position (intensive)
  vector_flag = 1, size_vector = 6, global_freq = 1, extvector = -1;
  extlist = new int[6]{1, 1, 1, 0, 0, 0};
  restart_global = 1;
  time_integrate = 0;
}

// fix_modify ID velocity VX VY VZ: the wall moves at this velocity from the next step on.
int FixSoftWall::modify_param(int narg, char** arg) {
  if (std::strcmp(arg[0], "velocity") != 0) return 0;  // LAMMPS's "Illegal fix_modify command"
  if (narg < 4) error->all(FLERR, fmt::format("fix_modify {}: expected velocity VX VY VZ", id));
  for (int k = 0; k < 3; ++k) velocity[k] = number_of(error, arg[1 + k], "velocity");
  return 4;
}

int FixSoftWall::setmask() { return LAMMPS_NS::FixConst::INITIAL_INTEGRATE; }

void FixSoftWall::initial_integrate(int) {
  point += update->dt * velocity;
  surface_velocity = velocity;
}

void FixSoftWall::write_restart(FILE* fp) {
  double list[9];
  for (int a = 0; a < 3; ++a) list[a] = point[a], list[3 + a] = surface_velocity[a], list[6 + a] = load_total[a];
  if (comm->me == 0) {
    const int size = static_cast<int>(sizeof(list));
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(list, sizeof(double), 9, fp);
  }
}

void FixSoftWall::restart(char* buf) {
  double list[9];
  std::memcpy(list, buf, sizeof(list));
  for (int a = 0; a < 3; ++a) point[a] = list[a], surface_velocity[a] = list[3 + a], load_total[a] = list[6 + a];
}

void FixSoftWall::sum_load() { MPI_Allreduce(load.data(), load_total.data(), 3, MPI_DOUBLE, MPI_SUM, world); }

double FixSoftWall::compute_vector(int k) { return k < 3 ? load_total[k] : point[k - 3]; }

}  // namespace softpack::lammps
