#!/usr/bin/env bash
# Bad input never passes silently. For every executable that reads configuration or HDF5 files
# (softpack-run, -pack, -normal, -tangential, -average, -fit): malformed YAML (with line and
# column), an unknown key (with the closest valid key), a value out of range, a missing file, a
# truncated HDF5 file, a foreign HDF5 file (not ours, or ours of another kind) and a packing of
# another configuration each give one message naming the file (and the key or dataset), exit
# code 2, and no output file or temporary left behind. So do values beyond the ranges of
# engine/scene/limits.hpp (seeds, moduli, radii, step counts), a seed given twice, and every
# command line that CLI11 refuses (exit 2, not CLI11's codes; --help exits 0). The cases
# test_softpack_*.sh already check are not repeated here.
set -euo pipefail
bin=$(cd "$1" && pwd)
root=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$tmp"

# Valid inputs: a tiny profile (half a dozen grains per soft-particle), two packings, a normal
# sweep of seed 1, an HDF5 file that is not ours (h5import, hdf5-tools), truncated copies.
profile=$root/fuzz/seed-profile.yaml
"$bin/softpack-pack" --config "$profile" --seed 1 --out p1.h5 --quiet
"$bin/softpack-pack" --config "$profile" --seed 2 --out p2.h5 --quiet
"$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 --packing p1.h5 --checkpoints n1 --out n1.h5 --quiet
printf '1.0 2.0 3.0 4.0\n' > numbers.txt
printf 'PATH /data\nINPUT-CLASS TEXTFP\nRANK 1\nDIMENSION-SIZES 4\nOUTPUT-CLASS FP\nOUTPUT-SIZE 64\n' > h5import.cfg
h5import numbers.txt -c h5import.cfg -o foreign.h5
head -c 1000 p1.h5 > truncated.h5
head -c 3000 n1.h5 > truncated-results.h5
sed 's/^  trials: .*/  trials: 299/' "$profile" > other.yaml  # another packing configuration
"$bin/softpack-pack" --config other.yaml --seed 3 --out other.h5 --quiet
scene=$root/experiments/scenes/sphere-on-wall.yaml
[ -z "$(find . -name '*.tmp.*')" ] || fail "temporaries after the valid runs"

# expect_error PATTERN OUTPUT COMMAND...: exit code 2; stderr is one line, "<program>: error: ",
# matching PATTERN (extended regex); OUTPUT not created; no temporary anywhere.
expect_error() {
  local pattern=$1 output=$2
  shift 2
  set +e
  "$@" 2> err > /dev/null
  local code=$?
  set -e
  [ -z "${VERBOSE:-}" ] || cat err >&2
  [ "$code" -eq 2 ] || fail "exit code $code (expected 2) for: $*: $(cat err)"
  [ "$(wc -l < err)" -eq 1 ] || fail "expected one line on stderr for: $*, got: $(cat err)"
  grep -qE "^softpack-[a-z-]+: error: " err || fail "not an error line: $(cat err)"
  grep -qE -- "$pattern" err || fail "expected /$pattern/, got: $(cat err)"
  [ ! -e "$output" ] || fail "$output was written for bad input: $*"
  [ -z "$(find . -name '*.tmp.*')" ] || fail "a temporary was left behind: $(find . -name '*.tmp.*')"
}
# edit FILE SED: FILE with one change (that must change something) -> bad.yaml.
edit() { sed "$2" "$1" > bad.yaml; ! cmp -s bad.yaml "$1" || fail "edit $2 changed nothing"; }

# --- softpack-run: scene files ------------------------------------------------------------------
run() { "$bin/softpack-run" --scene "$1" --out run.json --quiet; }
edit "$scene" 's/damping: {restitution: /damping: {restitution: [/'
expect_error "^softpack-run: error: bad\.yaml:[0-9]+:[0-9]+: malformed YAML" run.json run bad.yaml
edit "$scene" 's/restitution:/restitusion:/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: effects\.damping\.restitusion: unknown key; did you mean 'restitution'\?" run.json run bad.yaml
edit "$scene" 's/nu: [0-9.]*/nu: 0.7/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: materials\.grain\.nu: 0\.7 is not allowed; allowed: -1 < nu < 0\.5" run.json run bad.yaml
expect_error "none\.yaml: cannot open the file" run.json run none.yaml
expect_error "softpack-run: error: \.: is a directory, expected a YAML file" run.json run .
edit "$scene" 's/^effects:/effects:\n  rotation: true\neffects:/'
expect_error "bad\.yaml:[0-9]+:1: effects: duplicate key \(first at line [0-9]+, column 1\)" run.json run bad.yaml
{ cat "$scene"; printf '# caf\xe9\n'; } > bad.yaml  # a Latin-1 comment: YAML is UTF-8
expect_error "bad\.yaml:[0-9]+:6: not UTF-8 text \(byte 0xE9\)" run.json run bad.yaml

# --- softpack-pack: the packing section of a profile --------------------------------------------
pack() { "$bin/softpack-pack" --config "$1" --seed 1 --out pack.h5 --quiet; }
printf 'packing:\n  Rs: [0.016\n  beta: 2\n' > bad.yaml
expect_error "^softpack-pack: error: bad\.yaml:[0-9]+:[0-9]+: malformed YAML" pack.h5 pack bad.yaml
edit "$profile" 's/polydispersity:/polydisperity:/'
expect_error "bad\.yaml:[0-9]+:3: packing\.polydisperity: unknown key; did you mean 'polydispersity'\?" pack.h5 pack bad.yaml
edit "$profile" 's/profile_bins: [0-9]*/profile_bins: 0/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: packing\.profile_bins: 0 is not allowed; allowed: 1 <= bins <= 100000" pack.h5 pack bad.yaml
edit "$profile" 's/beta: [0-9.]*/beta: 1e999/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: packing\.beta: '1e999' is out of the range of numbers" pack.h5 pack bad.yaml
{ cat "$profile"; printf -- '---\nseeds: [3]\n'; } > bad.yaml
expect_error "bad\.yaml:[0-9]+:1: a second YAML document" pack.h5 pack bad.yaml

# --- softpack-normal: profile and packings ------------------------------------------------------
normal() { "$bin/softpack-normal" --config "$1" --scene "$2" --seed 1 --packing "$3" --second-packing "$4" \
             --checkpoints ncp --out normal.h5 --quiet; }
edit "$profile" 's/^normal:/normal: [/'
expect_error "^softpack-normal: error: bad\.yaml:[0-9]+:[0-9]+: malformed YAML" normal.h5 normal bad.yaml soft-solid p1.h5 p2.h5
edit "$profile" 's/  speed:/  sped:/'
expect_error "bad\.yaml:[0-9]+:3: normal\.sped: unknown key; did you mean 'speed'\?" normal.h5 normal bad.yaml soft-solid p1.h5 p2.h5
edit "$profile" 's/safety: [0-9.]*/safety: 1.5/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: simulation\.integration\.safety: 1\.5 is not allowed; allowed: 0 < safety <= 1" normal.h5 \
  normal bad.yaml soft-solid p1.h5 p2.h5
expect_error "none\.h5: no such file" normal.h5 normal "$profile" soft-solid none.h5 p2.h5
expect_error "truncated\.h5: truncated or corrupt HDF5 file: it has 1000 bytes, its superblock says [0-9]+" normal.h5 \
  normal "$profile" soft-solid truncated.h5 p2.h5
expect_error "foreign\.h5: not a softpack packing file \(no /centres, /radii or /provenance/program\)" normal.h5 \
  normal "$profile" soft-solid foreign.h5 p2.h5
expect_error "n1\.h5: not a softpack packing file \(it is a normal sweep results file \(softpack-normal\)\)" normal.h5 \
  normal "$profile" soft-solid n1.h5 p2.h5
expect_error "other\.h5: this packing was made from another packing configuration than the .packing. section of .*seed-profile\.yaml \('trials: 299' in the packing, 'trials: 300' in the profile;" normal.h5 \
  normal "$profile" soft-soft p1.h5 other.h5
expect_error "truncated\.h5: truncated or corrupt HDF5 file" normal.h5 normal "$profile" soft-soft p1.h5 truncated.h5
[ ! -e ncp ] || [ -z "$(ls -A ncp)" ] || fail "checkpoints were written for bad input: $(ls ncp)"

# --- softpack-tangential: profile, packings and the normal states --------------------------------
tangential() { "$bin/softpack-tangential" --config "$1" --scene soft-solid --seed 1 --packing "$2" \
                 --checkpoints tcp --normal-checkpoints "$3" --out tangential.h5 --quiet; }
edit "$profile" 's/after_rotation:/after_rotaton:/'
expect_error "^softpack-tangential: error: bad\.yaml:[0-9]+:3: tangential\.after_rotaton: unknown key; did you mean 'after_rotation'\?" \
  tangential.h5 tangential bad.yaml p1.h5 n1
edit "$profile" 's/alpha_deg: \[-0.5, 0.0, 0.5\]/alpha_deg: [-0.5, 0.0, 95]/'
expect_error "bad\.yaml:[0-9]+:[0-9]+: tangential\.alpha_deg\[2\]: 95 is not allowed; allowed: -90 <= value <= 90" tangential.h5 \
  tangential bad.yaml p1.h5 n1
printf 'tangential: {rate: 0.1\n' > bad.yaml
expect_error "bad\.yaml:[0-9]+:[0-9]+: malformed YAML" tangential.h5 tangential bad.yaml p1.h5 n1
expect_error "none\.yaml: cannot open the file" tangential.h5 tangential none.yaml p1.h5 n1
expect_error "other\.h5: this packing was made from another packing configuration" tangential.h5 \
  tangential "$profile" other.h5 n1
expect_error "foreign\.h5: not a softpack packing file" tangential.h5 tangential "$profile" foreign.h5 n1
[ ! -e tcp ] || [ -z "$(ls -A tcp)" ] || fail "checkpoints were written for bad input: $(ls tcp)"
# A truncated or foreign normal state is not used: the tangential stage computes it again, as
# the normal stage does with its own checkpoints.
state() { h5dump -d /result/force -d /state/x "$1" | tail -n +2; }
for bad in truncated foreign; do
  rm -rf n1-bad tcp-bad && cp -r n1 n1-bad
  if [ $bad = truncated ]; then head -c 2000 n1/point-003.h5 > n1-bad/point-003.h5; else cp foreign.h5 n1-bad/point-003.h5; fi
  "$bin/softpack-tangential" --config "$profile" --scene soft-solid --seed 1 --packing p1.h5 --checkpoints tcp-bad \
    --normal-checkpoints n1-bad --out t-bad.h5 --quiet || fail "tangential with a $bad normal state"
  [ "$(state n1-bad/point-003.h5)" = "$(state n1/point-003.h5)" ] || fail "the $bad normal state was not computed again"
done

# --- softpack-average: sweep results ------------------------------------------------------------
average() { "$bin/softpack-average" --scene "$1" --profile fuzz-seed --normal "$2" --tangential "$3" --out-dir avg; }
expect_error "^softpack-average: error: none\.h5: no such file" avg average soft-solid none.h5 n1.h5
expect_error "truncated-results\.h5: truncated or corrupt HDF5 file" avg average soft-solid n1.h5 truncated-results.h5
expect_error "foreign\.h5: not a softpack sweep results file \(no /delta_n, /Fn or /provenance/stage\)" avg \
  average soft-solid foreign.h5 n1.h5
expect_error "p1\.h5: not a softpack sweep results file \(it is a packing file \(softpack-pack\)\)" avg average soft-solid p1.h5 n1.h5
expect_error "n1\.h5: /provenance/stage: these are normal results, tangential ones are expected here" avg \
  average soft-solid n1.h5 n1.h5
expect_error "n1\.h5: /provenance/scene: these are results of the soft-solid scene, not of soft-soft" avg \
  average soft-soft n1.h5 n1.h5
expect_error "--scene: 'soft-hard' is not allowed; allowed: soft-solid, soft-soft" avg average soft-hard n1.h5 n1.h5

# --- softpack-fit: average files ----------------------------------------------------------------
fit() { "$bin/softpack-fit" --average "$1" --out fit.json --quiet; }
expect_error "^softpack-fit: error: truncated\.h5: truncated or corrupt HDF5 file" fit.json fit truncated.h5
expect_error "foreign\.h5: not a softpack average file \(no /normal/delta_n or /provenance/scene\)" fit.json fit foreign.h5
expect_error "p1\.h5: not a softpack average file \(it is a packing file \(softpack-pack\)\)" fit.json fit p1.h5
expect_error "n1\.h5: not a softpack average file \(it is a normal sweep results file \(softpack-normal\)\)" fit.json fit n1.h5

# --- Ranges (engine/scene/limits.hpp) -----------------------------------------------------------
# Random draws below (seeds, magnitudes) come from bash's RANDOM with a fixed seed, printed, so
# that a failure reproduces.
range_seed=20240611
RANDOM=$range_seed
echo "random seed of the range cases: $range_seed"
case_name() { echo "case: $1"; }
re() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|/]/\\&/g'; }  # TEXT as an extended regex
# big_seed: a random integer of [9.3e18, 2e19), beyond 2^63 - 1 = 9223372036854775807, as
# decimal text: 19 digits from 93..., or 20 from 1... (across 2^64 = 18446744073709551616).
big_seed() {
  local s k
  if ((RANDOM % 2)); then s="9$((3 + RANDOM % 7))"; else s="1$((RANDOM % 10))"; fi
  for k in $(seq 1 17); do s="$s$((RANDOM % 10))"; done
  [ "${s:0:1}" = 9 ] || s="$s$((RANDOM % 10))"
  echo "$s"
}
# big_magnitude LO HI: 1.0e<k> with k a random integer in [LO, HI].
big_magnitude() { echo "1.0e$(($1 + RANDOM % ($2 - $1 + 1)))"; }

case_name seed_of_2_63_or_more_on_the_command_line_is_refused
for s in 9223372036854775808 18446744073709551615 18446744073709551616 "$(big_seed)" "$(big_seed)"; do
  expect_error "^softpack-pack: error: --seed: '$s' is not allowed; allowed: a seed, an integer 0 <= seed <= 9223372036854775807" \
    pack.h5 "$bin/softpack-pack" --config "$profile" --seed "$s" --out pack.h5 --quiet
  expect_error "^softpack-normal: error: --seed: '$s' is not allowed; allowed: a seed" normal.h5 \
    "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed "$s" --packing p1.h5 --checkpoints ncp --out normal.h5
  expect_error "^softpack-tangential: error: --seed: '$s' is not allowed; allowed: a seed" tangential.h5 \
    "$bin/softpack-tangential" --config "$profile" --scene soft-solid --seed "$s" --packing p1.h5 --checkpoints tcp \
    --normal-checkpoints n1 --out tangential.h5
done

case_name seed_that_is_not_plain_decimal_digits_is_refused_with_exit_2
for s in 1.5 1e3 2.0 +3 " 3" "3 " 007 0x10 -1 abc ""; do
  expect_error "^softpack-pack: error: --seed: '$(re "$s")' is not allowed; allowed: a seed" pack.h5 \
    "$bin/softpack-pack" --config "$profile" --seed "$s" --out pack.h5 --quiet
done
"$bin/softpack-pack" --config "$profile" --seed 9223372036854775807 --out max.h5 --quiet
[ "$(h5dump -d /provenance/seed max.h5 | grep -o '(0): [0-9]*')" = "(0): 9223372036854775807" ] || fail "the largest seed was not recorded exactly"

case_name seed_of_2_63_or_more_in_a_profile_is_refused
for s in 9223372036854775808 "$(big_seed)"; do
  edit "$profile" "s/^seeds: \[1, 2\]/seeds: [1, $s]/"
  expect_error "^softpack-config: error: bad\.yaml:4:12: seeds\[1\]: '$s' is not allowed; allowed: a seed, an integer 0 <= seed <= 9223372036854775807" \
    none.txt "$bin/softpack-config" bad.yaml seeds
done
edit "$profile" 's/^seeds: \[1, 2\]/seeds: [1, 2.5]/'
expect_error "bad\.yaml:4:12: seeds\[1\]: '2\.5' is not allowed; allowed: a seed" none.txt "$bin/softpack-config" bad.yaml seeds

case_name repeated_seeds_in_a_profile_are_refused
edit "$profile" 's/^seeds: \[1, 2\]/seeds: [1, 1]/'
expect_error "bad\.yaml:4:12: seeds\[1\]: seed 1 is listed twice \(first as seeds\[0\]\)" none.txt "$bin/softpack-config" bad.yaml seeds

case_name average_of_one_file_twice_or_of_one_seed_twice_is_refused
# Each of these averaged one packing twice (standard error 0 for [1, 1]) and exited 0. t-bad.h5:
# the tangential results of seed 1 (above).
cp n1.h5 n1-copy.h5  # another file, the same seed
cp t-bad.h5 t1-copy.h5
avg() { "$bin/softpack-average" --scene soft-solid --profile fuzz-seed --normal $1 --tangential $2 --out-dir avg; }
expect_error "^softpack-average: error: --normal: n1\.h5 and n1\.h5 are the same file; allowed: each seed's results once" avg \
  avg "n1.h5 n1.h5" t-bad.h5
expect_error "^softpack-average: error: --normal: n1\.h5 and \./n1\.h5 are the same file" avg avg "n1.h5 ./n1.h5" t-bad.h5
expect_error "^softpack-average: error: --normal: n1\.h5 and n1-copy\.h5 are both results of seed 1; allowed: each seed's results once" \
  avg avg "n1.h5 n1-copy.h5" t-bad.h5
expect_error "^softpack-average: error: --tangential: t-bad\.h5 and t1-copy\.h5 are both results of seed 1" avg \
  avg n1.h5 "t-bad.h5 t1-copy.h5"
"$bin/softpack-average" --scene soft-solid --profile fuzz-seed --normal n1.h5 --tangential t-bad.h5 --out-dir avg ||
  fail "the average of one seed's results was refused"

case_name results_of_another_seed_than_the_packing_or_the_other_law_are_refused
# Both exited 0: a sweep filed under --seed 2 measured the packing of seed 1; an average mixed
# the normal results of seeds 1 and 2 with the tangential results of seed 1.
expect_error "^softpack-normal: error: --seed: 2 does not match --packing p1\.h5, which was made with seed 1" n-seed.h5 \
  "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 2 --packing p1.h5 --checkpoints ncp-seed --out n-seed.h5 --quiet
"$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 2 --packing p2.h5 --checkpoints n2 --out n2.h5 --quiet
rm -rf avg
expect_error "^softpack-average: error: --tangential: results of seeds 1, --normal: of seeds 1, 2; allowed: the same seeds for both" avg \
  avg "n1.h5 n2.h5" t-bad.h5

case_name youngs_modulus_that_overflows_is_refused_before_the_sweep
# E = 1e308 made the normal sweep spin (a time step of 1e-156 s, infinite residuals): the timeout
# turns that into a failure instead of a hang.
for E in 1.0e308 "$(big_magnitude 14 307)" "$(big_magnitude 14 307)"; do
  edit "$profile" "s/E: 5.0e5/E: $E/"
  expect_error "^softpack-normal: error: bad\.yaml:5:15: material\.E: [0-9.e]+ Pa is not allowed; allowed: 1 <= E <= 1e13 Pa" normal.h5 \
    timeout 60 "$bin/softpack-normal" --config bad.yaml --scene soft-solid --seed 1 --packing p1.h5 --checkpoints ncp --out normal.h5 --quiet
  expect_error "bad\.yaml:5:15: material\.E: [0-9.e]+ Pa is not allowed" none.txt "$bin/softpack-config" bad.yaml seeds
done
[ ! -e ncp ] || [ -z "$(ls -A ncp)" ] || fail "checkpoints were written for bad input: $(ls ncp)"

case_name shell_radius_that_overflows_is_refused
# Rs = 1e300 ended in "internal error: vector::reserve" (exit 1).
for Rs in 1.0e300 "$(big_magnitude 4 307)"; do
  edit "$profile" "s/Rs: 0.016/Rs: $Rs/"
  expect_error "^softpack-pack: error: bad\.yaml:7:7: packing\.Rs: [0-9.e]+ m is not allowed; allowed: 1e-9 <= Rs <= 1000 m" pack.h5 pack bad.yaml
done

case_name durations_of_more_than_1e12_steps_are_refused
# run.duration = 1e30 s (1.3e34 steps) used to run one step and exit 0: the step count overflowed.
for d in 1.0e30 "$(big_magnitude 9 300)"; do
  edit "$scene" "s/^  relaxation: .*/  duration: $d/"
  expect_error "^softpack-run: error: bad\.yaml:18:13: run\.duration: [0-9.e]+ s is [0-9.e]+ time steps of dt = 7\.74e-5 s; allowed: at most 1e12 steps" \
    run.json run bad.yaml
done
edit "$scene" 's/wait: 0.05, final_wait/wait: 1.0e20, final_wait/'
expect_error "bad\.yaml:18:49: run\.relaxation\.wait: the protocol \(6 stops after 1e20 s each, then 0\.05 s\) is [0-9.e]+ time steps" run.json run bad.yaml
edit "$profile" 's/speed: 0.02/speed: 1.0e-200/'
expect_error "^softpack-normal: error: bad\.yaml:[0-9]+:[0-9]+: normal\.speed: 1e-200 m/s, the approach of [0-9.e-]+ m .* time steps of dt = [0-9.e-]+ s; allowed: at most 1e12 steps" \
  normal.h5 timeout 60 "$bin/softpack-normal" --config bad.yaml --scene soft-solid --seed 1 --packing p1.h5 --checkpoints ncp --out normal.h5 --quiet
[ ! -e ncp ] || [ -z "$(ls -A ncp)" ] || fail "checkpoints were written for bad input: $(ls ncp)"

case_name settle_that_never_ends_early_or_without_a_measured_force_is_refused
edit "$scene" 's/final_wait: 0.05}/final_wait: 0.05, settle: {relative: 0.0, absolute: 0.0}}/'
expect_error "^softpack-run: error: bad\.yaml:18:[0-9]+: run\.relaxation\.settle: relative and absolute are both 0" run.json run bad.yaml
edit "$scene" 's/final_wait: 0.05}/final_wait: 0.05, settle: {relative: 0.01, absolute: 0.0}}/'
expect_error "^softpack-run: error: relaxation\.settle: needs a measured force" run.json run bad.yaml

case_name active_set_that_would_wake_at_once_or_has_an_unknown_key_is_refused
edit "$scene" 's/final_wait: 0.05}/final_wait: 0.05, active_set: {sleep_force: 1.0e-3, sleep_speed: 1.0e-6, wake_force: 1.0e-4, check_interval: 0.01}}/'
expect_error "^softpack-run: error: bad\.yaml:18:[0-9]+: run\.relaxation\.active_set\.wake_force: 0\.0001 is below sleep_force = 0\.001" run.json run bad.yaml
edit "$scene" 's/final_wait: 0.05}/final_wait: 0.05, active_set: {sleep_force: 1.0e-3, sleep_speed: 1.0e-6, wake: 1.0e-2, check_interval: 0.01}}/'
expect_error "^softpack-run: error: bad\.yaml:18:[0-9]+: .*wake: unknown key; allowed: sleep_force, sleep_speed, wake_force, check_interval" run.json run bad.yaml

# --- Command lines: CLI11's errors are bad input (exit 2, one line); --help exits 0 --------------
case_name every_executable_maps_command_line_errors_to_exit_2
for exe in softpack-run softpack-pack softpack-normal softpack-tangential softpack-sliding softpack-average softpack-fit softpack-table \
           softpack-config softpack-section softpack-apollonian softpack-timing softpack-study; do
  "$bin/$exe" --help > help.txt || fail "$exe --help: exit code $?"
  grep -q "^Usage: " help.txt || fail "$exe --help printed no usage"
  expect_error "^$exe: error: .+; see $exe --help$" none.txt "$bin/$exe" --no-such-option
  expect_error "^$exe: error: .* is required; see $exe --help$" none.txt "$bin/$exe"
done
# softpack-timing given a file of another kind names it.
expect_error "^softpack-timing: error: p1\.h5: not a softpack sweep results file" none.txt "$bin/softpack-timing" --normal p1.h5
# A value that does not convert (CLI11's exit code 104), or that a check refuses (105).
expect_error "^softpack-section: error: .*--offset.*abc" none.txt "$bin/softpack-section" --packing p1.h5 --out s.dat --offset abc
expect_error "^softpack-apollonian: error: .*--depth.*1\.5" ap.dat "$bin/softpack-apollonian" --depth 1.5 --out ap.dat
expect_error "^softpack-normal: error: Could not convert: .*= x; see softpack-normal --help" normal.h5 \
  "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 --packing p1.h5 --checkpoints ncp --out normal.h5 --stop-after x
expect_error "^softpack-config: error: .*spreading" none.txt "$bin/softpack-config" "$profile" stamp spreading
[ ! -e s.dat ] || fail "s.dat was written for bad input"
echo "ok"
