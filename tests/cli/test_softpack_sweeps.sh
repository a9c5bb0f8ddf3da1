#!/usr/bin/env bash
# softpack-normal and softpack-tangential from the command line: --help, a run with progress,
# resumption after a kill, a tangential stage that computes the normal states it lacks, and bad
# input (a packing of another profile, a grid that does not increase) refused with one message,
# exit 2, no output.
source "$(dirname "$0")/common.sh"
bin=$1
root=$2
profile=$root/tests/data/sweep-profile.yaml

"$bin/softpack-normal" --help | grep -q -- "--checkpoints" || fail "softpack-normal --help"
"$bin/softpack-tangential" --help | grep -q -- "--normal-checkpoints" || fail "softpack-tangential --help"

for s in 1 2; do "$bin/softpack-pack" --config "$profile" --seed $s --out "$tmp/p$s.h5" --quiet; done
normal() { "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 --packing "$tmp/p1.h5" "$@"; }
normal --checkpoints "$tmp/a" --out "$tmp/a.h5" 2> "$tmp/progress"
grep -q "point 5/5" "$tmp/progress" || fail "no progress lines: $(cat "$tmp/progress")"
# Delta_n 0 carries nothing: no force ratio there, which read as a failed relaxation (issue 31);
# a loaded point has its own.
grep "point 1/5" "$tmp/progress" | grep -q "not loaded yet" || fail "the unloaded point: $(grep "point 1/5" "$tmp/progress")"
grep "point 5/5" "$tmp/progress" | grep -q "force ratio" || fail "the loaded point has no force ratio: $(grep "point 5/5" "$tmp/progress")"

# Killed at a random moment, then started again: the same numbers as an uninterrupted run.
# (the command itself in the background, not the shell function: kill -9 of a function's subshell
# left the command running, which could write b.h5 after the resumed run)
"$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 --packing "$tmp/p1.h5" --checkpoints "$tmp/b" \
  --out "$tmp/b.h5" --quiet &
pid=$!
sleep "0.$((RANDOM % 3))"
kill -9 "$pid" 2> /dev/null || true
wait "$pid" 2> /dev/null || true
[ ! -e "$tmp/b.h5" ] || rm "$tmp/b.h5"  # it may have finished before the kill
ls "$tmp"/b 2> /dev/null | grep -q '\.tmp\.' && rm -f "$tmp"/b/*.tmp.*  # what a kill leaves: temporaries only
normal --checkpoints "$tmp/b" --out "$tmp/b.h5" --quiet --threads 2  # resumed on 2 threads (issue 32)
numbers() { h5dump -d /Fn -d /force -d /force_first -d /contacts -d /steps -d /relaxation/checks/force_ratio "$1" | tail -n +2; }
[ "$(numbers "$tmp/a.h5")" = "$(numbers "$tmp/b.h5")" ] || fail "resumed run (2 threads) differs from the uninterrupted one (1)"
threads_of() { h5dump -d /provenance/threads "$1" | awk '/\(0\)/ { print $2 }'; }
[ "$(threads_of "$tmp/a.h5")" = 1 ] && [ "$(threads_of "$tmp/b.h5")" = 2 ] ||
  fail "provenance/threads: $(threads_of "$tmp/a.h5") and $(threads_of "$tmp/b.h5"), expected 1 and 2"
set +e; normal --checkpoints "$tmp/c" --out "$tmp/c.h5" --quiet --threads 0 2> "$tmp/err"; code=$?; set -e
[ $code = 2 ] && grep -q -- "--threads" "$tmp/err" || fail "--threads 0: exit $code, $(cat "$tmp/err")"

sed 's/^  trials: .*/  trials: 2999/' "$profile" > "$tmp/other.yaml"  # another packing configuration
"$bin/softpack-pack" --config "$tmp/other.yaml" --seed 1 --out "$tmp/other.h5" --quiet
expect_error "this packing was made from another packing configuration" "$tmp/x.h5" \
  "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 --packing "$tmp/other.h5" --checkpoints "$tmp/x" --out "$tmp/x.h5"

# The tangential stage shears the normal stage's states; without them (normal results taken from
# the archive, which keeps no checkpoints) it computes them first: the same results.
tangential() { "$bin/softpack-tangential" --config "$profile" --scene soft-solid --seed 1 --packing "$tmp/p1.h5" "$@"; }
tangential --checkpoints "$tmp/ta" --normal-checkpoints "$tmp/a" --out "$tmp/ta.h5" --quiet
tangential --checkpoints "$tmp/tn" --normal-checkpoints "$tmp/n" --out "$tmp/tn.h5" 2> "$tmp/progress-t"
grep -q "normal state delta_n" "$tmp/progress-t" || fail "no progress lines for the normal states: $(cat "$tmp/progress-t")"
[ "$(numbers "$tmp/ta.h5")" = "$(numbers "$tmp/tn.h5")" ] || fail "tangential results differ when it computes the normal states"
ls "$tmp/n"/point-*.h5 > /dev/null 2>&1 || fail "the normal states were not saved as the normal stage's checkpoints"
sed 's/delta_n: \[0.0, 0.2, 0.4, 0.5, 0.6\]/delta_n: [0.0, 0.4, 0.2, 0.5, 0.6]/' "$profile" > "$tmp/bad.yaml"
expect_error "does not increase" "$tmp/y.h5" \
  "$bin/softpack-normal" --config "$tmp/bad.yaml" --scene soft-solid --seed 1 --packing "$tmp/p1.h5" --checkpoints "$tmp/y" --out "$tmp/y.h5"
expect_error "--second-packing: required for soft-soft" "$tmp/z.h5" \
  "$bin/softpack-normal" --config "$profile" --scene soft-soft --seed 1 --packing "$tmp/p1.h5" --checkpoints "$tmp/z" --out "$tmp/z.h5"
expect_error "scene 'hard-soft' is not allowed" "$tmp/z.h5" \
  "$bin/softpack-normal" --config "$profile" --scene hard-soft --seed 1 --packing "$tmp/p1.h5" --checkpoints "$tmp/z" --out "$tmp/z.h5"

# The sliding stage (issue 16): from the normal states, the second body moved parallel to the
# contact; a profile without a sliding section, or a sliding delta_n the normal grid lacks, is
# refused with one message naming it.
"$bin/softpack-sliding" --help | grep -q -- "--normal-checkpoints" || fail "softpack-sliding --help"
{ cat "$profile"; printf 'sliding: {delta_n: [0.5], ht_over_Rs: [0.01, 0.05], speed: 0.02}\n'; } > "$tmp/slide.yaml"
sliding() { "$bin/softpack-sliding" --config "$1" --scene soft-solid --seed 1 --packing "$tmp/p1.h5" --normal-checkpoints "$tmp/a" "${@:2}"; }
sliding "$tmp/slide.yaml" --checkpoints "$tmp/sa" --out "$tmp/sa.h5" 2> "$tmp/progress-s"
grep -q "point 2/2 delta_n 0.5000 ht" "$tmp/progress-s" || fail "no sliding progress lines: $(cat "$tmp/progress-s")"
[ "$(h5dump -d /provenance/stage "$tmp/sa.h5" | grep -c '"sliding"')" = 1 ] || fail "the sliding results are not marked as such"
sliding "$tmp/slide.yaml" --checkpoints "$tmp/sa" --out "$tmp/sb.h5" 2> "$tmp/progress-s2"
[ "$(grep -c '(checkpoint)' "$tmp/progress-s2")" = 2 ] || fail "a rerun of the sliding stage recomputed points: $(cat "$tmp/progress-s2")"
[ "$(numbers "$tmp/sa.h5")" = "$(numbers "$tmp/sb.h5")" ] || fail "the rerun's sliding results differ"
expect_error "no \`sliding\` section: this profile has no sliding measurement" "$tmp/sc.h5" sliding "$profile" --checkpoints "$tmp/sc" --out "$tmp/sc.h5"
sed 's/sliding: {delta_n: \[0.5\]/sliding: {delta_n: [0.45]/' "$tmp/slide.yaml" > "$tmp/slide-bad.yaml"
expect_error "0.45 is not in normal.delta_n: the sliding stage starts from the saved normal states" "$tmp/sc.h5" sliding "$tmp/slide-bad.yaml" --checkpoints "$tmp/sc" --out "$tmp/sc.h5"
echo ok
