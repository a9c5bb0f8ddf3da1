// softpack-lammps: LAMMPS as Debian ships it (liblammps), with softpack's soft-particle styles
// (host/styles.hpp). It takes LAMMPS's own command line: `mpirun -np 4 softpack-lammps -in in.medium`.
#include <mpi.h>

#include <cstdio>
#include <cstring>

#include "host/styles.hpp"
#include "pair/lammps_headers.hpp"

int main(int argc, char** argv) {
  for (int k = 1; k < argc; ++k)
    if (std::strcmp(argv[k], "--help") == 0) {
      std::printf(
          "softpack-lammps: LAMMPS (the Debian package's liblammps) with softpack's soft-particle styles\n\n"
          "usage: [mpirun -np N] softpack-lammps -in INPUT [LAMMPS's options: -log, -screen, -var, ...; -h lists them]\n\n"
          "styles added:\n"
          "  pair_style softpack/soft LAWFILE [grain_contact wall|reduced-radius] [restitution E] [tangential_ratio X]\n"
          "             [friction yes|no] [rotation yes|no] [history_update synchronized|standard] [history K]\n"
          "  pair_coeff I J ROLE_I ROLE_J   (ROLE: soft or grain, at least one soft)\n"
          "  (with friction: newton off; the springs' fix SOFTPACK/HISTORY is made by the pair style)\n"
          "  fix ID group softpack/wall AXIS lo|hi POSITION [velocity VX VY VZ]   (f_ID[1..3]: its load)\n\n"
          "docs/lammps.md says how a soft-particle medium is run with them.\n");
      return 0;
    }
  MPI_Init(&argc, &argv);
  auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  softpack::lammps::register_styles(lmp);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
