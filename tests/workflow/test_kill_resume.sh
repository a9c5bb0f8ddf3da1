#!/usr/bin/env bash
# Nothing is lost (quick profile, in a copy of the source tree; the build is reused):
#   - `make tables` killed with SIGKILL (make and every job it started) at random moments, then
#     rerun until it completes, gives the same results as an uninterrupted run, and leaves no
#     partial or temporary file;
#   - make -j1, make -j2 and a second -j1 run give the same results.
# "The same": every HDF5 dataset identical (h5diff, exact) except the wall-clock timings
# (/seconds, /timing, /provenance, which record time spent and code version), and the text outputs
# (.dat, .gp, .md) identical except their provenance comments.
#
#   test_kill_resume.sh BUILD_DIR SOURCE_DIR [ROUNDS=5]   (RANDOM_SEED=n to replay a run)
source "$(dirname "$0")/common.sh"
rounds=${3:-5}
seed=${RANDOM_SEED:-$(( $(date +%s) % 32768 ))}
RANDOM=$seed
echo "random seed $seed (RANDOM_SEED=$seed to replay the same kill moments)"

copy_tree "$work/tree"
cd "$work/tree"
export MAKEFLAGS=
mk() { make --no-print-directory PROFILE=quick BUILD="$build" FROM_SCRATCH=1 "$@"; }

# same_results A B: the results of data trees A and B agree (see the header).
same_results() {
  local a=$1 b=$2 f rel n=0
  while IFS= read -r f; do
    rel=${f#"$a"/}
    [[ -f $b/$rel ]] || { echo "missing in $b: $rel"; return 1; }
    case $f in
      *.h5) h5diff -q --exclude-path /seconds --exclude-path /timing --exclude-path /provenance "$f" "$b/$rel" > /dev/null 2>&1 ||
              { echo "differs: $rel"; h5diff --exclude-path /seconds --exclude-path /timing --exclude-path /provenance "$f" "$b/$rel" | head -5; return 1; } ;;
      *.dat|*.gp|*.md) diff -q <(grep -v -e '^#' -e '^<!--' "$f") <(grep -v -e '^#' -e '^<!--' "$b/$rel") > /dev/null ||
              { echo "differs: $rel"; return 1; } ;;
      *) continue ;;
    esac
    n=$((n + 1))
  done < <(find "$a/quick" -path '*/checkpoints' -prune -o -type f -print | sort)
  [[ $n -gt 0 ]] || { echo "no results in $a"; return 1; }
  echo "$n files compared"
}

mk -j1 DATA=ref tables > "$work/ref.log" 2>&1 || { cat "$work/ref.log"; fail "uninterrupted make -j1"; }
mk -j2 DATA=j2 tables > "$work/j2.log" 2>&1 || { cat "$work/j2.log"; fail "make -j2"; }
mk -j1 DATA=again tables > "$work/again.log" 2>&1 || { cat "$work/again.log"; fail "second make -j1"; }
same_results ref j2 || fail "make -j1 and make -j2 differ"
same_results ref again || fail "two make -j1 runs differ"
pass "make -j1, make -j2 and a second run give the same results"

# Each round: from scratch, SIGKILL make and its jobs at a random moment within an uninterrupted
# run's duration, then rerun make to completion and compare.
start=$(date +%s%N); mk -j2 DATA=timing tables > /dev/null 2>&1; span_ms=$(( ($(date +%s%N) - start) / 1000000 ))
for round in $(seq 1 "$rounds"); do
  rm -rf killed
  delay_ms=$(( RANDOM % (span_ms + 1) ))
  setsid make --no-print-directory PROFILE=quick BUILD="$build" FROM_SCRATCH=1 DATA=killed -j2 tables > "$work/kill-$round.log" 2>&1 &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL -- -"$pid" 2> /dev/null && killed=yes || killed="no (it had finished)"
  wait "$pid" 2> /dev/null || true
  partial=$(find killed -type f -name '*.h5' 2> /dev/null | wc -l)
  mk -j2 DATA=killed tables > "$work/finish-$round.log" 2>&1 || { cat "$work/finish-$round.log"; fail "round $round: make after the kill"; }
  same_results ref killed > /dev/null || fail "round $round: results after a SIGKILL at $delay_ms ms differ (RANDOM_SEED=$seed)"
  leftovers=$(find killed -name '*.tmp*' | head -5)
  [[ -z $leftovers ]] || fail "round $round: temporary files survived the kill and the rerun: $leftovers"
  echo "round $round: SIGKILL after $delay_ms of $span_ms ms: killed $killed, $partial HDF5 files then; rerun: same results"
done
pass "$rounds rounds of SIGKILL at a random moment, then make: the same results, no temporary left"
