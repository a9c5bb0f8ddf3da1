#!/usr/bin/env bash
# A study of the coarse-grain settings (issue 30: one study pattern for the profile's stages and the
# coarse-grain stages; workflow/studies.mk, workflow/coarse.mk, report kind `coarse`) on the tiny
# coarse-grain settings (tests/data/coarse-grain-tiny.yaml), in a copy of the source tree:
#   1. a study file in experiments/studies/ is a make goal of its name: every setting's media and
#      runs, the report across them and each setting's own table and figure;
#   2. a stage is shared by its stamp: a setting that changes only how a soft-particle meets a grain
#      has the reference's medium and resolved run as hard links and runs only its soft model; one
#      that changes the compression shares only the medium; one on a subset of the seeds shares it too;
#   3. a second make recomputes nothing, make -n writes nothing;
#   4. a report kind of the other base, a goal a coarse base has not, an archive: refused by key.
#
#   test_coarse_study.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
copy_tree "$work/tree"
cd "$work/tree"
export MAKEFLAGS=
mk() { make --no-print-directory BUILD="$build" DATA=data "$@"; }

cat > experiments/studies/coarse-tiny.yaml <<'YAML'
study: coarse-tiny
report: coarse
base: tests/data/coarse-grain-tiny.yaml
seeds: [901, 902]
figures:
  - {script: figures/coarse_grain.gp, data: reference/curves.dat, name: reference/coarse-grain}
settings:
  contact: {set: {coarse_grain.soft_particle.grain_contact: reduced-radius}}
  slow: {set: {coarse_grain.compression.speed: 0.04, coarse_grain.compression.shear: ~, coarse_grain.compression.record_shear: ~}}
  one-seed: {set: {coarse_grain.soft_particle.beyond_range: stop}, seeds: [902]}
YAML
mk coarse-tiny > "$work/c1.log" 2>&1 || { cat "$work/c1.log"; fail "make coarse-tiny"; }
d=data/studies/coarse-tiny
for s in reference contact slow; do for stage in media resolved soft; do for seed in 901 902; do
  [[ -f $d/$s/$stage/seed-$seed.h5 ]] || { cat "$work/c1.log"; fail "no $d/$s/$stage/seed-$seed.h5"; }; done; done; done
[[ -f $d/one-seed/soft/seed-902.h5 && ! -e $d/one-seed/soft/seed-901.h5 ]] || fail "one-seed did not run its seed alone"
for s in reference contact slow one-seed; do grep -q "^| $s | " $d/report/table.md || fail "no row of $s in the table"; done
[[ -f $d/report/contact/coarse-grain.md && -f $d/report/reference/coarse-grain.pdf ]] || fail "no report or figure of a setting"
grep -q "coarse_grain.compression.shear removed" $d/report/table.md || fail "the table does not say that slow removes the shear"
pass "make coarse-tiny: four settings' media and runs, the table across them, each setting's report and figure"

inode() { stat -c %i "$1"; }
same() { [[ $(inode "$d/$1") == $(inode "$d/$2") ]]; }
same contact/media/seed-901.h5 reference/media/seed-901.h5 || fail "contact did not share the medium"
same contact/resolved/seed-902.h5 reference/resolved/seed-902.h5 || fail "contact did not share the resolved runs (same stamp)"
! same contact/soft/seed-901.h5 reference/soft/seed-901.h5 || fail "contact shared the soft runs, whose stamp differs"
same slow/media/seed-902.h5 reference/media/seed-902.h5 || fail "slow did not share the medium"
! same slow/resolved/seed-901.h5 reference/resolved/seed-901.h5 || fail "slow shared the resolved runs, whose stamp differs"
same one-seed/media/seed-902.h5 reference/media/seed-902.h5 || fail "one-seed (a subset of the seeds) did not share the medium"
grep -q "contact shares reference's resolved" "$work/c1.log" || { cat "$work/c1.log"; fail "the log does not say what was shared"; }
pass "stages shared by their stamps: the medium with every setting, the resolved runs only where the compression is the same"

mk coarse-tiny > "$work/c2.log" 2>&1 || { cat "$work/c2.log"; fail "make coarse-tiny again"; }
! grep -q '^coarse-grain:' $d/*/make.log || { cat $d/*/make.log; fail "a second make coarse-tiny recomputed something"; }
find data > "$work/files.before"
mk -n coarse-tiny > "$work/c3.log" 2>&1 || fail "make -n coarse-tiny"
find data | cmp -s - "$work/files.before" || fail "make -n coarse-tiny wrote a file"
pass "a second make recomputes nothing; make -n writes nothing"

sed -i 's/coarse_grain.compression.speed: 0.04/coarse_grain.compression.speed: 0.03/' experiments/studies/coarse-tiny.yaml
mk coarse-tiny-report > "$work/c4.log" 2>&1 || { cat "$work/c4.log"; fail "make coarse-tiny-report"; }
grep -q 'Stale:\*\* slow holds' $d/report/table.md || { cat $d/report/table.md; fail "the report does not say slow's results are of another configuration"; }
grep -q 'Stale' $d/report/table.md && ! grep -q 'Stale:\*\* .*reference' $d/report/table.md || fail "the report calls more than slow stale"
mk coarse-tiny SETTINGS=slow > "$work/c5.log" 2>&1 || { cat "$work/c5.log"; fail "make coarse-tiny SETTINGS=slow"; }
! grep -q 'Stale' $d/report/table.md || fail "still stale after slow's rerun"
! grep -q '^coarse-grain: .*media' $d/slow/make.log || fail "slow's rerun built its medium again"
pass "an edited setting's results are reported as stale until it reruns (its resolved and soft runs only)"

refused() {  # refused MESSAGE FILE-TEXT
  printf '%s\n' "$2" > "$work/bad.yaml"
  set +e
  "$build/bin/softpack-study" plan --study "$work/bad.yaml" --data data > /dev/null 2> "$work/err"
  local rc=$?
  set -e
  [[ $rc == 2 ]] && grep -qF -- "$1" "$work/err" || fail "expected exit 2 and '$1', got $rc: $(cat "$work/err")"
}
head='study: bad
base: tests/data/coarse-grain-tiny.yaml
seeds: [901]
settings: {a: {set: {coarse_grain.medium.grains: 13}}}'
refused "the report kind 'fits' reports studies of a profile" "$head
report: fits"
refused "allowed: coarse-grain-runs" "$head
report: coarse
stages: [tangential]"
refused "reuses no archive" "$head
report: coarse
archive: data/archive/0.6.0/select"
refused "~ removes a key of the base profile, which has none there" "study: bad
report: coarse
base: tests/data/coarse-grain-tiny.yaml
seeds: [901]
settings: {a: {set: {coarse_grain.medium.colour: ~}}}"
refused "coarse_grain.compression.speed: -1 is not allowed" "$head
report: coarse
common: {coarse_grain.compression.speed: -1}"
pass "refused with their keys: a profile's report kind, a profile's goal, an archive, removing a key the base lacks, a bad value"
