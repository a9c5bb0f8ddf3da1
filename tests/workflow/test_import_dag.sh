#!/usr/bin/env bash
# The DAG of a normal-only profile on imported packings (docs/import.md): make tables figures on
# a profile whose packings come from LAMMPS data files (softpack-import) and whose grid does not
# start at 0: both scenes swept, averaged and fitted (Table 1, Figure 3); h5py reads it all as
# docs/reading-files.md says; make tangential refused with a message. (The import itself, its
# formats and bad input: cli.softpack_import.)
#
#   test_import_dag.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/../cli/common.sh"
bin=$1
root=$2
py=/usr/bin/python3
$py -c "import h5py" 2> /dev/null || { echo "skipped: python3-h5py is not installed (make setup)"; exit 77; }
source "$(dirname "$0")/../cli/import_inputs.sh"
import_inputs
profile "$tmp/lammps.yaml" "$(import_section "$tmp/run-1.data" "$tmp/run-2.data" $'    length_unit: 1.0e-3\n    shell: read\n')"

mk() { (cd "$root" && make --no-print-directory PROFILE=imported PROFILE_FILE="$tmp/lammps.yaml" DATA="$tmp/data" \
          FIGURES_OUT="$tmp/figures" BUILD="$(dirname "$bin")" TOOLS= "$@"); }
mk -j2 tables figures > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; fail "make tables figures (normal-only, imported)"; }
for s in 1 2; do
  h5dump -d /provenance/program "$tmp/data/imported/packings/seed-$s.h5" | grep -q softpack-import || fail "seed $s was not imported"
  for scene in soft-solid soft-soft; do
    h5dump -d /delta_n "$tmp/data/imported/normal/$scene-seed-$s.h5" | grep -q "0.1, 0.2, 0.3, 0.35" || fail "$scene seed $s: not the profile's grid"
  done
done
grep -q "^| a \[N\] | [0-9]" "$tmp/data/imported/tables/table1.md" || fail "Table 1 has no fitted a: $(cat "$tmp/data/imported/tables/table1.md")"
[[ -s $tmp/figures/fig3_normal.png && ! -e $tmp/figures/fig4_tangential_soft_solid.png ]] || fail "Figure 3 (and only the normal figures) expected"
[[ ! -e $tmp/data/imported/tangential && ! -e $tmp/data/imported/averages/kt-soft-solid.dat ]] || fail "tangential outputs on a normal-only profile"
$py "$root/tests/readers/check_hdf5.py" "$tmp/data/imported" --normal-only > "$tmp/check.log" ||
  { cat "$tmp/check.log"; fail "the imported packings, sweeps and averages do not read as docs/reading-files.md says"; }
mk tangential > "$tmp/make2.log" 2>&1 && fail "make tangential on a normal-only profile did not stop"
grep -q "normal-only profile" "$tmp/make2.log" || fail "make tangential on a normal-only profile: $(cat "$tmp/make2.log")"
echo "ok: make tables figures on a normal-only profile of imported packings (grid from 0.1): both scenes swept, averaged, fitted; Table 1 and Figure 3; h5py reads it all as the guide says; make tangential says why not"

# A profile of one scene (normal.scenes: [soft-solid]) draws its figure: make figures loaded the
# fits of both scenes and Figure 3 read both averages (issue 31).
sed 's/^  scenes: \[soft-solid, soft-soft\]/  scenes: [soft-solid]/' "$tmp/lammps.yaml" > "$tmp/one-scene.yaml"
grep -q "scenes: \[soft-solid\]$" "$tmp/one-scene.yaml" || fail "the one-scene profile was not written"
(cd "$root" && make --no-print-directory PROFILE=imported PROFILE_FILE="$tmp/one-scene.yaml" DATA="$tmp/data-one" \
   FIGURES_OUT="$tmp/figures-one" BUILD="$(dirname "$bin")" TOOLS= -j2 tables figures) > "$tmp/one.log" 2>&1 ||
  { cat "$tmp/one.log"; fail "make tables figures on a profile of the soft-solid scene alone"; }
[[ -s $tmp/figures-one/fig3_normal.png && -s $tmp/figures-one/fig3_normal.pdf ]] || fail "no Figure 3 of the one-scene profile"
[[ ! -e $tmp/data-one/imported/normal/soft-soft-seed-1.h5 ]] || fail "the one-scene profile swept soft-soft"
$py "$root/examples/figure3.py" "$tmp/data-one/imported" "$tmp/figure3-one.png" > "$tmp/fig3py.log" 2>&1 && [[ -s $tmp/figure3-one.png ]] ||
  { cat "$tmp/fig3py.log"; fail "examples/figure3.py refused the one-scene folder"; }
echo "ok: a profile of one scene: its sweeps, Table 1 and Figure 3 (make tables figures, examples/figure3.py)"

# Your own profile, kept elsewhere with its packings: make PROFILE=path/to/own.yaml, the import
# paths relative to the profile's folder (issue 31: they were relative to the repository).
mkdir -p "$tmp/own/packings" && cp "$tmp/run-1.data" "$tmp/run-2.data" "$tmp/own/packings/"
profile "$tmp/own/own.yaml" "$(import_section packings/run-1.data packings/run-2.data $'    length_unit: 1.0e-3\n    shell: read\n')"
sed -i 's/^profile: imported$/profile: own/' "$tmp/own/own.yaml"  # a profile is named after its file
(cd "$root" && make --no-print-directory PROFILE="$tmp/own/own.yaml" DATA="$tmp/data-own" BUILD="$(dirname "$bin")" TOOLS= -j2 tables) \
  > "$tmp/own.log" 2>&1 || { cat "$tmp/own.log"; fail "make PROFILE=$tmp/own/own.yaml tables"; }
[[ -s $tmp/data-own/own/tables/table1.md && -s $tmp/data-own/own/packings/seed-2.h5 ]] || fail "no results of the own profile in DATA/own/"
h5dump -d /imported/source_file "$tmp/data-own/own/packings/seed-1.h5" | grep -q "$tmp/own/packings/run-1.data" ||
  fail "the packing was not read from the profile's folder"
echo "ok: make PROFILE=path/to/own.yaml: results in DATA/own/, import paths relative to the profile's folder"
