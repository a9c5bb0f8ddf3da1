#!/usr/bin/env bash
# regression.recompute (issue 29): the current code, run on the archived per-seed results of this
# release, reproduces the archived averages, fits and verdict: a code change that alters a
# published number fails in CI (the sweeps are not rerun: seconds).
#
#   tests/regression/test_recompute.sh BIN_DIR SOURCE_DIR
# For each archived profile of the release (paper, select): softpack-average on its sweep results
# -> the averages' text columns equal the archive's; softpack-fit (its profile.yaml and
# criteria.yaml) -> every coefficient, error, judgement and candidate within 1e-12 relative;
# softpack-table -> the verdict's lines, selection and unit equal.
set -euo pipefail
bin=$1 root=$2
version=$(awk '/^project/ { print $3; exit }' "$root/CMakeLists.txt")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
found=0
for profile in paper select; do
  a=$root/data/archive/$version/$profile
  [[ -f $a/MANIFEST.sha256 ]] || { echo "no archive $a"; continue; }
  found=$((found + 1))
  w=$tmp/$profile && mkdir -p "$w/averages" "$w/fits" "$w/tables"
  for scene in soft-solid soft-soft; do
    "$bin/softpack-average" --scene $scene --profile $profile --config "$a/profile.yaml" \
      --normal $(ls "$a"/normal/$scene-seed-*.h5 | sort -V) --tangential $(ls "$a"/tangential/$scene-seed-*.h5 | sort -V) \
      --out-dir "$w/averages" 2> "$w/average.log" || { cat "$w/average.log"; fail "softpack-average $profile $scene"; }
    for dat in normal-$scene.dat tangential-$scene.dat kt-$scene.dat; do
      cmp -s <(grep -v '^#' "$a/averages/$dat") <(grep -v '^#' "$w/averages/$dat") ||
        fail "$profile: the averages $dat differ from the archive's: $(diff <(grep -v '^#' "$a/averages/$dat") <(grep -v '^#' "$w/averages/$dat") | head -4)"
    done
    "$bin/softpack-fit" --average "$w/averages/$scene.h5" --config "$a/profile.yaml" --criteria "$a/criteria.yaml" \
      --out "$w/fits/$scene.json" --quiet || fail "softpack-fit $profile $scene"
  done
  rs=$("$bin/softpack-config" "$a/profile.yaml" gnuplot | sed 's/^Rs=\([^;]*\);.*/\1/')
  "$bin/softpack-table" --fits "$w/fits/soft-solid.json" "$w/fits/soft-soft.json" --published "$root/experiments/published.yaml" \
    --out-dir "$w/tables" --averages "$w/averages/soft-solid.h5" "$w/averages/soft-soft.h5" --criteria "$a/criteria.yaml" \
    --Rs "$rs" > /dev/null || fail "softpack-table $profile"
  python3 - "$a" "$w" "$profile" <<'PY'
import json, math, sys
a, w, profile = sys.argv[1:]
def same(x, y, where):
    if isinstance(x, dict):
        for k in x:
            if k in ("provenance", "seconds", "cpu_seconds", "path", "notes"):
                continue
            if k not in y:
                sys.exit(f"FAIL: {profile}: {where}.{k} missing in the recomputed file")
            same(x[k], y[k], f"{where}.{k}")
    elif isinstance(x, list):
        if len(x) != len(y):
            sys.exit(f"FAIL: {profile}: {where}: {len(x)} entries archived, {len(y)} now")
        for i, (p, q) in enumerate(zip(x, y)):
            same(p, q, f"{where}[{i}]")
    elif isinstance(x, float) and isinstance(y, (int, float)):
        if not (x == y or abs(x - y) <= 1e-12 * max(abs(x), abs(y))):
            sys.exit(f"FAIL: {profile}: {where}: archived {x!r}, now {y!r}")
    elif x != y:
        sys.exit(f"FAIL: {profile}: {where}: archived {x!r}, now {y!r}")
for scene in ("soft-solid", "soft-soft"):
    same(json.load(open(f"{a}/fits/{scene}.json")), json.load(open(f"{w}/fits/{scene}.json")), f"fits/{scene}.json")
va, vw = json.load(open(f"{a}/tables/verdict.json")), json.load(open(f"{w}/tables/verdict.json"))
for key in ("lines", "selection", "unit", "curves", "reproduced", "judged"):
    same(va[key], vw[key], f"verdict.{key}")
print(f"ok: {profile}: the current code reproduces the archived averages, fits and verdict")
PY
done
(( found > 0 )) || fail "no archive of release $version under $root/data/archive: make archive first"
