#!/usr/bin/env bash
# Relaxation study: does the soft-soft normal law depend on how long each point relaxes?
#
#   workflow/studies/relaxation_stops.sh [STOPS] [WORK]      (defaults: 30, $DATA/studies/relaxation-stops)
#   make study-relaxation                                    (the same, with the packings made first)
#
# Reruns the paper profile's soft-soft normal sweep of every seed with STOPS stops of the paper's
# protocol instead of six (everything else as experiments/paper.yaml; about 4.5 min per seed on
# one core for 30 stops) and compares it, point by point, with the archived six-stop results of
# data/archive/<version>/paper/normal/. Needs the paper profile's packings ($DATA/paper/packings/,
# DATA=data by default: make packings) and
# python3-h5py. Prints a Markdown table (docs/measurement.md, "How long to relax"); the sweeps
# resume from WORK/seed-K/ when interrupted.
set -euo pipefail
stops=${1:-30}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
data=${DATA:-data}
work=${2:-$data/studies/relaxation-stops}
version=$(awk '/^project/ { print $3; exit }' CMakeLists.txt)  # as workflow/stamps.mk
archive=data/archive/$version/paper/normal
seeds=$(sed -n 's/^seeds: *\[\(.*\)\].*/\1/p' experiments/paper.yaml | tr ',' ' ')
[ -n "$seeds" ] || { echo "relaxation_stops: no 'seeds: [...]' line in experiments/paper.yaml" >&2; exit 2; }
[ -d "$archive" ] || { echo "relaxation_stops: no archived results $archive" >&2; exit 2; }
mkdir -p "$work"
config=$work/paper-$stops-stops.yaml
sed "s/^relaxation: .*/relaxation: {protocol: paper, stops: $stops, wait: 0.3, final_wait: 0.3}/" experiments/paper.yaml > "$config"
grep -q "stops: $stops," "$config" || { echo "relaxation_stops: no 'relaxation:' line to change in experiments/paper.yaml" >&2; exit 2; }

set -- $seeds
first=$1
for seed in $seeds; do
  shift
  next=${1:-$first}  # soft-soft pairs seed k with the next seed (workflow/sweeps.mk)
  out=$work/soft-soft-seed-$seed.h5
  [ -f "$out" ] && continue
  echo "relaxation_stops: seed $seed ($stops stops) -> $out" >&2
  build/bin/softpack-normal --config "$config" --scene soft-soft --seed "$seed" \
    --packing "$data"/paper/packings/seed-$seed.h5 --second-packing "$data"/paper/packings/seed-$next.h5 \
    --checkpoints "$work/seed-$seed" --out "$out" --quiet
done

/usr/bin/python3 - "$archive" "$work" "$stops" $seeds <<'EOF'
import sys, h5py, numpy as np
archive, work, stops, seeds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
rows = []
for s in seeds:
    a = h5py.File(f"{archive}/soft-soft-seed-{s}.h5", "r")
    b = h5py.File(f"{work}/soft-soft-seed-{s}.h5", "r")
    rows.append((s, a["delta_n"][:], a["Fn"][:], b["Fn"][:], a["relaxation/final_force_ratio"][:],
                 b["relaxation/final_force_ratio"][:]))
dn = rows[0][1]
show = [k for k in range(len(dn)) if dn[k] >= 0.4 - 1e-9]
print(f"Fn [mN] of soft-soft, six stops (archive) / {stops} stops, and the force ratio after them at the last point")
print()
print("| seed | " + " | ".join(f"Δn = {dn[k]:.3g}" for k in show) + " | Fn ratio at Δn = 0.5 | force ratio 6 / " + stops + " stops |")
print("|---" * (len(show) + 3) + "|")
for s, _, fa, fb, ra, rb in rows:
    print(f"| {s} | " + " | ".join(f"{1e3*fa[k]:.3g} / {1e3*fb[k]:.3g}" for k in show) +
          f" | {fb[-1]/fa[-1]:.2f} | {ra[-1]:.1e} / {rb[-1]:.1e} |")
fa = np.array([r[2] for r in rows]); fb = np.array([r[3] for r in rows])
n = len(rows)
def mean_err(x): return x.mean(), x.std(ddof=1) / np.sqrt(n)
print("| mean ± s.e. | " + " | ".join("{:.3g} ± {:.2g} / {:.3g} ± {:.2g}".format(
    *(1e3 * np.array(mean_err(fa[:, k]))), *(1e3 * np.array(mean_err(fb[:, k])))) for k in show) + " | | |")
EOF

# Are the states at rest relative to what is measured? The largest unbalanced grain force over
# the force on the second body, from the saved states: the study's, and the six-stop ones when
# this machine computed the paper profile ($DATA/paper/checkpoints; a clone that reused the
# archive has none).
/usr/bin/python3 - "$data/paper/checkpoints/normal/soft-soft" "$work" "$stops" $seeds <<'EOF'
import sys, os, h5py, numpy as np
six, work, stops, seeds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
def ratios(folder):
    if not os.path.isdir(folder): return None
    out = {}
    for name in sorted(os.listdir(folder)):
        f = h5py.File(os.path.join(folder, name), "r")
        body = np.linalg.norm(f["result/force"][:])
        grain = np.linalg.norm(f["state/F"][:], axis=1).max()
        out[round(float(f["result/delta_n"][()]), 6)] = grain / body if body > 0 else float("inf")
    return out
show = [0.425, 0.45, 0.475, 0.5]
cell = lambda r, d: "-" if r is None or d not in r else f"{r[d]:.1e}"
print()
print(f"Largest unbalanced grain force / force on the second body, six stops / {stops} stops")
print()
print("| seed | " + " | ".join(f"Δn = {d}" for d in show) + " |")
print("|---" * (len(show) + 1) + "|")
for s in seeds:
    a, b = ratios(f"{six}/seed-{s}"), ratios(f"{work}/seed-{s}")
    print(f"| {s} | " + " | ".join(f"{cell(a, d)} / {cell(b, d)}" for d in show) + " |")
EOF
