# Sourced by the fault-injection tests (tests/faults/test_*.sh, ctest label faults): the scratch
# folder $tmp, fail, expect_error (tests/cli/common.sh), a random seed printed so that a failure
# can be replayed (FAULT_SEED=N), and the files of every kind the stages write, made with the
# small sweep profile of the command-line tests (about a second).
source "$(dirname "${BASH_SOURCE[0]}")/../cli/common.sh"
seed=${FAULT_SEED:-$(( $(date +%s%N) % 1000000 ))}
echo "fault seed $seed (replay: FAULT_SEED=$seed)"
profile=$root/tests/data/sweep-profile.yaml
py=/usr/bin/python3  # Debian's, with python3-h5py

# random_below N: a random integer in [0, N), also for N > 32767. The draws follow from the seed
# alone, also inside $(...): bash reseeds $RANDOM in every subshell, so the generator's state (a
# 64-bit LCG) is kept in a file of the test's scratch folder instead.
rng_state=$tmp/.rng-state
echo "$seed" > "$rng_state"
random_below() {
  local s
  s=$(( ($(< "$rng_state") * 6364136223846793005 + 1442695040888963407) & 0x7fffffffffffffff ))
  echo "$s" > "$rng_state"
  echo $(( (s >> 17) % $1 ))
}

# The stages' commands on the sample files; OUT arguments last so the tests can redirect them.
pack() { "$bin/softpack-pack" --config "$profile" --seed "$1" --quiet --out "$2" "${@:3}"; }
normal() {  # normal SEED PACKING CHECKPOINTS OUT
  "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed "$1" --packing "$2" --checkpoints "$3" --out "$4" --quiet
}
tangential() {  # tangential SEED PACKING NORMAL_CHECKPOINTS CHECKPOINTS OUT
  "$bin/softpack-tangential" --config "$profile" --scene soft-solid --seed "$1" --packing "$2" --normal-checkpoints "$3" \
    --checkpoints "$4" --out "$5" --quiet
}
average() {  # average NORMAL1 NORMAL2 TANGENTIAL1 TANGENTIAL2 OUT_DIR
  "$bin/softpack-average" --scene soft-solid --profile sweep --normal "$1" "$2" --tangential "$3" "$4" --out-dir "$5"
}
fit() { "$bin/softpack-fit" --average "$1" --out "$2" --gnuplot "$3"; }

# make_samples DIR: packings, checkpoints, normal and tangential results of seeds 1 and 2, the
# average and the fit, as the workflow makes them (the fixture faults_samples makes them once per
# suite: tests/faults/samples.sh; the tests take a copy with copy_samples DIR).
make_samples() {
  local d=$1 s
  mkdir -p "$d"
  for s in 1 2; do
    pack $s "$d/p$s.h5"
    normal $s "$d/p$s.h5" "$d/ck$s" "$d/n$s.h5"
    tangential $s "$d/p$s.h5" "$d/ck$s" "$d/tk$s" "$d/t$s.h5"
  done
  average "$d/n1.h5" "$d/n2.h5" "$d/t1.h5" "$d/t2.h5" "$d/avg" 2> /dev/null
  fit "$d/avg/soft-solid.h5" "$d/fit.json" "$d/fit.gp" 2> /dev/null
}

# same_results A B: A and B hold the same results (the wall-clock seconds aside: every other value
# of the HDF5 files, the text of the others without its comments).
same_results() {
  case $1 in
    *.h5) h5diff -q --exclude-path /seconds --exclude-path /timing --exclude-path /provenance/seconds --exclude-path /provenance/cpu_seconds --exclude-path /result/seconds --exclude-path /result/timing "$1" "$2" ;;
    *.json) diff -q <(grep -v -e '"seconds"' -e '"cpu_seconds"' "$1") <(grep -v -e '"seconds"' -e '"cpu_seconds"' "$2") > /dev/null ;;
    *) diff -q <(grep -v '^#' "$1") <(grep -v '^#' "$2") > /dev/null ;;
  esac
}

# no_temporaries DIR: nothing named *.tmp.* left under DIR.
no_temporaries() { ! find "$1" -name '*.tmp.*' | grep -q .; }

# The fixture faults_samples (tests/faults/samples.sh): the samples of make_samples, made once.
samples_fixture=$(dirname "$bin")/test-fixtures/faults-samples
# copy_samples DIR: a copy of them in DIR.
copy_samples() {
  [[ -f $samples_fixture/done ]] || fail "no samples in $samples_fixture: the fixture faults_samples (faults.samples) failed or did not run"
  mkdir -p "$(dirname "$1")"
  cp -a "$samples_fixture/s" "$1"
}
