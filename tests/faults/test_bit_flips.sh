#!/usr/bin/env bash
# A flipped bit in any file the stages write is an error on read, never a silent wrong value:
#   1. (PART h5py) h5py alone (a standard reader) reads every dataset and attribute of each file
#      kind (packing, checkpoint, normal and tangential results, average) after random
#      single-bit flips: each read fails or gives exactly the original values
#      (tests/faults/h5_bitflips.py); h5dump reads the intact files;
#   2. (PART stages) the stages themselves, given a file with a flipped bit at a random offset,
#      either refuse it (exit 2, "corrupt" in the one message, no output) or give the same results
#      as with the intact file (the bit was in unused bytes); a damaged checkpoint is computed
#      again.
# ctest runs the parts as two tests: readers.h5py_bit_flips (Python and libhdf5, no C++ of ours)
# and faults.bit_flips (our readers: the sanitizer suite runs it).
#
#   test_bit_flips.sh BIN_DIR SOURCE_DIR [PART]   (PART: h5py, stages, or both by default;
#                                                  FAULT_SEED=N replays; FLIPS=N flips per kind)
bin=$1 root=$2 part=${3:-all}
source "$(dirname "$0")/common.sh"
flips=${FLIPS:-12}
copy_samples "$tmp/s"
s=$tmp/s

# --- 1. h5py and h5dump ----------------------------------------------------------------------------
if [[ $part != stages ]]; then
  for f in p1.h5 ck1/point-002.h5 n1.h5 t1.h5 avg/soft-solid.h5; do
    h5dump "$s/$f" > /dev/null || fail "h5dump cannot read the intact $f"
    out=$("$py" "$root/tests/faults/h5_bitflips.py" "$s/$f" --flips $((flips * 10)) --seed "$seed" 2> /dev/null) ||
      fail "h5py read wrong values: $out"
    echo "ok: h5py, $out"
    grep -q ' 0 wrong values' <<< "$out" || fail "h5py: $out"
  done
fi
[[ $part != h5py ]] || exit 0

# flip FILE: one bit at a random offset of FILE, in place; says where.
flip() {
  local size offset bit
  size=$(stat -c %s "$1") offset=$(random_below "$(stat -c %s "$1")") bit=$(random_below 8)
  "$py" -c "import sys; p, o, b = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]); d = bytearray(open(p, 'rb').read()); d[o] ^= 1 << b; open(p, 'wb').write(d)" \
    "$1" "$offset" "$bit"
  where="byte $offset bit $bit of $size"
}

# judge WHAT OUTPUT REFERENCE COMMAND...: the command on a damaged input refuses it (exit 2, one
# message saying the file is corrupt, no OUTPUT, no temporary) or gives REFERENCE's results.
refused=0 harmless=0
judge() {
  local what=$1 output=$2 reference=$3
  shift 3
  rm -rf "$output" "$(dirname "$output")"/*.tmp.*
  set +e
  "$@" > /dev/null 2> "$tmp/err"
  local code=$?
  set -e
  grep -q 'infinite loop closing library' "$tmp/err" && fail "$what ($where): libhdf5 loops at exit: $(cat "$tmp/err")"
  if [[ $code == 2 ]]; then
    grep -qE 'corrupt|not an HDF5 file' "$tmp/err" || fail "$what ($where): exit 2 without saying the file is corrupt: $(cat "$tmp/err")"
    [[ $(grep -c . "$tmp/err") == 1 ]] || fail "$what ($where): more than one line: $(cat "$tmp/err")"
    [[ ! -e $output ]] || fail "$what ($where): refused, but $output was written"
    refused=$((refused + 1))
  elif [[ $code == 0 ]]; then
    same_results "$reference" "$output" || fail "$what ($where): read without error but the results differ: a wrong value was used"
    harmless=$((harmless + 1))
  else
    fail "$what ($where): exit $code (expected 2, or 0 with the same results): $(cat "$tmp/err")"
  fi
  no_temporaries "$tmp" || fail "$what ($where): a temporary file was left"
}

# kind NAME INTACT OUTPUT COMMAND...: the command reads $tmp/x.h5 (a copy of INTACT) and writes
# OUTPUT; run once on the intact copy (the reference: provenance names the input's path), then
# on $flips copies with one bit flipped each.
kind() {
  local name=$1 intact=$2 output=$3
  shift 3
  rm -rf "$output" "$tmp/xck" && cp "$intact" "$tmp/x.h5"
  "$@" > /dev/null 2>&1 || fail "$name: the intact file is refused"
  local reference=$tmp/reference-$(basename "$output")
  cp "$output" "$reference"
  for _ in $(seq "$flips"); do
    rm -rf "$tmp/xck" && cp "$intact" "$tmp/x.h5" && flip "$tmp/x.h5"
    judge "$name" "$output" "$reference" "$@"
  done
}
kind "packing -> softpack-normal" "$s/p1.h5" "$tmp/xn.h5" normal 1 "$tmp/x.h5" "$tmp/xck" "$tmp/xn.h5"
kind "normal results -> softpack-average" "$s/n1.h5" "$tmp/xa/normal-soft-solid.dat" \
  average "$tmp/x.h5" "$s/n2.h5" "$s/t1.h5" "$s/t2.h5" "$tmp/xa"
kind "tangential results -> softpack-average" "$s/t2.h5" "$tmp/xa/tangential-soft-solid.dat" \
  average "$s/n1.h5" "$s/n2.h5" "$s/t1.h5" "$tmp/x.h5" "$tmp/xa"
kind "average -> softpack-fit" "$s/avg/soft-solid.h5" "$tmp/xf.gp" fit "$tmp/x.h5" "$tmp/xf.json" "$tmp/xf.gp"
echo "ok: the stages refused $refused damaged inputs and read $harmless with the same results (flips in unused bytes)"

# A damaged checkpoint is not used: the point is computed again, with a warning, same results
# (as a run at these paths, which the provenance records: the samples were made elsewhere).
normal 1 "$s/p1.h5" "$tmp/ck-reference" "$tmp/n1-reference.h5" 2> /dev/null || fail "the normal sweep of the intact samples"
for _ in 1 2 3; do
  rm -rf "$tmp/ck" && cp -r "$s/ck1" "$tmp/ck"
  point=$tmp/ck/point-00$(random_below 5).h5
  flip "$point"
  normal 1 "$s/p1.h5" "$tmp/ck" "$tmp/xn.h5" 2> "$tmp/err" || fail "resume with a damaged checkpoint ($where of $point): $(cat "$tmp/err")"
  same_results "$tmp/n1-reference.h5" "$tmp/xn.h5" || fail "resume with a damaged checkpoint ($where of $point): other results"
  grep -c 'checkpoint not used' "$tmp/err" > /dev/null || echo "  (the flip at $where of $point was in unused bytes)"
done
echo "ok: a damaged checkpoint is computed again, with the same results"
