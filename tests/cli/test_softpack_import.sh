#!/usr/bin/env bash
# softpack-import (docs/import.md): packings written by another program are imported and swept.
#   1. A LAMMPS data file (atom_style sphere, millimetres, the shell off the origin, image flags,
#      a Velocities section), an extended XYZ file (our own --xyz export) and "x y z r" text, each
#      written from a generated packing, import to the generated spheres (to 1e-12 of Rs), with
#      the source's SHA-256 and the options as provenance; the stamps follow the source's bytes.
#   2. (make tables figures on a normal-only profile of imported packings: workflow.import_dag)
#   3. The direct path on a grid that does not start at 0: each point is what a one-point sweep
#      at its Delta_n gives, bit for bit (every point starts from the scene as built).
#   4. Bad input: overlapping grains, a grain beyond the shell, a missing seed, another atom
#      style, a count that disagrees, a non-cubic box read as the shell, generator keys beside
#      import; each one message naming the file and line or key, exit 2, no output.
#
#   test_softpack_import.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
bin=$1
root=$2
py=/usr/bin/python3
$py -c "import h5py" 2> /dev/null || { echo "skipped: python3-h5py is not installed (make setup)"; exit 77; }
"$bin/softpack-import" --help | grep -q -- "--seed" || fail "softpack-import --help"
source "$(dirname "$0")/import_inputs.sh"

# --- 1. three formats, one generated packing --------------------------------------------------------
import_inputs
profile "$tmp/lammps.yaml" "$(import_section "$tmp/run-1.data" "$tmp/run-2.data" $'    length_unit: 1.0e-3\n    shell: read\n')"
profile "$tmp/xyz.yaml" "$(import_section "$tmp/gen-1.xyz" "$tmp/gen-2.xyz" $'    shell: read\n')"
profile "$tmp/text.yaml" "$(import_section "$tmp/run-1.txt" "$tmp/run-2.txt" $'    shell: {radius: 0.016, centre: [0, 0, 0]}\n')"
for f in lammps xyz text; do
  "$bin/softpack-import" --config "$tmp/$f.yaml" --seed 1 --out "$tmp/$f-1.h5" --vtp "$tmp/$f-1.vtp" 2> "$tmp/$f.log" ||
    fail "import of the $f file: $(cat "$tmp/$f.log")"
  grep -q "spheres from" "$tmp/$f.log" || fail "no summary line for $f"
done
$py - "$tmp" "$(sha256sum "$tmp/run-1.data" | cut -d' ' -f1)" <<'PY' || fail "the imported spheres differ from the generated ones"
import sys, h5py, numpy as np
d, sha = sys.argv[1], sys.argv[2]
g = h5py.File(f"{d}/gen-1.h5", "r")
R = g["shell/radius"][()]
for fmt in ("lammps", "xyz", "text"):
    f = h5py.File(f"{d}/{fmt}-1.h5", "r")
    assert f["provenance/program"][()].decode() == "softpack-import", fmt
    assert f["imported/format"][()].decode() == fmt, fmt
    assert len(f["radii"]) == len(g["radii"]), (fmt, len(f["radii"]))
    dx = np.abs(f["centres"][()] - g["centres"][()]).max() / R
    dr = np.abs(f["radii"][()] - g["radii"][()]).max() / R
    assert dx < 1e-12 and dr < 1e-12, (fmt, dx, dr)
    assert abs(f["shell/radius"][()] - R) < 1e-12 * R, (fmt, f["shell/radius"][()])
    assert abs(f["stats/solid_fraction"][()] - g["stats/solid_fraction"][()]) < 1e-9, fmt
l = h5py.File(f"{d}/lammps-1.h5", "r")
assert l["imported/source_sha256"][()].decode() == sha
assert np.allclose(l["imported/shell_centre_in_file"][()], [2.5, -1.0, 7.0], rtol=0, atol=1e-12)
assert l["imported/shell"][()].decode() == "read" and l["imported/length_unit"][()] == 1e-3
assert "length_unit: 1.0e-3" in l["provenance/config"][()].decode()
print("ok")
PY
echo "ok: LAMMPS data, extended XYZ and text import to the generated spheres, with the source's SHA-256"
stamp() { "$bin/softpack-config" "$tmp/lammps.yaml" stamp "$1"; }
before=$(stamp packing) normal_before=$(stamp normal)
cp "$tmp/run-2.data" "$tmp/run-2.orig"
sed -i '1s/$/ (edited)/' "$tmp/run-2.data"
[[ $(stamp packing) != "$before" && $(stamp normal) != "$normal_before" ]] || fail "editing a source file left the stamps as they were"
cp "$tmp/run-2.orig" "$tmp/run-2.data"
[[ $(stamp packing) == "$before" ]] || fail "the stamp did not come back with the source file"
"$bin/softpack-config" "$tmp/lammps.yaml" stages | grep -qx "packing normal" || fail "a normal-only profile: stages"
echo "ok: the stamps follow the source files' bytes; a profile without tangential has the stages packing normal"
# Enclosing shells: one radius for every seed (the larger), each seed its own centre.
profile "$tmp/enclosing.yaml" "$(import_section "$tmp/run-1.txt" "$tmp/run-2.txt" $'    shell: enclosing\n')"
for s in 1 2; do "$bin/softpack-import" --config "$tmp/enclosing.yaml" --seed $s --out "$tmp/enc-$s.h5" --quiet; done
$py - "$tmp" <<'PY' || fail "enclosing shells: not one radius for both seeds"
import sys, h5py, numpy as np
d = sys.argv[1]
R = [h5py.File(f"{d}/enc-{s}.h5", "r")["shell/radius"][()] for s in (1, 2)]
reach = [max(np.linalg.norm(f["centres"][()], axis=1) + f["radii"][()]) for f in (h5py.File(f"{d}/enc-{s}.h5", "r") for s in (1, 2))]
assert R[0] == R[1] and abs(max(reach) - R[0]) < 1e-12 * R[0] and min(reach) <= R[0], (R, reach)
print("ok")
PY
echo "ok: enclosing shells share the larger radius across seeds"

# --- 3. the direct path from a grid that does not start at 0 -------------------------------------------
profile "$tmp/direct.yaml" "$(import_section "$tmp/run-1.data" "$tmp/run-2.data" $'    length_unit: 1.0e-3\n    shell: read\n')" "[0.2, 0.4]"
sed -i 's/path: incremental/path: direct/' "$tmp/direct.yaml"
sed 's/delta_n: \[0.2, 0.4\]/delta_n: [0.4]/' "$tmp/direct.yaml" > "$tmp/direct-one.yaml"
pk=$tmp/lammps-1.h5  # seed 1 imported from the LAMMPS file (section 1)
for p in direct direct-one; do
  "$bin/softpack-normal" --config "$tmp/$p.yaml" --scene soft-solid --seed 1 --packing "$pk" --checkpoints "$tmp/ck-$p" \
    --out "$tmp/$p.h5" --quiet
done
$py - "$tmp/direct.h5" "$tmp/direct-one.h5" <<'PY' || fail "direct path: the point at 0.4 differs from a one-point sweep"
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
assert list(a["delta_n"][()]) == [0.2, 0.4] and list(b["delta_n"][()]) == [0.4]
assert a["Fn"][1] == b["Fn"][0] and a["steps"][1] == b["steps"][0], (a["Fn"][()], b["Fn"][()], a["steps"][()], b["steps"][()])
assert np.array_equal(a["force"][1], b["force"][0])
print("ok")
PY
echo "ok: the direct path from delta_n 0.2: the point at 0.4 is a one-point sweep's, bit for bit"

# --- 4. bad input ------------------------------------------------------------------------------------------
out=$tmp/bad.h5
imp() { "$bin/softpack-import" --config "$1" --seed "${2:-1}" --out "$out" --quiet; }
bad_profile() { profile "$tmp/bad.yaml" "$(import_section "$1" "$tmp/run-2.data" "$2")"; }
unit=$'    length_unit: 1.0e-3\n    shell: read\n'
awk '/Atoms/ {a = 1} a && $1 == 2 && NF == 10 {$5 = x5; $6 = x6; $7 = x7} a && $1 == 1 && NF == 10 {x5 = $5; x6 = $6; x7 = $7} {print}' \
  "$tmp/run-1.data" > "$tmp/overlap.data"
bad_profile "$tmp/overlap.data" "$unit"
expect_error "overlap.data:" "$out" imp "$tmp/bad.yaml"
expect_error "of the smaller radius; allowed: packing.import.overlap_tolerance = 1e-06" "$out" imp "$tmp/bad.yaml"
awk '/Atoms/ {a = 1} a && $1 == 3 && NF == 10 {$5 = $5 + 100} {print}' "$tmp/run-1.data" > "$tmp/outside.data"
bad_profile "$tmp/outside.data" "$unit"
expect_error "beyond the shell" "$out" imp "$tmp/bad.yaml"
sed 's/Atoms # sphere/Atoms # atomic/' "$tmp/run-1.data" > "$tmp/atomic.data"
bad_profile "$tmp/atomic.data" "$unit"
expect_error "atom_style atomic: softpack-import reads atom_style sphere" "$out" imp "$tmp/bad.yaml"
sed 's/^\([0-9]*\) atoms$/9999 atoms/' "$tmp/run-1.data" > "$tmp/count.data"
bad_profile "$tmp/count.data" "$unit"
expect_error "the header says 9999 atoms" "$out" imp "$tmp/bad.yaml"
awk '$3 == "zlo" {$2 = $2 + 1} {print}' "$tmp/run-1.data" > "$tmp/box.data"
bad_profile "$tmp/box.data" "$unit"
expect_error "shell: read needs a cubic box" "$out" imp "$tmp/bad.yaml"
bad_profile "$tmp/run-1.txt" $'    shell: read\n'
expect_error "the file gives no box" "$out" imp "$tmp/bad.yaml"
profile "$tmp/bad.yaml" $'packing:\n  import:\n    files: {1: '"$tmp/run-1.data"$'}\n    shell: read\n'
expect_error "packing.import.files: no file for seed 2" "$out" imp "$tmp/bad.yaml"
profile "$tmp/bad.yaml" "$(import_section "$tmp/run-1.data" "$tmp/run-2.data" $'    shell: read\n')"$'\n  beta: 2.0'
expect_error "packing.beta" "$out" imp "$tmp/bad.yaml"
awk '$3 ~ /^[xyz]lo$/ {$1 = $1 - 0.5; $2 = $2 + 0.5} {print}' "$tmp/run-2.data" > "$tmp/bigger-box.data"
profile "$tmp/bad.yaml" "$(import_section "$tmp/run-1.data" "$tmp/bigger-box.data" "$unit")"
expect_error "the shells read from their boxes differ" "$out" imp "$tmp/bad.yaml"
bad_profile "$tmp/missing.data" "$unit"
expect_error "missing.data: cannot read" "$out" imp "$tmp/bad.yaml"
expect_error "packing: no \`import\` section" "$out" imp "$base"
echo "ok: overlapping grains, a grain beyond the shell, another atom style, a wrong count, a non-cubic box, no box, boxes of two sizes, a missing seed or file, generator keys: refused"

# --- 5. the density column: taken and checked against the profile's material, or ignored ----------------
awk '/Atoms/ {a = 1} a && NF == 10 {$4 = 2500} {print}' "$tmp/run-1.data" > "$tmp/light-1.data"
awk '/Atoms/ {a = 1} a && NF == 10 {$4 = 2500} {print}' "$tmp/run-2.data" > "$tmp/light-2.data"
profile "$tmp/light.yaml" "$(import_section "$tmp/light-1.data" "$tmp/light-2.data" "$unit")" "[0.4]"
"$bin/softpack-import" --config "$tmp/light.yaml" --seed 1 --out "$tmp/light-1.h5" 2> "$tmp/light.log" || fail "import: $(cat "$tmp/light.log")"
grep -q "density 2500 kg/m^3 (the file's)" "$tmp/light.log" || fail "softpack-import does not say the file's density: $(cat "$tmp/light.log")"
expect_error "its grains' density is 2500 kg/m^3 (the density column of $tmp/light-1.data, times packing.import.density_unit), not material.density = 250000" \
  "$tmp/light.h5" "$bin/softpack-normal" --config "$tmp/light.yaml" --scene soft-solid --seed 1 --packing "$tmp/light-1.h5" \
  --checkpoints "$tmp/ck-light" --out "$tmp/light.h5"
profile "$tmp/light.yaml" "$(import_section "$tmp/light-1.data" "$tmp/light-2.data" "$unit"$'    density: ignore\n')" "[0.4]"
"$bin/softpack-import" --config "$tmp/light.yaml" --seed 1 --out "$tmp/light-1.h5" 2> "$tmp/light.log" || fail "import: $(cat "$tmp/light.log")"
grep -q "the file's density ignored" "$tmp/light.log" || fail "softpack-import does not say the density is ignored: $(cat "$tmp/light.log")"
"$bin/softpack-normal" --config "$tmp/light.yaml" --scene soft-solid --seed 1 --packing "$tmp/light-1.h5" --checkpoints "$tmp/ck-light" \
  --out "$tmp/light.h5" --quiet 2> "$tmp/light-normal.log" || fail "density: ignore did not let the sweep take the profile's density: $(tail -3 "$tmp/light-normal.log")"
awk '/Atoms/ {a = 1} a && NF == 10 && $1 == 2 {$4 = 2600} {print}' "$tmp/run-1.data" > "$tmp/mixed.data"
bad_profile "$tmp/mixed.data" "$unit"
expect_error "densities 250000 and 2600: softpack's grains share one material" "$out" imp "$tmp/bad.yaml"
echo "ok: the density column is taken and checked by the sweep (refused when it is not the profile's), ignored on request, one value"
