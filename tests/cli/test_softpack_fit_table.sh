#!/usr/bin/env bash
# softpack-fit and softpack-table from the command line: --help; fits of fake seed averages
# (written with python3-h5py: Eq. 7 and 8 with the paper's coefficients) recover them; a
# tangential fit with too few points is written as null with the reason (exit 0); the tables
# are written and printed; bad input gives one message, exit code 2 and no output file.
# Exit 77 (skipped) without python3-h5py.
source "$(dirname "$0")/common.sh"
bin=$1
root=$2
py=/usr/bin/python3
"$py" -c 'import h5py, numpy' 2> /dev/null || { echo "python3-h5py is not installed: skipped"; exit 77; }

"$bin/softpack-fit" --help | grep -q -- "--average" || fail "softpack-fit --help"
"$bin/softpack-table" --help | grep -q -- "--published" || fail "softpack-table --help"

# fake SCENE A B C KT_A KT_B KT_POINTS FILE: Eq. 7 on delta_n 0..0.5 by 0.025 (stderr 1% of F
# plus 1e-4 N), Eq. 8 on delta_n 0.2..0.5 by 0.05 with kt > 0 at the last KT_POINTS only.
fake() {
  "$py" - "$@" << 'EOF'
import sys, h5py, numpy as np
scene, a, b, c, ka, kb, kpoints, path = sys.argv[1], *map(float, sys.argv[2:7]), int(sys.argv[7]), sys.argv[8]
delta = (-c / a) ** (1 / b)
dn = np.arange(21) * 0.025
F = np.where(dn >= delta, a * dn ** b + c, 0.0)
kdn = 0.2 + np.arange(7) * 0.05
kt = ka * (kdn ** kb - delta ** kb)
kt[: len(kt) - kpoints] = 0.0
with h5py.File(path, "w") as f:
    f["normal/delta_n"] = dn
    f["normal/Fn_mean"] = F
    f["normal/Fn_stderr"] = 0.01 * F + 1e-4
    f["normal/seeds"] = np.int64(7)
    f["kt/delta_n"] = kdn
    f["kt/mean"] = kt
    f["kt/stderr"] = 0.03 * np.abs(kt) + 1e-6
    f["provenance/scene"] = scene
    f["provenance/profile"] = "fake"
    f["provenance/code_version"] = "test"
EOF
}
fake soft-solid 73.669 2.799 -0.035 0.740 2.100 7 "$tmp/avg-solid.h5"
fake soft-soft 28.512 5.003 -0.002 0.982 4.422 2 "$tmp/avg-soft.h5"

"$bin/softpack-fit" --average "$tmp/avg-solid.h5" --out "$tmp/fit/soft-solid.json" --quiet
"$bin/softpack-fit" --average "$tmp/avg-soft.h5" --out "$tmp/fit/soft-soft.json" 2> "$tmp/log"
grep -q "no tangential fit" "$tmp/log" || fail "no word of the missing tangential fit: $(cat "$tmp/log")"
"$py" - "$tmp/fit" << 'EOF' || fail "fit files"
import json, sys
solid = json.load(open(sys.argv[1] + "/soft-solid.json"))
soft = json.load(open(sys.argv[1] + "/soft-soft.json"))
n, t = solid["normal"], solid["tangential"]
for key, value in [("a", 73.669), ("b", 2.799), ("c", -0.035)]:
    assert abs(n[key] - value) < 1e-6 * max(1, abs(value)), (key, n[key])
assert abs(n["delta"] - 0.065) < 5e-4 and n["weighted"] and n["points"] == 18, n
assert abs(t["a"] - 0.740) < 1e-6 and abs(t["b"] - 2.100) < 1e-6 and t["points"] == 7, t
assert solid["scene"] == "soft-solid" and solid["provenance"]["inputs"][0]["seeds"] == 7
assert "code_version" in solid["provenance"] and "seconds" in solid["provenance"]
assert soft["tangential"] is None and "at least 3" in soft["tangential_reason"], soft
assert abs(soft["normal"]["b"] - 5.003) < 1e-6
EOF

"$bin/softpack-table" --fits "$tmp/fit/soft-solid.json" "$tmp/fit/soft-soft.json" \
  --published "$root/experiments/published.yaml" --out-dir "$tmp/tables" > "$tmp/stdout"
for f in table1.md table1.tex table2.md table2.tex; do [ -s "$tmp/tables/$f" ] || fail "no $f"; done
grep -qF "| a [N] | 73.669 | 73.669 | 0.0% |" "$tmp/stdout" || fail "Table 1 on stdout: $(cat "$tmp/stdout")"
grep -qF "| a [N/m] | 0.74 | 0.740 | 0.0% | — | 0.982 | — |" "$tmp/stdout" || fail "Table 2 on stdout: $(cat "$tmp/stdout")"
grep -q "^% softpack-table" "$tmp/tables/table1.tex" || fail "no provenance in table1.tex"
grep -q '\\toprule' "$tmp/tables/table2.tex" || fail "table2.tex is not booktabs"

fit() { "$bin/softpack-fit" --average "$1" --out "$2" --quiet; }
out=$tmp/bad.json
fake soft-solid 73.669 2.799 -10.0 0.740 2.100 7 "$tmp/late.h5"  # delta = 0.49: one positive point
expect_error "1 point with Fn > 0 (the force starts at delta_n = 0.5)" "$out" fit "$tmp/late.h5" "$out"
expect_error "none.h5: no such file" "$out" fit "$tmp/none.h5" "$out"
"$py" -c "import h5py; f = h5py.File('$tmp/avg-solid.h5', 'a'); del f['provenance/scene']; f['provenance/scene'] = 'soft-hard'"
expect_error "/provenance/scene: 'soft-hard' is not allowed; allowed: soft-solid, soft-soft" "$out" fit "$tmp/avg-solid.h5" "$out"
"$py" -c "import h5py; f = h5py.File('$tmp/avg-soft.h5', 'a'); del f['normal/Fn_stderr']; f['normal/Fn_stderr'] = [1.0, 2.0]"
expect_error "/normal/Fn_stderr has 2 values but /normal/delta_n has 21" "$out" fit "$tmp/avg-soft.h5" "$out"

# fit.delta_n_max per scene: the bound of the average's scene is applied (and recorded), the
# other scene's is not.
printf 'profile: fake\nfit: {weighting: unweighted, delta_n_max: {soft-solid: 0.31, soft-soft: 0.45}}\n' > "$tmp/range.yaml"
"$bin/softpack-fit" --average "$tmp/late.h5" --config "$tmp/range.yaml" --out "$tmp/r.json" --quiet 2> /dev/null && fail "a fit of 0 loaded points"
fake soft-solid 73.669 2.799 -0.035 0.740 2.100 7 "$tmp/ranged.h5"
"$bin/softpack-fit" --average "$tmp/ranged.h5" --config "$tmp/range.yaml" --out "$tmp/r.json" --quiet || fail "ranged fit"
"$py" -c "
import json, sys
j = json.load(open('$tmp/r.json'))
n = j['normal']
assert j['options']['delta_n_max'] == 0.31, j['options']
assert abs(n['range'][1] - 0.3) < 1e-9, n['range']
assert abs(n['b'] - 2.799) < 1e-3, n['b']
" || fail "the soft-solid bound of a per-scene delta_n_max: $(cat "$tmp/r.json")"

table() { "$bin/softpack-table" --fits "$@" --published "$root/experiments/published.yaml" --out-dir "$tmp/t2"; }
expect_error "cannot open the file" "$tmp/t2" table "$tmp/fit/none.json"
expect_error "scene 'soft-solid' is given twice" "$tmp/t2" table "$tmp/fit/soft-solid.json" "$tmp/fit/soft-solid.json"
echo '{"scene": "soft-solid", "normal": {"a": 1}}' > "$tmp/fit/partial.json"
expect_error "normal.b: missing" "$tmp/t2" table "$tmp/fit/partial.json"
echo '{"scene": "soft-liquid", "normal": {"a": 1, "b": 2, "c": 3, "delta": 0}}' > "$tmp/fit/liquid.json"
expect_error "no scene 'soft-liquid'; allowed: soft-solid, soft-soft" "$tmp/t2" table "$tmp/fit/liquid.json"
echo 'not json' > "$tmp/fit/garbage.json"
expect_error "not a JSON file" "$tmp/t2" table "$tmp/fit/garbage.json"
echo "ok"
