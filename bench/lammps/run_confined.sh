#!/usr/bin/env bash
# Run the LAMMPS side of the confined-shell throughput benchmark.
# usage: run_confined.sh SPHERES.txt --Rs RS --dt DT --nsteps N (--alpha A | --ecor E')
#                        [--xgammat X] [--frictionless] [--neigh multi|bin] [--skin S] [--g G]
#   SPHERES.txt: first line a comment header, then 'x y z r' per line (SI).
#   --alpha A : softpack's damping constant; converted to LAMMPS's e' (tsuji_e.py)
#   --xgammat X: gamma_t/gamma_n (README C3); default 0.594088525786, the value that
#               softpack-bench-scene --parameters prints for the benchmark material
#   --neigh   : bin (default, measured fastest, README) or multi (3 diameter collections)
#   --skin    : Verlet skin in m (default: smallest radius)
# Prints LAMMPS's thermo (first/last step), its "Loop time" line and a summary
# line 'lammps_loop_time_s=... particle_steps_per_s=...'.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
LMP="${LMP:-/usr/bin/lmp}"
die() { echo "run_confined.sh: $*" >&2; exit 2; }

[ $# -ge 1 ] || die "usage: see header of $0"
spheres="$1"; shift
Rs= dt= nsteps= alpha= ecor= friction=1 neigh=bin skin= g=0 xgammat=0.594088525786
while [ $# -gt 0 ]; do
  case "$1" in
    --Rs) Rs="$2"; shift 2 ;;       --dt) dt="$2"; shift 2 ;;
    --nsteps) nsteps="$2"; shift 2 ;; --alpha) alpha="$2"; shift 2 ;;
    --ecor) ecor="$2"; shift 2 ;;   --frictionless) friction=0; shift ;;
    --neigh) neigh="$2"; shift 2 ;; --skin) skin="$2"; shift 2 ;;
    --g) g="$2"; shift 2 ;;         --xgammat) xgammat="$2"; shift 2 ;;
    *) die "unknown option $1" ;;
  esac
done
[ -r "$spheres" ] && [ -n "$Rs" ] && [ -n "$dt" ] && [ -n "$nsteps" ] || die "need SPHERES --Rs --dt --nsteps"
[ -n "$alpha$ecor" ] || die "need --alpha or --ecor"
[ -n "$ecor" ] || ecor="$(/usr/bin/python3 "$here/tsuji_e.py" "$alpha")"
case "$neigh" in multi|bin) ;; *) die "--neigh multi|bin" ;; esac

tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
# spheres -> LAMMPS data file (atom_style sphere: id type diameter density x y z)
read -r n rmin rmax < <(awk 'NR > 1 && NF >= 4 && $1 !~ /^#/ {
    n++; if (n == 1 || $4 < lo) lo = $4; if ($4 > hi) hi = $4 }
    END { printf "%d %.17g %.17g\n", n, lo, hi }' "$spheres")
[ "$n" -gt 0 ] || die "no spheres in $spheres"
awk -v Rs="$Rs" -v n="$n" 'BEGIN { b = 1.02 * Rs
    printf "LAMMPS data from softpack spheres\n\n%d atoms\n1 atom types\n\n", n
    printf "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\nAtoms # sphere\n\n", -b, b, -b, b, -b, b }
  NR > 1 && NF >= 4 && $1 !~ /^#/ { printf "%d 1 %.17g 2500 %s %s %s\n", ++i, 2 * $4, $1, $2, $3 }' \
  "$spheres" > "$tmp/spheres.data"

# neighbor: skin and 3 diameter collections spaced geometrically (polydisperse)
read -r skin c1 c2 c3 < <(awk -v lo="$rmin" -v hi="$rmax" -v s="$skin" 'BEGIN {
    q = (hi / lo) ^ (1 / 3); if (s == "") s = lo
    printf "%.9g %.9g %.9g %.9g\n", s, 2 * lo * q, 2 * lo * q * q, 2 * hi * 1.000001 }')

OMP_NUM_THREADS=1 "$LMP" -nocite -log none -screen "$tmp/screen" -in "$here/confined.in.template" \
  -var data "$tmp/spheres.data" -var Rs "$Rs" -var dt "$dt" -var nsteps "$nsteps" \
  -var ecor "$ecor" -var xgammat "$xgammat" -var friction "$friction" -var g "$g" -var skin "$skin" \
  -var nstyle "$neigh" -var c1 "$c1" -var c2 "$c2" -var c3 "$c3" \
  || { tail -20 "$tmp/screen" >&2; die "LAMMPS failed"; }

[ "$neigh" = multi ] && neigh="multi, collections d<=$c1,$c2,$c3"
echo "# N=$n Rs=$Rs dt=$dt nsteps=$nsteps e'=$ecor xgammat=$xgammat friction=$friction g=$g neighbor: $neigh skin=$skin"
sed -n '/^ *Step /,/^Loop time/p' "$tmp/screen"
grep -E '^(Section|Pair|Neigh|Comm|Modify|Other) |^(Neighbor list builds|Dangerous builds)' "$tmp/screen"
awk -v n="$n" -v s="$nsteps" '/^Loop time of/ { t = $4
    printf "lammps_loop_time_s=%s particle_steps_per_s=%.4g\n", t, n * s / t }' "$tmp/screen"
