#!/usr/bin/env bash
# The studies' machinery (workflow/studies.mk, softpack-study) on a tiny accuracy study of the
# quick profile, in a copy of the source tree (the build is reused):
#   1. a bad study file is refused with its key and exit code 2: a seed of the paper's seven,
#      an unknown key, a setting `of` one that does not run, a key of a section the base lacks;
#   2. a study file in experiments/studies/ is a make goal of its name, with no make edit: it runs
#      the reference and every setting, writes the table, the Pareto data and the figure; the
#      reference compared with itself has zero error, every setting a row;
#   3. a second make recomputes nothing; changing one setting reruns that one only; a stage whose
#      seeds and stamp are an earlier setting's is shared, not recomputed;
#   4. softpack-study check compares two of its profiles on their seeds (the fast profile's
#      confirmation): every quantity with both standard errors, the costs; different seeds, or
#      different packings of a seed, refused;
#   5. the calibration report (another kind) of the same runs: make study-report STUDY=FILE;
#   6. a study of fit options: its setting shares the reference's sweeps by their stamps and runs
#      only averages and fits; its report (kind fits) has each coefficient's jackknife error.
#
#   test_accuracy.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
copy_tree "$work/tree"
cd "$work/tree"
export MAKEFLAGS=
acc="$build/bin/softpack-study"

study() {  # study FILE [EXTRA-SETTING-LINES]: a study of the quick profile on seeds 101-102
  cat > "$1" <<YAML
study: $(basename "$1" .yaml)
report: accuracy
out: accuracy
figures:
  - {script: figures/accuracy_cost.gp, data: pareto.dat, name: accuracy-cost}
base: experiments/quick.yaml
seeds: [101, 102]
compare: {Fn_delta_n: [0.5, 0.7], kt_delta_n: [0.6, 0.7]}
reference:
  seeds: [101, 102, 103]
  set:
    relaxation: {protocol: converged, force_tolerance: 1.0e-3, energy_tolerance: 1.0e-7, check_interval: 0.05,
                 max_time: 5.0, zero_velocities_at_checks: true}
settings:
  base: {}
  stops-1: {set: {relaxation.stops: 1}}
  base-1-seed: {of: base, seeds: [101]}
${2:-}
YAML
}

# --- 1. bad study files ------------------------------------------------------------------------
refused() {  # refused MESSAGE: the study file $work/bad.yaml is refused with MESSAGE, exit 2
  set +e
  "$acc" profiles --study "$work/bad.yaml" --out-dir "$work/p" > /dev/null 2> "$work/err"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "exit code $code (expected 2) for a study with $1: $(cat "$work/err")"
  grep -qF -- "$1" "$work/err" || fail "expected '$1', got: $(cat "$work/err")"
}
study "$work/bad.yaml"; sed -i 's/^seeds: \[101, 102\]/seeds: [1, 102]/' "$work/bad.yaml"
refused "seed 1 is not allowed; allowed: held-out seeds >= 101"
study "$work/bad.yaml" "  typo: {sett: {relaxation.stops: 1}}"
refused "settings.typo.sett: unknown key"
study "$work/bad.yaml" "  sub: {of: base-1-seed, seeds: [101]}"
refused "'base-1-seed' is not a setting that runs"
study "$work/bad.yaml" "  bad: {set: {relaxaton.stops: 1}}"
refused "'relaxaton.stops': the base profile has no section 'relaxaton' to change"
study "$work/bad.yaml" "  bad: {set: {relaxation.stops: -1}}"
refused "setting bad"
pass "bad study files are refused with the key"

# --- 2. the study runs -------------------------------------------------------------------------
study experiments/studies/tiny.yaml  # a new study: one file, no make edit, `make tiny`
mk() { make --no-print-directory BUILD="$build" DATA=data "$@"; }
mk -j2 tiny > "$work/a1.log" 2>&1 || { cat "$work/a1.log"; fail "make tiny"; }
report=data/accuracy/report
for f in table.md pareto.dat report.json accuracy-cost.pdf accuracy-cost.png; do
  [[ -s $report/$f ]] || fail "$report/$f is missing or empty"
done
[ "$(grep -vc '^#' $report/pareto.dat)" -eq 3 ] || fail "pareto.dat: $(cat $report/pareto.dat)"
grep -q '^| base | (the base, experiments/quick.yaml) | 2 |' $report/table.md || fail "no row for base: $(cat $report/table.md)"
grep -q '^| base-1-seed | base on 1 of its seeds | 1 |' $report/table.md || fail "no row for base-1-seed"
/usr/bin/python3 - "$report/report.json" <<'PY' || fail "report.json"
import json, sys
r = json.load(open(sys.argv[1]))
assert len(r["quantities"]) == 2 * (4 + 3 + 2 + 2), r["quantities"]
assert all(s > 0 for s in r["reference"]["sigma"] if s is not None), r["reference"]["sigma"]
cpu = {s["name"]: s["cpu_seconds"] for s in r["settings"]}
assert 0 < cpu["base-1-seed"] < cpu["base"], cpu  # one seed of the two costs less
assert r["reference"]["cpu_seconds"] > 0
PY
pass "make tiny (experiments/studies/tiny.yaml): the reference, 2 settings run and 1 subset compared; table, data, figure"
# stops-1 and base have the reference's packing section and seeds among its (101-102 of 101-103;
# the relaxation differs): the reference's packings are theirs, the first earlier setting that fits.
for s in base stops-1; do
  grep -q "^study: $s shares reference's packings" "$work/a1.log" || { cat "$work/a1.log"; fail "$s did not share the reference's packings"; }
  grep -q "^pack: $s " "$work/a1.log" && fail "$s's packings were generated again"
  [ data/accuracy/$s/packings/seed-101.h5 -ef data/accuracy/reference/packings/seed-101.h5 ] || fail "$s's packing is not the reference's file"
  [ data/accuracy/$s/packings/seed-101.log -ef data/accuracy/reference/packings/seed-101.log ] && fail "$s's packing log is the reference's (a rerun would truncate both)"
  cmp -s data/accuracy/$s/packings/seed-101.log data/accuracy/reference/packings/seed-101.log || fail "$s's packing log differs from the reference's"
done
grep -qE "^study: (stops-1|base) shares [a-z0-9-]+'s (normal|tangential)" "$work/a1.log" && fail "a setting shared a sweep of another relaxation"
pass "a setting whose seeds are among an earlier one's, with its packing stamp, shares its packings (hard links), not its sweeps"

# --- 3. nothing twice; a changed setting reruns alone --------------------------------------------
mk -j2 tiny > "$work/a2.log" 2>&1 || { cat "$work/a2.log"; fail "make tiny again"; }
! grep -qE '^(packing|normal|tangential):' "$work/a2.log" || { cat "$work/a2.log"; fail "a second make tiny recomputed something"; }
sed -i 's/stops-1: {set: {relaxation.stops: 1}}/stops-1: {set: {relaxation.stops: 2}}/' experiments/studies/tiny.yaml
mk -j2 tiny > "$work/a3.log" 2>&1 || { cat "$work/a3.log"; fail "make tiny after a change"; }
grep -qE '^normal: stops-1 ' "$work/a3.log" || { cat "$work/a3.log"; fail "the changed setting was not rerun"; }
! grep -qE '^(normal|tangential|packing): (reference|base) ' "$work/a3.log" || { cat "$work/a3.log"; fail "an unchanged setting was rerun"; }
pass "a second make tiny recomputes nothing; a changed setting reruns alone"

# --- 4. one profile against another (softpack-study check, make fast-check's comparison) -----
"$acc" check --data data/accuracy --reference data/accuracy/profiles/base.yaml --candidate data/accuracy/profiles/stops-1.yaml \
  --Fn-at 0.5 0.7 --kt-at 0.6 0.7 --out-dir "$work/check" > "$work/check.log" 2>&1 || { cat "$work/check.log"; fail "softpack-study check"; }
grep -q '^# The stops-1 profile against the base profile on seeds 101, 102' "$work/check/table.md" || fail "check table: $(head -3 "$work/check/table.md")"
/usr/bin/python3 - "$work/check/check.json" <<'PY' || fail "check.json"
import json, sys
c = json.load(open(sys.argv[1]))
assert len(c["rows"]) == 2 * (4 + 3 + 2 + 2), len(c["rows"])
assert c["reference_cpu"] > 0 and c["candidate_cpu"] > 0 and c["cpu_ratio"] > 0, c
assert c["agreeing"] <= c["compared"] <= len(c["rows"]), c
for r in c["rows"]:
    if r["established"]:
        assert r["reference_sigma"] > 0 and r["candidate_sigma"] > 0, r
        assert r["agrees"] == (abs(r["z"]) <= 1.0), r
PY
set +e
"$acc" check --data data/accuracy --reference data/accuracy/profiles/reference.yaml --candidate data/accuracy/profiles/base.yaml \
  --out-dir "$work/check2" > /dev/null 2> "$work/err"
code=$?
set -e
[ $code -eq 2 ] && grep -q "different seeds" "$work/err" || fail "profiles of different seeds: exit $code, $(cat "$work/err")"
# Two protocols on different packings are refused (the paper profile's packings changed in 0.6.0,
# the fast profile's did not): here stops-1's packings of seeds 101 and 102 swapped.
mkdir -p "$work/swapped" && cp -rL data/accuracy/base data/accuracy/stops-1 "$work/swapped/"
p=$work/swapped/stops-1/packings
mv "$p/seed-101.h5" "$p/tmp.h5" && mv "$p/seed-102.h5" "$p/seed-101.h5" && mv "$p/tmp.h5" "$p/seed-102.h5"
set +e
"$acc" check --data "$work/swapped" --reference data/accuracy/profiles/base.yaml --candidate data/accuracy/profiles/stops-1.yaml \
  --Fn-at 0.5 0.7 --kt-at 0.6 0.7 --out-dir "$work/check3" > /dev/null 2> "$work/err"
code=$?
set -e
[ $code -eq 2 ] && grep -q "the base and stops-1 profiles measured different packings of seed 101" "$work/err" ||
  fail "profiles of different packings: exit $code, $(cat "$work/err")"
[[ ! -e $work/check3/check.json ]] || fail "a check of different packings was written"
pass "softpack-study check: every quantity with both standard errors and the costs; different seeds, different packings refused"

# --- 5. the calibration report on the same runs (make study-report STUDY=FILE, another kind) ---
sed -e 's/^study: .*/study: calibrate-test/' -e 's/^report: .*/report: calibration/' \
  -e 's/^  - {script: figures.*/  - {script: figures\/calibration_onset.gp, data: onset.dat, name: onset}/' \
  -e 's/^compare:.*/compare: {Fn_delta_n: [0.5, 0.7], kt_delta_n: [0.6, 0.7]}\ncalibrate: {b_range: {soft-solid: [0.4, 0.8]}}\ncommon: {fit: {weighting: unweighted, onset_force: 1.0e-3}}/' \
  experiments/studies/tiny.yaml > "$work/calibrate-test.yaml"
# The same profiles as the accuracy study's plus a fit section: only the averages would differ, not the runs.
mk study-report STUDY="$work/calibrate-test.yaml" > "$work/c.log" 2>&1 || { cat "$work/c.log"; fail "make study-report (calibration)"; }
cal=data/accuracy/report
for f in table.md onset.dat calibration.json onset.pdf onset.png; do [[ -s $cal/$f ]] || fail "$cal/$f is missing or empty"; done
grep -q '^| reference | (the base, experiments/quick.yaml) | 3 |' $cal/table.md || fail "calibration table: $(head -20 $cal/table.md)"
/usr/bin/python3 - "$cal/calibration.json" <<'PY' || fail "calibration.json"
import json, sys
r = json.load(open(sys.argv[1]))
q = r["quantities"]
s = {x["name"]: x for x in r["settings"]}
assert set(s) == {"reference", "base", "stops-1", "base-1-seed"}, list(s)
ref = s["reference"]
phi = ref["value"][q.index("solid fraction")]
assert 0.3 < phi < 0.8, phi
z = ref["value"][q.index("coordination after growth")]
assert z >= 1.0, z  # growth leaves every grown grain touching a neighbour or the shell
assert ref["error"][q.index("soft-solid Fn(0.7)")] > 0, ref
# One seed has no seed-to-seed error.
assert all(e is None for e in s["base-1-seed"]["error"]), s["base-1-seed"]["error"]
PY
pass "make study-report, a calibration study: every setting's laws and packings with their errors, table, data, figure"

# --- 6. fit options: the sweeps shared, only averages and fits run ------------------------------
cat > experiments/studies/tiny-fits.yaml <<'YAML'
study: tiny-fits
report: fits
stages: [fits]
base: experiments/quick.yaml
seeds: [101, 102, 103]
settings:
  unweighted: {set: {fit: {weighting: unweighted, onset_force: 1.0e-3}}}
YAML
mk tiny-fits > "$work/f.log" 2>&1 || { cat "$work/f.log"; fail "make tiny-fits"; }
for stage in packings normal tangential; do
  grep -q "^study: unweighted shares reference's $stage" "$work/f.log" || { cat "$work/f.log"; fail "unweighted did not share the $stage"; }
done
[ -d data/studies/tiny-fits/unweighted/checkpoints/normal ] || fail "the normal checkpoints did not come with the shared normal results"
! grep -qE '^(pack|normal|tangential): unweighted ' "$work/f.log" || { cat "$work/f.log"; fail "unweighted ran a sweep"; }
grep -qE '^fit: unweighted ' "$work/f.log" || { cat "$work/f.log"; fail "unweighted did not fit"; }
fits=data/studies/tiny-fits/report/table.md
[ "$(grep -c '^| unweighted | fit = ' $fits)" -eq 2 ] || fail "fits report: $(cat $fits)"
grep -q '^| reference | the reference | [0-9.e+-]* ± ' $fits || fail "no jackknife error in the fits report: $(cat $fits)"
pass "a fit-options study: its sweeps shared by stamp, only its averages and fits run"

