#!/usr/bin/env bash
# The walkthrough of docs/import.md as a user meets it (issue 31), with no knowledge of the
# project's internals: LAMMPS itself (Debian's lmp) writes a packing in a shell of 16 mm at the
# origin with write_data (its box is +-1.1 Rs, its density column the user's material); ASE writes
# a second one as extended XYZ; a profile of the user's own, outside the repository beside its
# packings, imports them; `shell: read` is refused for the box's gap and the shell is given; make
# runs the normal sweeps, the tables and the figures from the repository by the profile's path.
#
#   test_walkthrough.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/../cli/common.sh"
bin=$1
root=$2
py=/usr/bin/python3
command -v lmp > /dev/null || { echo "skipped: no lmp (Debian's lammps: make setup)"; exit 77; }
$py -c "import ase, h5py" 2> /dev/null || { echo "skipped: python3-ase or python3-h5py is not installed (make setup)"; exit 77; }
own=$tmp/own
mkdir -p "$own/packings"

# 1. LAMMPS: the spheres of a dense packing (the quick profile's generator; a user's would come from
#    a compaction) created one by one with create_atoms, their diameters and the material's
#    density set, written by write_data in a box of +-1.1 Rs.
for s in 1 2; do
  "$bin/softpack-pack" --config "$root/experiments/quick.yaml" --seed $s --out "$tmp/gen-$s.h5" --quiet
  $py - "$tmp/gen-$s.h5" "$own/packings/in-$s.lmp" run-$s.data <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1], "r")
with open(sys.argv[2], "w") as o:
    o.write("units si\natom_style sphere\nboundary f f f\n")
    o.write("region box block -0.0176 0.0176 -0.0176 0.0176 -0.0176 0.0176\ncreate_box 1 box\n")
    for i, (x, r) in enumerate(zip(f["centres"][()], f["radii"][()])):
        o.write(f"create_atoms 1 single {x[0]!r} {x[1]!r} {x[2]!r} units box\nset atom {i + 1} diameter {2 * r!r}\n")
    o.write(f"set type 1 density 250000\nwrite_data {sys.argv[3]}\n")
PY
  (cd "$own/packings" && lmp -in in-$s.lmp -log none -screen none) || fail "lmp did not write the packing of seed $s"
done
# 2. ASE: the second packing as extended XYZ (positions and radii), as a user would convert it.
$py - "$own/packings" <<'PY'
import sys, numpy as np, ase, ase.io
d = sys.argv[1]
rows = []
with open(f"{d}/run-2.data") as f:
    lines = f.read().split("\n")
start = lines.index("Atoms # sphere") + 2
for line in lines[start:]:
    w = line.split()
    if not w:
        break
    rows.append([float(v) for v in w[2:7]])  # diameter density x y z
a = np.array(rows)
atoms = ase.Atoms("H" * len(a), positions=a[:, 2:5])
atoms.set_array("radii", a[:, 0] / 2)
ase.io.write(f"{d}/run-2.xyz", atoms, format="extxyz")
PY
grep -q "radii" "$own/packings/run-2.xyz" || fail "ASE did not write the radii"

# 3. The user's profile: the quick profile's settings, the packings imported, the soft-solid normal
#    law only (as in the issue's trial).
awk '
  /^profile:/ {print "profile: own"; next}
  /^packing:/ {print "packing:\n  import:\n    files: {1: packings/run-1.data, 2: packings/run-2.data}\n    shell: read"; skip = 1; next}
  /^tangential:/ {skip = 1; next}
  skip && /^  / {next}
  {skip = 0}
  /^  delta_n:/ {print "  delta_n: [0.0, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5]"; next}
  /^  scenes:/ {print "  scenes: [soft-solid]"; next}
  {print}' "$root/experiments/quick.yaml" > "$own/own.yaml"
mk() { (cd "$root" && make --no-print-directory PROFILE="$own/own.yaml" DATA="$tmp/data" FIGURES_OUT="$tmp/figures" \
          BUILD="$(dirname "$bin")" TOOLS= "$@"); }
# A profile whose profile: key names another than its file is refused before anything runs (its
# results would be filed under the file's name; the fit refused it, after the sweeps); a profile
# that does not exist is refused with the list of the profiles, not every YAML of experiments/.
cp "$own/own.yaml" "$own/mine.yaml"
(cd "$root" && make --no-print-directory PROFILE="$own/mine.yaml" DATA="$tmp/data-mine" BUILD="$(dirname "$bin")" TOOLS= \
  packings) > "$tmp/name.log" 2>&1 && fail "a profile named 'own' in mine.yaml was run"
grep -q "names itself 'own' (its profile: key), but make names it 'mine'" "$tmp/name.log" || { cat "$tmp/name.log"; fail "the name was not said"; }
[[ -z $(ls "$tmp/data-mine") ]] || fail "the refused profile wrote into $tmp/data-mine: $(ls "$tmp/data-mine")"
rm "$own/mine.yaml"
(cd "$root" && make --no-print-directory PROFILE=nonesuch BUILD="$(dirname "$bin")" TOOLS= packings) > "$tmp/none.log" 2>&1 &&
  fail "make PROFILE=nonesuch ran"
grep -q "the profiles here: .*quick" "$tmp/none.log" && ! grep -qE "criteria|published|coarse-grain" "$tmp/none.log" ||
  { cat "$tmp/none.log"; fail "PROFILE=nonesuch: not the list of profiles"; }
echo "ok: a profile named unlike its file is refused before it runs; a missing one lists the profiles"
mk packings > "$tmp/read.log" 2>&1 && fail "shell: read took LAMMPS's box (+-1.1 Rs) for the shell"
grep -qE "a gap of [0-9.]+ % of the shell's radius 0.0176" "$tmp/read.log" || { cat "$tmp/read.log"; fail "the gap was not said"; }
sed -i 's/^    shell: read$/    shell: {radius: 0.016, centre: [0, 0, 0]}/; s|2: packings/run-2.data|2: packings/run-2.xyz|' "$own/own.yaml"
mk packings > "$tmp/xyz.log" 2>&1 && fail "ASE's rounded positions of grains touching the shell passed the default tolerance"
grep -q "beyond the shell .* allowed: packing.import.overlap_tolerance = 1e-06" "$tmp/xyz.log" || { cat "$tmp/xyz.log"; fail "the rounding was not said"; }
sed -i 's/^    shell: {radius/    overlap_tolerance: 1.0e-4\n    shell: {radius/' "$own/own.yaml"
mk -j2 tables figures > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; fail "make tables figures with the user's profile"; }
grep -q "density 250000 kg/m^3 (the file's)" "$tmp/data/own/packings/seed-1.log" || fail "the LAMMPS density was not taken"
grep -q "no density in the file" "$tmp/data/own/packings/seed-2.log" || fail "the XYZ file's lack of density was not said"
grep -q "grains pressing into the shell moved in by up to" "$tmp/data/own/packings/seed-2.log" || fail "the grains moved in were not said"
grep -q "^| a \[N\] | [0-9]" "$tmp/data/own/tables/table1.md" || fail "Table 1 has no fitted a"
[[ -s $tmp/figures/fig3_normal.png ]] || fail "no Figure 3"
echo "ok: LAMMPS write_data and ASE extxyz imported by a profile outside the repository; the box refused as the shell with its gap, the shell given; sweeps, Table 1, Figure 3 through make"
