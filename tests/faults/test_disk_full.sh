#!/usr/bin/env bash
# A full disk or a read-only file system is one message and exit 2, never a crash, and leaves
# no partial result: every stage (pack, normal, tangential, average, fit) writes into a small
# tmpfs filled to a random level, so that the disk runs full at a random moment of the stage;
# then the space is freed and the same command, run again, gives the results of a run that never
# failed (the sweeps resume from the checkpoints written before the fault).
#
# The tmpfs is mounted in a private mount namespace (unshare -rm: no root needed where user
# namespaces are allowed); the namespace, and the mount with it, ends with this script.
#
#   test_disk_full.sh BIN_DIR SOURCE_DIR   (FAULT_SEED=N replays)
if [[ -z ${SOFTPACK_IN_NAMESPACE:-} ]]; then
  if ! unshare -rm true 2> /dev/null; then
    echo "SKIPPED: unshare -rm is not allowed here (no user or mount namespaces); a full disk is not tested"
    exit 77
  fi
  SOFTPACK_IN_NAMESPACE=1 exec unshare -rm "$0" "$@"
fi
bin=$1 root=$2
source "$(dirname "$0")/common.sh"
copy_samples "$tmp/s"
s=$tmp/s
disk=$tmp/disk
mkdir -p "$disk"
trap 'umount "$disk" 2> /dev/null; rm -rf "$tmp"; true' EXIT

# run_stage COMMAND...: runs it, its messages in $tmp/err.
run_stage() { "$@" > /dev/null 2> "$tmp/err"; }
fresh_disk() {  # fresh_disk KIB: an empty tmpfs of KIB KiB at $disk
  umount "$disk" 2> /dev/null || true
  mount -t tmpfs -o "size=${1}k" softpack-faults "$disk"
}

# check_stage NAME PRIMARY COMMAND...: the command writes only under $disk; PRIMARY is the
# stage's result file. What it writes is measured on an empty tmpfs first.
check_stage() {
  local name=$1 primary=$2
  shift 2
  fresh_disk 65536
  run_stage "$@" || fail "$name on an empty disk: $(cat "$tmp/err")"
  cp "$primary" "$tmp/reference-$(basename "$primary")"
  local used
  used=$(du -sk "$disk" | cut -f1)
  local runs=0 failed=0
  for _ in 1 2 3; do
    # Free space at random between none and all but one page of what the stage needs.
    local free=$((4 * $(random_below $(( (used + 3) / 4 )))))
    fresh_disk $((used + 64))
    head -c $(( (used + 64 - free) * 1024 )) /dev/zero > "$disk/filler" 2> /dev/null || true
    set +e
    "$@" > /dev/null 2> "$tmp/err"
    local code=$?
    set -e
    runs=$((runs + 1))
    if [[ $code == 0 ]]; then  # it fitted after all (tmpfs rounds to pages): the same results
      same_results "$tmp/reference-$(basename "$primary")" "$primary" || fail "$name, $free KiB free: other results"
      continue
    fi
    failed=$((failed + 1))
    [[ $code == 2 ]] || fail "$name with $free KiB free: exit $code (expected 2): $(cat "$tmp/err")"
    grep -q 'No space left on device' "$tmp/err" || fail "$name with $free KiB free: no 'No space left on device': $(cat "$tmp/err")"
    [[ $(grep -vc '^warning:' "$tmp/err") == 1 ]] || fail "$name with $free KiB free: more than one line: $(cat "$tmp/err")"
    grep -q 'infinite loop closing library' "$tmp/err" && fail "$name: libhdf5 loops at exit"
    [[ ! -e $primary ]] || fail "$name with $free KiB free: $primary was left"
    no_temporaries "$disk" || fail "$name with $free KiB free: a temporary was left: $(find "$disk" -name '*.tmp.*')"
    # The fault fixed: the same command gives the results of a run that never failed.
    rm -f "$disk/filler"
    run_stage "$@" || fail "$name after freeing the space: $(cat "$tmp/err")"
    same_results "$tmp/reference-$(basename "$primary")" "$primary" ||
      fail "$name after freeing the space: the results differ from a run that never failed"
  done
  [[ $failed -gt 0 ]] || fail "$name: the disk never ran full in $runs runs"
  echo "ok: $name: the disk ran full in $failed of $runs runs: one message, exit 2, nothing partial; rerun: same results"
}

check_stage pack "$disk/p.h5" pack 1 "$disk/p.h5" --vtp "$disk/p.vtp" --xyz "$disk/p.xyz"
check_stage normal "$disk/n.h5" normal 1 "$s/p1.h5" "$disk/ck" "$disk/n.h5"
check_stage tangential "$disk/t.h5" tangential 1 "$s/p1.h5" "$s/ck1" "$disk/tk" "$disk/t.h5"
check_stage average "$disk/avg/soft-solid.h5" average "$s/n1.h5" "$s/n2.h5" "$s/t1.h5" "$s/t2.h5" "$disk/avg"
check_stage fit "$disk/fit.json" fit "$s/avg/soft-solid.h5" "$disk/fit.json" "$disk/fit.gp"

# A read-only file system (or a folder the user may not write): one message, exit 2.
fresh_disk 1024
mount -o remount,ro "$disk"
expect_error "Read-only file system" "$disk/n.h5" normal 1 "$s/p1.h5" "$disk/ck" "$disk/n.h5"
expect_error "Read-only file system" "$disk/p.h5" pack 1 "$disk/p.h5"
expect_error "Read-only file system" "$disk/fit.json" fit "$s/avg/soft-solid.h5" "$disk/fit.json" "$disk/fit.gp"
echo "ok: a read-only file system: one message, exit 2, no output"
