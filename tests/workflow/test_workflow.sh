#!/usr/bin/env bash
# The workflow end to end on the quick profile, in a copy of the fixture quick_run's tree (the
# quick profile's tables and figures made with make -j2; the build is reused):
#   1. make -j1 from scratch gives the same results as the fixture's make -j2 (every HDF5
#      dataset exact, the text outputs; the same files); the tables and Figures 1-6 exist and are
#      not empty; afterwards make -q says everything is up to date;
#   2. an interrupted make, rerun, finishes with the same results and no leftovers;
#   3. editing a comment or the description reruns nothing; editing a key only the tangential
#      stage reads reruns tangential -> average -> fit -> tables/figures and nothing before, and
#      make -n says so without writing anything;
#      editing a normal key reruns normal and tangential but not the packings;
#   4. make archive, then a fresh copy without the data: make tables figures reuses every result.
#
#   test_workflow.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
quick_fixture_copy "$work/tree"
cd "$work/tree"
export MAKEFLAGS=
mk() { make --no-print-directory PROFILE=quick BUILD="$build" "$@"; }

# --- 1. -j1 and -j2 agree ------------------------------------------------------------------------
mk -j1 DATA=data-j1 FROM_SCRATCH=1 tables figures > "$work/j1.log" 2>&1 || { cat "$work/j1.log"; fail "make -j1 tables figures"; }
numbers() {  # the numeric results of a data tree, without provenance (comments, code versions)
  for f in "$1"/quick/averages/*.dat "$1"/quick/fits/*.gp "$1"/quick/tables/*.md; do
    echo "== ${f#"$1"/}"; grep -v -e '^#' -e '^<!--' "$f"
  done
}
[[ -n $(numbers data-j1) ]] || fail "no results in data-j1"
files() { (cd "$1/quick" && find . -path ./checkpoints -prune -o -type f -print | sort); }
diff <(files data-j1) <(files data) > /dev/null || { diff <(files data-j1) <(files data) | head; fail "-j1 and -j2 wrote different files"; }
compared=$(same_results data-j1 data) || { echo "$compared"; fail "-j1 and -j2 differ"; }
pass "make -j1 and make -j2 (the fixture's run) give the same results: ${compared}, every HDF5 dataset exact"
for f in data-j1/quick/tables/table{1,2}.{md,tex} \
         data-j1/quick/figures/fig{1_apollonian,2_softparticle,3_normal,4_tangential_soft_solid,5_tangential_soft_soft,6_kt}.{pdf,png}; do
  [[ -s $f ]] || fail "$f is missing or empty"
done
grep -q 'soft-solid ours' data-j1/quick/tables/table1.md || fail "table1.md has no soft-solid column"
pass "Tables 1-2 and Figures 1-6 exist and are not empty"
# `tables` prints the tables (a recipe, so never "up to date" for make -q): ask about its files.
uptodate() { mk -q DATA=data-j1 figures "$@" data-j1/quick/tables/table1.md; }
uptodate || fail "make -q after a complete run: not up to date"
pass "make -q: up to date after a run"

# --- 2. an interrupted make finishes on a rerun -----------------------------------------------------
# Whatever the moment of the interruption, the rerun must complete and give the same numbers.
setsid make --no-print-directory PROFILE=quick BUILD="$build" DATA=data-int FROM_SCRATCH=1 -j2 tables > "$work/int.log" 2>&1 &
pid=$!
for _ in $(seq 1 100); do compgen -G 'data-int/quick/packings/*.h5' > /dev/null && break; sleep 0.02; done
kill -INT -- -"$pid" 2> /dev/null || true
wait "$pid" 2> /dev/null || true
mk DATA=data-int tables > "$work/int2.log" 2>&1 || { cat "$work/int2.log"; fail "rerun after an interruption"; }
diff <(numbers data-j1) <(numbers data-int) > /dev/null ||
  fail "the rerun after an interruption differs from an uninterrupted run"
leftovers=$(find data-int -name '*.tmp*' | head -3)
[[ -z $leftovers ]] || fail "temporary files left after the rerun: $leftovers"
pass "an interrupted make, rerun, finishes with the same results"

# --- 3. rerun only what a change touches ------------------------------------------------------------
profile=experiments/quick.yaml
cp "$profile" "$work/quick.yaml.orig"
sed -i '1i # a comment added by the test' "$profile"
sed -i 's/^description: .*/description: "edited by the test"/' "$profile"
uptodate || { mk -n DATA=data-j1 tables figures | head -5; fail "a comment and the description reran something"; }
pass "editing a comment or the description reruns nothing"

sed -i 's/^  rate: .*/  rate: 0.12/' "$profile"
grep -q '^  rate: 0.12' "$profile" || fail "could not edit tangential.rate"
mk -q DATA=data-j1 packings || fail "tangential.rate: the packings would rerun"
mk -q DATA=data-j1 normal || fail "tangential.rate: the normal sweeps would rerun"
mk -q DATA=data-j1 tangential && fail "tangential.rate: the tangential sweeps would not rerun"
uptodate && fail "tangential.rate: the tables would not be remade"
# make -n says exactly what would run and writes nothing: a dry run, then undoing the edit,
# reruns nothing.
stamps_before=$(stat -c '%n %Y %s' data-j1/quick/stamps/*.hash)
mk -n DATA=data-j1 tables figures > "$work/dry.log" 2>&1 || { cat "$work/dry.log"; fail "make -n"; }
grep -q 'softpack-tangential ' "$work/dry.log" || fail "make -n: no tangential sweep listed"
grep -qE 'softpack-(pack|normal) ' "$work/dry.log" && fail "make -n lists packings or normal sweeps after editing tangential.rate"
[[ $stamps_before == $(stat -c '%n %Y %s' data-j1/quick/stamps/*.hash) ]] || fail "make -n rewrote a stamp"
cp "$work/quick.yaml.orig" "$profile"
uptodate || fail "a dry run followed by undoing the edit: something would rerun"
sed -i 's/^  rate: .*/  rate: 0.12/' "$profile"
pass "make -n lists the tangential chain only and writes nothing"
before=$(stat -c %Y data-j1/quick/normal/*.h5 data-j1/quick/packings/*.h5 | md5sum)
mk DATA=data-j1 tables figures > "$work/change.log" 2>&1 || { cat "$work/change.log"; fail "make after editing tangential.rate"; }
grep -q '^tangential: ' "$work/change.log" || fail "tangential.rate: no tangential sweep ran"
grep -q '^fit: ' "$work/change.log" || fail "tangential.rate: no fit ran"
grep -E '^(pack|normal): ' "$work/change.log" && fail "tangential.rate: a packing or normal sweep ran"
[[ $before == $(stat -c %Y data-j1/quick/normal/*.h5 data-j1/quick/packings/*.h5 | md5sum) ]] ||
  fail "tangential.rate: packings or normal results were rewritten"
pass "editing tangential.rate reruns tangential -> average -> fit -> tables/figures only"

sed -i 's/^  speed: .*/  speed: 0.025/' "$profile"
mk -q DATA=data-j1 packings || fail "normal.speed: the packings would rerun"
mk -q DATA=data-j1 normal && fail "normal.speed: the normal sweeps would not rerun"
mk -q DATA=data-j1 tangential && fail "normal.speed: the tangential sweeps would not rerun"
pass "editing normal.speed reruns the normal and tangential sweeps, not the packings"
cp "$work/quick.yaml.orig" "$profile"

# --- 4. archive, then a fresh copy reuses everything ------------------------------------------------
mk DATA=data-j1 tables > /dev/null 2>&1 || fail "make tables with the original profile"
mk DATA=data-j1 archive > "$work/archive.log" 2>&1 || { cat "$work/archive.log"; fail "make archive"; }
archive=data/archive/$(awk '/^project/ { print $3; exit }' CMakeLists.txt)/quick
for f in MANIFEST.sha256 PROVENANCE.json dataset.bib profile.yaml stamps/tangential.hash fits/soft-solid.json; do
  [[ -s $archive/$f ]] || fail "archive: $archive/$f is missing"
done
(cd "$archive" && sha256sum --quiet -c MANIFEST.sha256) || fail "archive: MANIFEST.sha256 does not match"
touch data-j1/quick/fits/*.json  # newer, same content: the archive is kept as it is
mk DATA=data-j1 archive > "$work/archive2.log" 2>&1 || { cat "$work/archive2.log"; fail "make archive (again)"; }
grep -q 'already holds these results' "$work/archive2.log" || fail "make archive rewrote an archive of the same results"
sed -i '1s/^/# a comment added since the archive\n/' "$profile"  # the same configuration: the archive is kept
mk DATA=data-j1 archive > "$work/archive3.log" 2>&1 || { cat "$work/archive3.log"; fail "make archive (a comment added)"; }
grep -q 'already holds these results' "$work/archive3.log" || fail "make archive rewrote the archive for a comment of the profile"
cp "$work/quick.yaml.orig" "$profile"
pass "make archive: results, stamps, MANIFEST (verified), provenance, BibTeX; kept when unchanged, a comment aside"

copy_tree "$work/fresh"
mkdir -p "$work/fresh/data" && cp -r data/archive "$work/fresh/data/"
cd "$work/fresh"
mk tables figures > "$work/fresh.log" 2>&1 || { cat "$work/fresh.log"; fail "make tables figures in a fresh copy"; }
grep -E '^(pack|normal|tangential|average|fit): ' "$work/fresh.log" && fail "a fresh copy recomputed results the archive holds"
grep -q '^reused ' "$work/fresh.log" || fail "a fresh copy reused nothing from the archive"
diff <(cd "$work/tree" && numbers data-j1) <(numbers data) > /dev/null || fail "the reused results differ from the archived run"
pass "a fresh copy's make tables figures recomputes nothing ($(grep -c '^reused ' "$work/fresh.log") results reused)"

# In that fresh copy the normal results came from the archive, which keeps no checkpoints: a
# tangential key edited, the tangential stage computes the normal states it shears itself.
sed -i 's/^  rate: .*/  rate: 0.12/' experiments/quick.yaml
mk tables > "$work/fresh-rate.log" 2>&1 || { cat "$work/fresh-rate.log"; fail "make tables after editing tangential.rate in the fresh copy"; }
grep -q '^tangential: ' "$work/fresh-rate.log" || fail "fresh copy, tangential.rate: no tangential sweep ran"
grep -E '^(pack|normal): ' "$work/fresh-rate.log" && fail "fresh copy, tangential.rate: a packing or normal sweep ran"
compgen -G 'data/quick/checkpoints/normal/soft-solid/seed-1/point-*.h5' > /dev/null ||
  fail "fresh copy: the tangential stage did not compute the normal states"
pass "with the normal results from the archive, the tangential stage computes the normal states it needs"
