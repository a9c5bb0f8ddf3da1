#!/usr/bin/env bash
# softpack-lammps (issue 34, docs/lammps.md) answers --help, runs the example of docs/lammps.md with
# the forces of the law file's Eq. 7 (soft-soft at Δn 0.3, soft-solid at 0.15, a wall's load at 0.2,
# to 1e-12), on one
# rank and on two, and stops with LAMMPS's ERROR line naming the bad value for a bad role or quench
# switch; softpack-coarse export --lammps refuses settings LAMMPS cannot carry.
source "$(dirname "$0")/common.sh"
exe=$1
root=$2
cd "$root"  # the example names the law file from the repository's root

"$exe" --help | grep -q "pair_style softpack/soft" || fail "--help does not name the pair style"
expected=$(python3 - <<'PY'
import json
d = json.load(open("data/radius/report/laws.json"))["scenes"]
def eq7(scene, dn):
    n = d[scene]["normal"]
    return n["a"]["value"] * dn ** n["b"]["value"] + n["c"]["value"] if dn >= n["delta"]["value"] else 0.0
print(f"{eq7('soft-soft', 0.0048 / 0.016):.17g} {eq7('soft-solid', 0.0024 / 0.016):.17g} {-2 * eq7('soft-solid', 0.0032 / 0.016):.17g}")
PY
)
check() {  # check LINE: the printed forces against Eq. 7
  python3 - "$1" $expected <<'PY' || fail "forces: $1 (expected $expected)"
import re, sys
line, expected = sys.argv[1], [float(v) for v in sys.argv[2:]]
got = [float(v) for v in re.findall(r"(-?[0-9.]+(?:e-?[0-9]+)?) N", line)]
assert len(got) == 3 and all(abs(g - e) <= 1e-12 * abs(e) for g, e in zip(got, expected)), (got, expected)
PY
}
check "$("$exe" -in examples/lammps/two-soft-particles.in -log none | grep '^soft-soft Fx')"
check "$(mpirun --allow-run-as-root --oversubscribe -np 2 "$exe" -in examples/lammps/two-soft-particles.in -log none | grep '^soft-soft Fx')"

# expect_lammps_error INPUT MESSAGE: LAMMPS stops (exit code not 0) with the ERROR line MESSAGE
expect_lammps_error() {
  set +e
  "$exe" -in "$1" -log none > "$tmp/out" 2>&1
  local code=$?
  set -e
  [ "$code" -ne 0 ] || fail "$1 ran (exit 0)"
  grep -qF "$2" "$tmp/out" || fail "$1: expected '$2', got: $(grep ERROR "$tmp/out")"
}
sed 's/softpack\/soft soft grain/softpack\/soft soft graim/' examples/lammps/two-soft-particles.in > "$tmp/bad.in"
expect_lammps_error "$tmp/bad.in" "ERROR: softpack/soft: role 'graim' is not allowed; allowed: soft, grain"
# fix softpack/quench takes yes or no
printf 'units si\natom_style sphere\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\nfix q all softpack/quench maybe\n' > "$tmp/quench.in"
expect_lammps_error "$tmp/quench.in" "ERROR: fix softpack/quench: 'maybe' is not allowed; allowed: yes, no"

# softpack-coarse export --lammps refuses what LAMMPS's input cannot carry, naming the key
coarse=$(dirname "$exe")/softpack-coarse
expect_error "coarse_grain.soft_particle.rotation: locked is not exported" "$tmp/locked" \
  "$coarse" export --lammps --config data/many-body-v6/profiles/spin-locked.yaml --medium data/many-body-v6/reference/media/seed-327.h5 --out "$tmp/locked"
