#!/usr/bin/env bash
# Nothing is lost (quick profile, in a copy of the fixture quick_run's tree; the build is reused):
# `make tables` killed with SIGKILL (make and every job it started) at random moments, then rerun
# until it completes, gives the same results as the fixture's uninterrupted run, and leaves no
# partial or temporary file. "The same": same_results (tests/workflow/common.sh), every HDF5
# dataset identical (h5diff, exact) except the wall-clock timings, the text outputs identical
# except their provenance comments. (That make -j1 and make -j2 give the same results is
# workflow.quick_profile's first check, on the same fixture.)
#
#   test_kill_resume.sh BUILD_DIR SOURCE_DIR [ROUNDS=5]   (RANDOM_SEED=n to replay a run)
source "$(dirname "$0")/common.sh"
rounds=${3:-5}
seed=${RANDOM_SEED:-$(( $(date +%s) % 32768 ))}
RANDOM=$seed
echo "random seed $seed (RANDOM_SEED=$seed to replay the same kill moments)"

quick_fixture_copy "$work/tree"
cd "$work/tree"
export MAKEFLAGS=
mk() { make --no-print-directory PROFILE=quick BUILD="$build" FROM_SCRATCH=1 "$@"; }
ref=data  # the fixture's uninterrupted make -j2 tables (and figures)
span_ms=$quick_tables_ms

# Each round: from scratch, SIGKILL make and its jobs at a random moment within an uninterrupted
# run's duration (the fixture's), then rerun make to completion and compare.
for round in $(seq 1 "$rounds"); do
  rm -rf killed
  delay_ms=$(( RANDOM % (span_ms + 1) ))
  setsid make --no-print-directory PROFILE=quick BUILD="$build" FROM_SCRATCH=1 DATA=killed -j2 tables > "$work/kill-$round.log" 2>&1 &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL -- -"$pid" 2> /dev/null && killed=yes || killed="no (it had finished)"
  wait "$pid" 2> /dev/null || true
  partial=$({ find killed -type f -name '*.h5' 2> /dev/null || true; } | wc -l)  # killed may not exist yet (an early kill)
  mk -j2 DATA=killed tables > "$work/finish-$round.log" 2>&1 || { cat "$work/finish-$round.log"; fail "round $round: make after the kill"; }
  same_results killed "$ref" > /dev/null || fail "round $round: results after a SIGKILL at $delay_ms ms differ (RANDOM_SEED=$seed)"
  leftovers=$(find killed -name '*.tmp*' | head -5)
  [[ -z $leftovers ]] || fail "round $round: temporary files survived the kill and the rerun: $leftovers"
  echo "round $round: SIGKILL after $delay_ms of $span_ms ms: killed $killed, $partial HDF5 files then; rerun: same results"
done
pass "$rounds rounds of SIGKILL at a random moment, then make: the same results, no temporary left"
