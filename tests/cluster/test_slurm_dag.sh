#!/usr/bin/env bash
# The quick profile's DAG on a real (single-node) Slurm cluster, started for the test by
# tests/cluster/slurm_cluster.sh and stopped whatever happens:
#   1. make -j2 RUN="srun -N1 -n1" tables figures runs every engine invocation as a Slurm job
#      (counted in the cluster's job record against the invocations make -n lists), and gives
#      the same averages, fits, tables and sweep results as a local make (the fixture quick_run's
#      make -j2 tables figures; same_results.py:
#      byte for byte, provenance and timing aside);
#   2. a sweep job cancelled mid-way (scancel) fails make, and the next make resumes it from its
#      checkpoint (points marked reused) and ends with the same results.
# Exit 77 (skipped) when slurm-wlm or munge is not installed.
#
#   test_slurm_dag.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/../workflow/common.sh"
here=$(cd "$(dirname "$0")" && pwd)
cluster=$work/cluster
bg=  # the process group of a make started in the background
cleanup() {
  [[ -n $bg ]] && kill -- -"$bg" 2> /dev/null
  "$here"/slurm_cluster.sh stop "$cluster" || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM  # (the EXIT trap runs)
"$here"/slurm_cluster.sh start "$cluster" || exit $?
# Should this script be killed outright (a ctest timeout sends SIGKILL), a watcher in its own
# session stops the daemons, which have detached themselves.
setsid bash -c 'while kill -0 '"$$"' 2> /dev/null; do sleep 2; done; "$0" stop "$1"; rm -rf "$2"' \
  "$here"/slurm_cluster.sh "$cluster" "$work" > /dev/null 2>&1 < /dev/null &
eval "$("$here"/slurm_cluster.sh env "$cluster")"
export MAKEFLAGS=
jobs_done() { [[ -f $cluster/jobcomp.txt ]] && wc -l < "$cluster/jobcomp.txt" || echo 0; }

# --- 1. the whole DAG through srun = locally -------------------------------------------------------
quick_fixture_copy "$work/local"  # the local run: the fixture quick_run's make -j2 tables figures
copy_tree "$work/slurm"
# TOOLS= : run the built executables, never rebuild them (the build is the suite's).
mk() { make --no-print-directory PROFILE=quick BUILD="$build" DATA=data TOOLS= "$@"; }
cd "$work/slurm"
expected=$(mk -n FROM_SCRATCH=1 RUN=__RUN__ tables figures 2> /dev/null | grep -o '__RUN__ [^ ]*' | sort | uniq -c)
[[ -n $expected ]] || fail "make -n lists no engine invocation"
n_expected=$(awk '{n += $1} END {print n}' <<< "$expected")
mk -j2 FROM_SCRATCH=1 RUN="srun -N1 -n1" tables figures > "$work/slurm.log" 2>&1 ||
  { tail -30 "$work/slurm.log"; tail -20 "$cluster"/log/*.log; fail "make -j2 RUN=srun tables figures"; }
# The controller writes a job's record when it has processed its end: wait for all of them.
for _ in $(seq 1 300); do [[ $(jobs_done) -ge $n_expected ]] && break; sleep 0.1; done
n_jobs=$(jobs_done)
states=$(grep -o 'JobState=[A-Z]*' "$cluster/jobcomp.txt" | sort | uniq -c | tr -s ' ')
echo "engine invocations make -n lists:"; echo "$expected"
echo "Slurm jobs recorded: $n_jobs ($states)"
[[ $n_jobs == "$n_expected" ]] || fail "$n_jobs Slurm jobs for $n_expected engine invocations"
[[ $(grep -c 'JobState=COMPLETED' "$cluster/jobcomp.txt") == "$n_expected" ]] || fail "a job did not complete: $states"
while read -r count _ tool; do
  got=$(grep -c "Name=$(basename "$tool") " "$cluster/jobcomp.txt" || true)
  [[ $got == "$count" ]] || fail "$(basename "$tool"): $got Slurm jobs, $count invocations"
done <<< "$expected"
pass "every one of the $n_expected engine invocations ran as a Slurm job ($(awk '{printf "%s%s x%s", s, $3, $1; s=", "}' <<< "$expected" | sed 's|[^ ,]*/||g'))"
"$here"/same_results.py "$work/local/data/quick" data/quick || fail "srun and local results differ"
pass "srun and local runs: the same averages, fits, tables and sweep results"

# --- 2. a sweep job cancelled by Slurm is resumed by the next make ---------------------------------
# hold_sweep.sh stops one sweep after its first checkpointed point (no race with its end), and
# says which job it is; the test cancels that job.
before=$(jobs_done)
sweep=data-cancel/quick/normal/soft-solid-seed-1.h5
HOLD_OUT=$sweep setsid make --no-print-directory PROFILE=quick BUILD="$build" DATA=data-cancel TOOLS= FROM_SCRATCH=1 -j2 \
  RUN="srun -N1 -n1 $here/hold_sweep.sh" tables > "$work/cancel.log" 2>&1 &
pid=$! bg=$!
for _ in $(seq 1 3000); do [[ -e $sweep.held ]] && break; kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
[[ -e $sweep.held ]] || { kill -- -"$pid" 2> /dev/null; cat "$work/cancel.log"; fail "the sweep $sweep was never held"; }
job=$(cat "$sweep.held")
squeue -h -j "$job" -t RUNNING -o %i | grep -qx "$job" || fail "job $job of $sweep is not running"
scancel "$job"
wait "$pid" && fail "make succeeded although its sweep job $job was cancelled"
bg=
grep -q "normal: FAILED for quick soft-solid seed 1" "$work/cancel.log" || { cat "$work/cancel.log"; fail "make did not report the cancelled sweep"; }
[[ -e $sweep ]] && fail "the cancelled sweep left its result file $sweep"
for _ in $(seq 1 100); do grep -q "JobId=$job .*JobState=CANCELLED" "$cluster/jobcomp.txt" && break; sleep 0.1; done
grep "JobId=$job " "$cluster/jobcomp.txt" | grep -q 'JobState=CANCELLED' || fail "job $job is not recorded as cancelled"
pass "scancel of sweep job $job ($sweep, held after its first point): make fails and names the sweep"
rm "$sweep.held"
mk -j2 DATA=data-cancel RUN="srun -N1 -n1" tables > "$work/resume.log" 2>&1 ||
  { tail -30 "$work/resume.log"; fail "make after the cancelled job"; }
reused=$(/usr/bin/python3 -c "import h5py, sys; print(int(h5py.File(sys.argv[1])['timing/reused'][()].sum()))" "$sweep")
[[ $reused -ge 1 ]] || fail "the rerun of $sweep reused no checkpointed point"
"$here"/same_results.py "$work/local/data/quick" data-cancel/quick || fail "the resumed run differs from the local run"
pass "the next make resumed $sweep from its checkpoint ($reused points reused) and gave the same results; $(($(jobs_done) - before)) Slurm jobs in all"
