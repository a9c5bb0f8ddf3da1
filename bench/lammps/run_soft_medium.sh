#!/usr/bin/env bash
# softpack-lammps against the engine on soft-particle media (issue 34's targets; docs/lammps.md):
# usage  bench/lammps/run_soft_medium.sh BUILD_DIR
# For each size n (n^3 soft-particles, bench/lammps/soft_medium.py) and each law file (the pairwise
# laws, the many-body law's sixth version): the engine on one thread (softpack-run, its run's
# seconds), LAMMPS on one rank and on two (softpack-lammps under mpirun, its loop time), the same
# bodies, dt and steps, each the least of BENCH_REPEATS runs, one after the other. Prints a table
# and, last, key=value lines: the ratio LAMMPS / engine on one core and the efficiency on two ranks,
# t1 / (2 t2), of the largest medium with each law. Run nothing else beside it.
# Environment: BENCH_SOFT_SIZES (default "10 20 30"), BENCH_SOFT_STEPS (default 200), BENCH_REPEATS (2).
set -euo pipefail
die() { echo "run_soft_medium.sh: $*" >&2; exit 1; }
[ $# -eq 1 ] || die "usage: $0 BUILD_DIR"
build="$(cd "$1" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
run_exe="$build/bin/softpack-run" lammps_exe="$build/bin/softpack-lammps"
for exe in "$run_exe" "$lammps_exe"; do [ -x "$exe" ] || die "$exe missing: make build (softpack-lammps needs liblammps-dev: make setup)"; done
sizes="${BENCH_SOFT_SIZES:-10 20 30}" steps="${BENCH_SOFT_STEPS:-200}" repeats="${BENCH_REPEATS:-2}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_NUM_THREADS=1 SOFTPACK_THREADS=1
mpi=(mpirun --allow-run-as-root --oversubscribe)

declare -A last_ratio last_eff
last_bodies=0
least() { sort -g | head -1; }
engine_seconds() {  # the engine's run (stopped by its watchdog: the benchmark stops), its report's seconds
  "$run_exe" --scene "$1.yaml" --threads 1 --quiet --out "$tmp/report.json" 2> "$tmp/engine.err" \
    || { echo "run_soft_medium.sh: the engine's run of $1 failed: $(tail -1 "$tmp/engine.err")" >&2; return 1; }
  python3 -c "import json; print(json.load(open('$tmp/report.json'))['provenance']['seconds'])"
}
lammps_seconds() {  # RANKS: LAMMPS's loop time
  "${mpi[@]}" -np "$2" "$lammps_exe" -in "$1.in" -log none -screen "$tmp/screen" > /dev/null \
    || { echo "run_soft_medium.sh: LAMMPS on $2 ranks failed on $1: $(grep -m1 ERROR "$tmp/screen")" >&2; return 1; }
  awk '/^Loop time of/ {print $4}' "$tmp/screen"
}
times() {  # COMMAND ARGS...: BENCH_REPEATS times, each must succeed; the least
  local k out
  for k in $(seq "$repeats"); do out+="$("$@")"$'\n' || exit 1; done
  printf "%s" "$out" | least
}

printf "%-8s %-10s %14s %14s %9s %14s %10s\n" "bodies" "laws" "engine [us]" "LAMMPS 1 [us]" "L1 / eng" "LAMMPS 2 [us]" "eff. 2"
for n in $sizes; do
  for law in pairwise many-body; do
    # The many-body law at a quarter of the pairwise step: on this medium (every body pressed by six
    # at Δn 0.22) its gain makes the contacts stiffer than the engine's time step assumes (the
    # step comes from the pairwise laws), and at 0.2 the engine's watchdog stops the run.
    laws="$root/data/radius/report/laws.json" safety=0.2
    [ "$law" = many-body ] && laws="$root/data/many-body/report/laws-v6.json" safety=0.05
    base="$tmp/medium-$n-$law"
    python3 "$root/bench/lammps/soft_medium.py" "$n" "$laws" 1 0 "$base" "$safety"
    dt=$("$run_exe" --scene "$base.yaml" --threads 1 --quiet | python3 -c "import json, sys; print(repr(json.load(sys.stdin)['dt']))")
    python3 "$root/bench/lammps/soft_medium.py" "$n" "$laws" "$steps" "$dt" "$base" "$safety"
    e=$(times engine_seconds "$base") || exit 1
    l1=$(times lammps_seconds "$base" 1) || exit 1
    l2=$(times lammps_seconds "$base" 2) || exit 1
    bodies=$((n * n * n))
    awk -v b="$bodies" -v law="$law" -v s="$steps" -v e="$e" -v l1="$l1" -v l2="$l2" 'BEGIN {
      u = 1e6 / (b * s); printf "%-8d %-10s %14.3f %14.3f %9.2f %14.3f %9.0f%%\n", b, law, e * u, l1 * u, l1 / e, l2 * u, 100 * l1 / (2 * l2) }'
    last_ratio[$law]=$(awk -v e="$e" -v l="$l1" 'BEGIN {printf "%.3f", l / e}')
    last_eff[$law]=$(awk -v a="$l1" -v b="$l2" 'BEGIN {printf "%.3f", a / (2 * b)}')
    last_bodies=$((n * n * n))
  done
done
echo "largest_bodies=$last_bodies ratio_pairwise=${last_ratio[pairwise]} ratio_many_body=${last_ratio[many-body]} efficiency_pairwise=${last_eff[pairwise]} efficiency_many_body=${last_eff[many-body]}"
