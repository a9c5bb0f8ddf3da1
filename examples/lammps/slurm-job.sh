#!/usr/bin/env bash
# softpack-lammps on a Slurm cluster (issue 34, docs/lammps.md): one LAMMPS input run under MPI, a
# rank per Slurm task, LAMMPS's domain decomposition across them.
#
#   sbatch --ntasks=64 examples/lammps/slurm-job.sh DIR [INPUT]
#
# from the repository's root (or set SOFTPACK_LAMMPS). DIR is the run's folder, which holds INPUT
# (default in.compression: softpack-coarse export --lammps --out DIR writes one) and gets its
# outputs (log.lammps; the export's curve.dat). What a user sets:
#   --ntasks (or --nodes and --ntasks-per-node)  the MPI ranks: about 10^4 bodies per rank or more
#                          keeps the parallel efficiency high (make bench, section 6, measures it);
#   --time, --mem-per-cpu  LAMMPS prints its memory per rank ("Per MPI rank memory allocation")
#                          at the run's start: about 2.5 kB a soft-particle with 64 springs each;
#   --partition, --account as the cluster wants;
#   SOFTPACK_LAMMPS        the executable (default: build/bin/softpack-lammps of the submit folder);
#   SOFTPACK_MPI           srun's --mpi plugin (default pmix: Debian's OpenMPI is built with PMIx;
#                          `srun --mpi=list` shows the cluster's).
# One thread per rank (OMP_NUM_THREADS=1): the soft-particle styles are MPI-parallel only.
#SBATCH --job-name=softpack-lammps
#SBATCH --ntasks=2
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=softpack-lammps-%j.out
set -euo pipefail
dir=${1:?usage: sbatch [--ntasks=N] examples/lammps/slurm-job.sh DIR [INPUT]}
input=${2:-in.compression}
exe=${SOFTPACK_LAMMPS:-${SLURM_SUBMIT_DIR:-$PWD}/build/bin/softpack-lammps}
[[ -x $exe ]] || { echo "slurm-job.sh: $exe is not an executable (make build; or set SOFTPACK_LAMMPS)" >&2; exit 2; }
[[ -f $dir/$input ]] || { echo "slurm-job.sh: $dir/$input: no such input" >&2; exit 2; }
export OMP_NUM_THREADS=1
cd "$dir"
srun --mpi="${SOFTPACK_MPI:-pmix}" "$exe" -in "$input" -log log.lammps -screen none
