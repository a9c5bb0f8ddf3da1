#!/usr/bin/env bash
# Fit options study (docs/fit.md, "The choice"): how much each weighting and onset threshold of
# the Eq. 7/8 fits depends on which soft-particles were measured.
#
#   workflow/studies/fit_options.sh [RESULTS] [WORK]
#       RESULTS: a folder with normal/ and tangential/ results of held-out seeds
#                (default data/fast-profile/reference: the paper profile on seeds 201-204)
#       WORK:    scratch folder (default: a temporary one, removed afterwards)
#
# For each option, the seeds' averages and fit (softpack-average, softpack-fit --config with a
# one-section profile), and the same for every leave-one-seed-out set: prints, per option, each
# coefficient on all seeds ± its jackknife standard error, as a Markdown table. Seconds; needs
# make build and python3.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
results=${1:-$root/data/fast-profile/reference}
work=${2:-$(mktemp -d)}
[[ -n ${2:-} ]] || trap 'rm -rf "$work"' EXIT
bin=$root/${BUILD:-build}/bin
options=("stderr|1.0e-9" "stderr|1.0e-3" "stderr|1.0e-2" "relative|1.0e-4" "relative|1.0e-3" "relative|1.0e-2"
         "unweighted|1.0e-4" "unweighted|1.0e-3" "unweighted|1.0e-2")
mapfile -t seeds < <(ls "$results"/normal/soft-solid-seed-*.h5 | sed 's/.*seed-\([0-9]*\)\.h5/\1/' | sort -n)
(( ${#seeds[@]} >= 3 )) || { echo "fit_options.sh: $results holds ${#seeds[@]} seeds; at least 3 are needed" >&2; exit 2; }
profile=$(basename "$results")
for scene in soft-solid soft-soft; do
  for leave in all "${seeds[@]}"; do
    normal=() tangential=()
    for s in "${seeds[@]}"; do
      [[ $s == "$leave" ]] && continue
      normal+=("$results/normal/$scene-seed-$s.h5") tangential+=("$results/tangential/$scene-seed-$s.h5")
    done
    mkdir -p "$work/$leave"
    "$bin/softpack-average" --scene "$scene" --profile "$profile" --normal "${normal[@]}" --tangential "${tangential[@]}" \
      --out-dir "$work/$leave" 2> /dev/null
    for o in "${options[@]}"; do
      name=${o%%|*}-${o#*|}
      printf 'profile: %s\nfit: {weighting: %s, onset_force: %s}\n' "$profile" "${o%%|*}" "${o#*|}" > "$work/$name.yaml"
      "$bin/softpack-fit" --average "$work/$leave/$scene.h5" --config "$work/$name.yaml" --out "$work/$leave/$scene-$name.json" \
        --quiet 2> "$work/$leave/$scene-$name.err" || true
    done
  done
done
python3 - "$work" "${seeds[*]}" "${options[@]}" <<'PY'
import json, math, os, sys
work, seeds, options = sys.argv[1], sys.argv[2].split(), sys.argv[3:]
def fit(leave, scene, name):
    p = f"{work}/{leave}/{scene}-{name}.json"
    return json.load(open(p)) if os.path.exists(p) and os.path.getsize(p) else None
for scene in ("soft-solid", "soft-soft"):
    print(f"\n{scene}, seeds {', '.join(seeds)}: value on all seeds ± jackknife standard error\n")
    print("| weighting, onset_force | a [N] | b | c [N] | delta | kt a | kt b | fitted range |\n|---|---|---|---|---|---|---|---|")
    for o in options:
        name = o.replace("|", "-")
        full = fit("all", scene, name)
        if not full:
            err = open(f"{work}/all/{scene}-{name}.err").read().strip().split(": ")[-1]
            print(f"| {o.replace('|', ', ')} | no fit: {err} | | | | | | |")
            continue
        cells = []
        for law, key in (("normal", "a"), ("normal", "b"), ("normal", "c"), ("normal", "delta"), ("tangential", "a"), ("tangential", "b")):
            v = full[law][key] if full[law] else float("nan")
            loo = [f[law][key] for f in (fit(s, scene, name) for s in seeds) if f and f[law]]
            n = len(loo)
            se = math.sqrt((n - 1) / n * sum((x - sum(loo) / n) ** 2 for x in loo)) if n == len(seeds) else float("nan")
            cells.append(f"{v:.4g} ± {se:.2g}")
        r = full["normal"]["range"]
        print(f"| {o.replace('|', ', ')} | " + " | ".join(cells) + f" | {r[0]}–{r[1]} |")
PY
