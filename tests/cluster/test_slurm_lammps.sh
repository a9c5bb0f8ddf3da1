#!/usr/bin/env bash
# examples/lammps/slurm-job.sh (issue 34, docs/lammps.md) on a real single-node Slurm cluster,
# started for the test by tests/cluster/slurm_cluster.sh and stopped whatever happens: a short
# compression of a coarse medium (softpack-coarse export --lammps), submitted with sbatch
# --ntasks=2, runs on two ranks through srun and writes the same curve.dat, byte for byte, as the
# same input under mpirun -np 2. Exit 77 (skipped) when slurm-wlm or munge is not installed.
#
#   test_slurm_lammps.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) source_dir=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
cluster=$work/cluster
fail() { echo "FAIL: $*" >&2; exit 1; }
cleanup() {
  "$here"/slurm_cluster.sh stop "$cluster" || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM  # (the EXIT trap runs)

"$here"/slurm_cluster.sh start "$cluster" || exit $?
setsid bash -c 'while kill -0 '"$$"' 2> /dev/null; do sleep 2; done; "$0" stop "$1"; rm -rf "$2"' \
  "$here"/slurm_cluster.sh "$cluster" "$work" > /dev/null 2>&1 < /dev/null &
eval "$("$here"/slurm_cluster.sh env "$cluster")"

cd "$source_dir"  # the settings name their profile and law file from the repository
sed -e 's/^    strain: .*/    strain: 0.02/' -e 's/^    unload_strain: .*/    unload_strain: 0.005/' -e 's/^    shear: .*/    shear: 0.01/' \
  data/many-body-v6/profiles/reference.yaml > "$work/short.yaml"
medium=data/many-body-v6/reference/media/seed-327.h5
for run in slurm local; do
  "$build"/bin/softpack-coarse export --lammps --config "$work/short.yaml" --medium "$medium" --out "$work/$run"
done
(cd "$work/local" && mpirun --allow-run-as-root --oversubscribe -np 2 "$build"/bin/softpack-lammps -in in.compression -log log.lammps -screen none)

(cd "$work" && SOFTPACK_LAMMPS="$build"/bin/softpack-lammps sbatch --wait --quiet --ntasks=2 --output="$work/job.out" \
  "$source_dir"/examples/lammps/slurm-job.sh "$work/slurm") || fail "the job failed: $(cat "$work/job.out"; tail -3 "$work/slurm/log.lammps" 2> /dev/null)"
grep -q "on 2 procs" "$work/slurm/log.lammps" || fail "the job did not run on 2 ranks: $(grep -m1 'Loop time' "$work/slurm/log.lammps")"
[[ $(grep -vc '^#' "$work/slurm/curve.dat") -eq 8 ]] || fail "curve.dat: $(grep -vc '^#' "$work/slurm/curve.dat") rows, expected 8"
cmp -s "$work/slurm/curve.dat" "$work/local/curve.dat" || fail "the job's curve differs from mpirun -np 2's: $(diff "$work/slurm/curve.dat" "$work/local/curve.dat" | head -4)"
echo "slurm-job.sh: the compression on 2 ranks through srun, the same curve as mpirun -np 2"
