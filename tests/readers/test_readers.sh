#!/usr/bin/env bash
# The readers users open our files with, on the quick profile's results (docs/reading-files.md),
# in a copy of the fixture quick_run's tree (the quick profile's tables made with make -j2):
#   1. every HDF5 file of the quick profile (packings, sweeps, averages, checkpoints) and every
#      fit, then every archive under data/archive, read with h5py alone against the guide's
#      tables (check_hdf5.py): datasets, shapes, types, units, counts across files;
#   2. each packing's .vtp opened by VTK's vtkXMLPolyDataReader and by ParaView (pvpython), its
#      .xyz by ASE: counts, radii, points, bounds and box against the packing file;
#   3. damaged copies are refused by each check: a sphere less, files cut short, a dataset the
#      guide does not list, a mean that is not the seeds' mean;
#   4. examples/figure3.py draws Figure 3 (PNG and PDF) from the quick results and the newest
#      archive.
# A reader that is not installed (python3-paraview, python3-ase, python3-matplotlib) gives a
# skip: line; the test then exits 77 (skipped) once everything else ran, unless a check failed.
#
#   test_readers.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/../workflow/common.sh"
py=/usr/bin/python3  # Debian's: a pyenv or conda python3 does not see python3-h5py and the rest
"$py" -c 'import h5py, numpy' 2> /dev/null || { echo "python3-h5py is not installed: skipped"; exit 77; }
pv=$(command -v pvpython || echo "$py")  # check_vtp_paraview.py exits 77 if neither has paraview
skipped=()

# check NAME COMMAND...: passes (its ok: lines, the last $show of them), is skipped (77) or fails.
check() {
  local out rc=0
  out=$("${@:2}" 2>&1) || rc=$?
  case $rc in
    0) grep "^ok:" <<< "$out" | tail -n "${show:-1000}" || true ;;
    77) echo "skip: $1: $(tail -n 1 <<< "$out")"; skipped+=("$1") ;;
    *) echo "$out"; fail "$1 (exit $rc)" ;;
  esac
}
# refuse NAME PATTERN COMMAND...: the check fails (exit 1) with a FAIL: line matching PATTERN.
refuse() {
  local out rc=0
  out=$("${@:3}" 2>&1) || rc=$?
  [[ $rc == 77 ]] && return 0  # the reader is not installed: said by check
  [[ $rc == 1 ]] && grep -qE "^FAIL: .*$2" <<< "$out" || { echo "$out"; fail "$1: not refused as expected (exit $rc)"; }
  pass "$1 is refused: $(grep -m 1 -E "^FAIL: .*$2" <<< "$out" | cut -c 7-160)"
}

quick_fixture_copy "$work/tree"  # the quick profile's results (the fixture quick_run)
cd "$work/tree"
data=data/quick
readers=tests/readers

# --- 1. HDF5 and JSON with h5py and json alone ------------------------------------------------------
check "h5py: $data" "$py" $readers/check_hdf5.py $data --profile experiments/quick.yaml
for archive in data/archive/*/*/; do
  show=1 check "h5py: $archive" "$py" $readers/check_hdf5.py "$archive"
done
# The guide's own snippets, as printed (they read data/archive/0.5.0/paper).
"$py" - docs/reading-files.md > "$work/snippets.log" 2>&1 << 'EOF' || { cat "$work/snippets.log"; fail "a Python snippet of docs/reading-files.md"; }
import re, sys
snippets = re.findall(r"```python\n(.*?)```", open(sys.argv[1], encoding="utf-8").read(), re.S)
assert len(snippets) >= 5, f"{len(snippets)} Python snippets"
for k, code in enumerate(snippets, 1):
    try:
        exec(compile(code, f"docs/reading-files.md, snippet {k}", "exec"), {})
    except ImportError as e:  # the reader of that snippet is not installed: its check says so
        print(f"not run: snippet {k}: {e}")
print(f"{len(snippets)} snippets")
EOF
pass "the Python snippets of docs/reading-files.md run ($(grep -c '^not run' "$work/snippets.log" || true) not run)"

# --- 2. The exports with VTK, ParaView and ASE --------------------------------------------------------
packings=("$data"/packings/seed-*.h5)
[[ -e ${packings[0]} ]] || fail "no packing in $data/packings"
for h5 in "${packings[@]}"; do
  check "VTK: ${h5%.h5}.vtp" "$py" $readers/check_vtp_vtk.py "${h5%.h5}.vtp" "$h5"
  check "ParaView: ${h5%.h5}.vtp" "$pv" $readers/check_vtp_paraview.py "${h5%.h5}.vtp" "$h5"
  check "ASE: ${h5%.h5}.xyz" "$py" $readers/check_xyz_ase.py "${h5%.h5}.xyz" "$h5"
done

# --- 3. Damaged copies are refused ----------------------------------------------------------------------
bad=$work/damaged/quick
mkdir -p "$bad" && cp -r "$data"/. "$bad"
"$py" - "$bad" << 'EOF'
import sys, h5py
bad = sys.argv[1]
with h5py.File(f"{bad}/packings/seed-1.h5", "a") as f:  # the last sphere removed
    for name in ("centres", "radii", "radii_inserted"):
        kept, unit = f[name][:-1], f[name].attrs.get("unit")
        del f[name]
        f[name] = kept
        if unit is not None:
            f[name].attrs["unit"] = unit
with h5py.File(f"{bad}/normal/soft-soft-seed-1.h5", "a") as f:  # a dataset the guide does not list
    f["Fn_corrected"] = f["Fn"][:]
with h5py.File(f"{bad}/averages/soft-solid.h5", "a") as f:  # a mean that is not the seeds' mean
    f["normal/Fn_mean"][-1] *= 1 + 1e-9
EOF
truncate -s 2000 "$bad/averages/soft-soft.h5" "$bad/packings/seed-2.vtp"
head -n -1 "$data/packings/seed-2.xyz" > "$bad/packings/seed-2.xyz"
refuse "h5py: a packing with a sphere less" "packings/seed-1.h5: stats/inserted differs" "$py" $readers/check_hdf5.py "$bad" --profile experiments/quick.yaml
refuse "h5py: an average cut short" "averages/soft-soft.h5: h5py cannot open" "$py" $readers/check_hdf5.py "$bad"
refuse "h5py: a dataset the guide does not list" "/Fn_corrected is not in docs" "$py" $readers/check_hdf5.py "$bad"
refuse "h5py: a mean changed by 1e-9" "/normal/Fn_mean: value" "$py" $readers/check_hdf5.py "$bad"
refuse "VTK: a sphere less in the packing" "reads [0-9]+ points" "$py" $readers/check_vtp_vtk.py "$data/packings/seed-1.vtp" "$bad/packings/seed-1.h5"
refuse "VTK: a .vtp cut short" "error" "$py" $readers/check_vtp_vtk.py "$bad/packings/seed-2.vtp" "$data/packings/seed-2.h5"
refuse "ParaView: a .vtp cut short" "reads 0 points" "$pv" $readers/check_vtp_paraview.py "$bad/packings/seed-2.vtp" "$data/packings/seed-2.h5"
refuse "ASE: a sphere less in the packing" "atoms" "$py" $readers/check_xyz_ase.py "$data/packings/seed-1.xyz" "$bad/packings/seed-1.h5"
refuse "ASE: a .xyz without its last line" "cannot read" "$py" $readers/check_xyz_ase.py "$bad/packings/seed-2.xyz" "$data/packings/seed-2.h5"

# --- 4. The Python example: Figure 3 from the averages and the fits -----------------------------------
if "$py" -c 'import matplotlib' 2> /dev/null; then
  latest=$(ls -d data/archive/*/paper | sort -V | tail -n 1)
  for case in "$data:$work/figure3-quick.png" "$data:$work/figure3-quick.pdf" "$latest:$work/figure3-archive.png"; do
    "$py" examples/figure3.py "${case%%:*}" "${case#*:}" > "$work/figure3.log" 2>&1 ||
      { cat "$work/figure3.log"; fail "examples/figure3.py ${case%%:*}"; }
  done
  head -c 4 "$work/figure3-quick.pdf" | grep -q '%PDF' || fail "examples/figure3.py: the .pdf is not a PDF"
  "$py" - "$work"/figure3-quick.png "$work"/figure3-archive.png << 'EOF' || fail "examples/figure3.py: an empty or blank PNG"
import sys, numpy as np, matplotlib.image
for path in sys.argv[1:]:
    image = matplotlib.image.imread(path)  # fails on a file that is not a PNG
    colours = np.unique(image.reshape(-1, image.shape[-1]), axis=0)
    assert image.shape[0] >= 500 and image.shape[1] >= 500 and len(colours) > 20, (path, image.shape, len(colours))
EOF
  pass "examples/figure3.py draws Figure 3 from $data and $latest (PNG, PDF)"
else
  echo "skip: examples/figure3.py: python3-matplotlib is not installed"
  skipped+=("figure3")
fi

if [[ ${#skipped[@]} -gt 0 ]]; then
  echo "skipped (a reader is not installed): ${skipped[*]}"
  exit 77
fi
pass "every reader opens every file kind, with the counts of the packing files"
