#!/usr/bin/env bash
# softpack-lammps against the engine on soft-particle media (issue 34's targets; docs/lammps.md):
# usage  bench/lammps/run_soft_medium.sh BUILD_DIR
# For each size n (n^3 soft-particles, bench/lammps/soft_medium.py) and each law file (the pairwise
# laws, the many-body law's sixth version), the same bodies, dt and steps, one run after the other:
#   the engine on one thread: softpack-run of S and of 2S steps, the time of a step (t(2S) - t(S)) / S,
#     so that neither its scene's reading nor its set-up is counted;
#   LAMMPS on one rank and on two (strong scaling: the same medium): softpack-lammps under mpirun,
#     its loop time of S steps (LAMMPS's set-up is outside it) / S;
#   LAMMPS on two ranks on a medium of n x n x 2n (weak scaling: the same bodies per rank);
# each the least of BENCH_REPEATS runs. Prints a table (us per body-step; the efficiencies
# t1 / (2 t2) strong and t1(n^3) / t2(n x n x 2n) weak; the largest memory of a rank, LAMMPS's
# own count, and the engine's resident peak) and, last, key=value lines for the largest medium.
# S: BENCH_SOFT_STEPS if set, else BENCH_SOFT_BODY_STEPS / n^3 (default 5.4e6, 200 steps at 30^3),
# at least 20. Run nothing else beside it.
# Environment: BENCH_SOFT_SIZES (default "10 20 30"), BENCH_SOFT_STEPS, BENCH_SOFT_BODY_STEPS, BENCH_REPEATS (2),
# BENCH_SOFT_ENGINE_SIZES (default: every size): the sizes the engine runs too (its scene is YAML, a
# minute and gigabytes to read at 10^6 bodies; above them only LAMMPS runs).
set -euo pipefail
die() { echo "run_soft_medium.sh: $*" >&2; exit 1; }
[ $# -eq 1 ] || die "usage: $0 BUILD_DIR"
build="$(cd "$1" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
run_exe="$build/bin/softpack-run" lammps_exe="$build/bin/softpack-lammps"
for exe in "$run_exe" "$lammps_exe"; do [ -x "$exe" ] || die "$exe missing: make build (softpack-lammps needs liblammps-dev: make setup)"; done
sizes="${BENCH_SOFT_SIZES:-10 20 30}" engine_sizes="${BENCH_SOFT_ENGINE_SIZES:-${BENCH_SOFT_SIZES:-10 20 30}}" body_steps="${BENCH_SOFT_BODY_STEPS:-5.4e6}" repeats="${BENCH_REPEATS:-2}"
steps_for() { [ -n "${BENCH_SOFT_STEPS:-}" ] && { echo "$BENCH_SOFT_STEPS"; return; }; awk -v b="$body_steps" -v n="$1" 'BEGIN {s = int(b / (n * n * n) + 0.5); print (s < 20 ? 20 : s)}'; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_NUM_THREADS=1 SOFTPACK_THREADS=1
mpi=(mpirun --allow-run-as-root --oversubscribe)

declare -A last_ratio last_eff last_weak last_step
last_bodies=0
least() { sort -g | head -1; }
engine_seconds() {  # SCENE: the engine's run (stopped by its watchdog: the benchmark stops), its report's seconds; its peak RSS [kB] in $tmp/rss
  /usr/bin/time -f "%M" -o "$tmp/rss" "$run_exe" --scene "$1.yaml" --threads 1 --quiet --out "$tmp/report.json" 2> "$tmp/engine.err" \
    || { echo "run_soft_medium.sh: the engine's run of $1 failed: $(tail -1 "$tmp/engine.err")" >&2; return 1; }
  python3 -c "import json; print(json.load(open('$tmp/report.json'))['provenance']['seconds'])"
}
engine_step() {  # BASE S: (t(2S) - t(S)) / S from the scenes BASE-S.yaml and BASE-2S.yaml
  local a b
  a=$(engine_seconds "$1-$2") || return 1
  b=$(engine_seconds "$1-$(($2 * 2))") || return 1
  awk -v a="$a" -v b="$b" -v s="$2" 'BEGIN {printf "%.9g\n", (b - a) / s}'
}
lammps_step() {  # BASE RANKS S: LAMMPS's loop time / S; its largest memory per rank [MB] in $tmp/mem-RANKS
  "${mpi[@]}" -np "$2" "$lammps_exe" -in "$1.in" -log none -screen "$tmp/screen" > /dev/null \
    || { echo "run_soft_medium.sh: LAMMPS on $2 ranks failed on $1: $(grep -m1 ERROR "$tmp/screen")" >&2; return 1; }
  awk '/memory allocation/ {m = $(NF - 1)} END {print m}' "$tmp/screen" > "$tmp/mem-$2"
  awk -v s="$3" '/^Loop time of/ {printf "%.9g\n", $4 / s}' "$tmp/screen"
}
times() {  # COMMAND ARGS...: BENCH_REPEATS times, each must succeed; the least
  local k out
  for k in $(seq "$repeats"); do out+="$("$@")"$'\n' || exit 1; done
  printf "%s" "$out" | least
}

printf "%-8s %-10s %6s %12s %13s %8s %13s %9s %13s %8s %11s %10s\n" "bodies" "laws" "steps" "engine [us]" "LAMMPS 1 [us]" "L1/eng" \
  "LAMMPS 2 [us]" "strong 2" "weak 2 [us]" "weak 2" "LAMMPS [MB]" "eng. [MB]"
for n in $sizes; do
  steps=$(steps_for "$n")
  for law in pairwise many-body; do
    # The many-body law at a quarter of the pairwise step: on this medium (every body pressed by six
    # at Δn 0.22) its gain makes the contacts stiffer than the engine's time step assumes (the
    # step comes from the pairwise laws), and at 0.2 the engine's watchdog stops the run.
    laws="$root/data/radius/report/laws.json" safety=0.2
    [ "$law" = many-body ] && laws="$root/data/many-body/report/laws-v6.json" safety=0.05
    base="$tmp/medium-$n-$law"
    # the engine's step for this medium (a medium of 2^3 bodies with the same laws and safety has it)
    python3 "$root/bench/lammps/soft_medium.py" 2 "$laws" 1 0 "$base" "$safety"
    dt=$("$run_exe" --scene "$base.yaml" --threads 1 --quiet | python3 -c "import json, sys; print(repr(json.load(sys.stdin)['dt']))")
    python3 "$root/bench/lammps/soft_medium.py" "$n" "$laws" "$steps" "$dt" "$base-$steps" "$safety"
    python3 "$root/bench/lammps/soft_medium.py" "$n,$n,$((2 * n))" "$laws" "$steps" "$dt" "$base-weak" "$safety"
    e=nan rss=nan
    if [[ " $engine_sizes " == *" $n "* ]]; then
      python3 "$root/bench/lammps/soft_medium.py" "$n" "$laws" $((2 * steps)) "$dt" "$base-$((2 * steps))" "$safety"
      e=$(times engine_step "$base" "$steps") || exit 1
      rss=$(cat "$tmp/rss")
    fi
    l1=$(times lammps_step "$base-$steps" 1 "$steps") || exit 1
    l2=$(times lammps_step "$base-$steps" 2 "$steps") || exit 1
    mem=$(cat "$tmp/mem-1")
    w2=$(times lammps_step "$base-weak" 2 "$steps") || exit 1
    rm -f "$base"-*.yaml "$base"-*.data
    bodies=$((n * n * n))
    awk -v b="$bodies" -v law="$law" -v s="$steps" -v e="$e" -v l1="$l1" -v l2="$l2" -v w2="$w2" -v mem="$mem" -v rss="$rss" 'BEGIN {
      u = 1e6 / b; engine = e != "nan"
      printf "%-8d %-10s %6d %12s %13.3f %8s %13.3f %8.0f%% %13.3f %7.0f%% %11.0f %10s\n", b, law, s, engine ? sprintf("%.3f", e * u) : "-", l1 * u,
        engine ? sprintf("%.2f", l1 / e) : "-", l2 * u, 100 * l1 / (2 * l2), w2 * u / 2, 100 * l1 / w2, mem, engine ? sprintf("%.0f", rss / 1024) : "-" }'
    [ "$e" = nan ] || last_ratio[$law]=$(awk -v e="$e" -v l="$l1" 'BEGIN {printf "%.3f", l / e}') last_engine_bodies=$bodies
    last_eff[$law]=$(awk -v a="$l1" -v b="$l2" 'BEGIN {printf "%.3f", a / (2 * b)}')
    last_weak[$law]=$(awk -v a="$l1" -v b="$w2" 'BEGIN {printf "%.3f", a / b}')
    last_bodies=$bodies last_step[$law]=$l1
  done
done
echo "largest_bodies=$last_bodies largest_engine_bodies=${last_engine_bodies:-0} ratio_pairwise=${last_ratio[pairwise]} ratio_many_body=${last_ratio[many-body]} efficiency_pairwise=${last_eff[pairwise]} efficiency_many_body=${last_eff[many-body]} weak_efficiency_pairwise=${last_weak[pairwise]} weak_efficiency_many_body=${last_weak[many-body]} lammps_seconds_per_step_pairwise=${last_step[pairwise]} lammps_seconds_per_step_many_body=${last_step[many-body]}"
