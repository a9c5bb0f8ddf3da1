#!/usr/bin/env bash
# The commands' executable (apps/softpack.cpp): every command `softpack --help` lists is a
# link softpack-<name> in the build, answers --help with its own name and exits 0; `softpack
# <name>` is the same command; a name that is no command is one line and exit 2.
#
#   test_softpack_commands.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
bin=$1 source_dir=$2

# The commands `softpack --help` lists are the build's (apps/CMakeLists.txt, SOFTPACK_COMMANDS).
mapfile -t names < <("$bin/softpack" --help | sed -n 's/^  softpack-\([a-z-]*\) .*/\1/p')
built=$(sed -n '/^set(SOFTPACK_COMMANDS/,/)/p' "$source_dir/apps/CMakeLists.txt" | sed 's/^set(SOFTPACK_COMMANDS//' | tr -d '()' | tr -s ' \n' '\n' | grep . | sort)
[[ $(printf '%s\n' "${names[@]}" | sort) == "$built" ]] ||
  fail "softpack --help lists ${names[*]}; apps/CMakeLists.txt builds $(echo $built)"
for name in "${names[@]}"; do
  [[ -L $bin/softpack-$name && $(readlink "$bin/softpack-$name") == softpack ]] || fail "$bin/softpack-$name is not a link to softpack"
  "$bin/softpack-$name" --help > "$tmp/help" || fail "softpack-$name --help: exit $?"
  grep -q "^softpack-$name: " "$tmp/help" || fail "softpack-$name --help does not name it: $(head -2 "$tmp/help")"
  "$bin/softpack" "$name" --help > "$tmp/help2" || fail "softpack $name --help: exit $?"
  cmp -s <(grep -v '^Usage:' "$tmp/help") <(grep -v '^Usage:' "$tmp/help2") || fail "softpack $name --help differs from softpack-$name --help"
done
echo "ok: ${#names[@]} commands, each a link answering --help; softpack <name> is the same"

for bad in bogus softpack-bogus ""; do
  set +e
  "$bin/softpack" $bad > "$tmp/out" 2> "$tmp/err"
  code=$?
  set -e
  [[ $code == 2 ]] || fail "softpack '$bad': exit $code (expected 2)"
  [[ -z $bad ]] && continue  # no command: the list, on stderr
  [[ $(wc -l < "$tmp/err") == 1 ]] && grep -q "is not a command of softpack; see softpack --help" "$tmp/err" ||
    fail "softpack '$bad': $(cat "$tmp/err")"
done
ln -s "$bin/softpack" "$tmp/softpack-bogus"
set +e; "$tmp/softpack-bogus" 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 ]] && grep -q "'softpack-bogus' is not a command" "$tmp/err" || fail "a link of another name: exit $code, $(cat "$tmp/err")"
echo "ok: a name that is no command: one line, exit 2"

# SOFTPACK_THREADS (engine/core/parallel.hpp) is read before a command runs: a bad value is one
# line and exit 2, even for a scene too small to be cut into blocks.
for bad in 0 zero 2x 100000; do
  set +e; SOFTPACK_THREADS=$bad "$bin/softpack-run" --scene "$source_dir/experiments/scenes/sphere-on-wall.yaml" > /dev/null 2> "$tmp/err"
  code=$?; set -e
  [[ $code == 2 ]] && [[ $(wc -l < "$tmp/err") == 1 ]] && grep -q "SOFTPACK_THREADS = '$bad' is not allowed" "$tmp/err" ||
    fail "SOFTPACK_THREADS=$bad: exit $code, $(cat "$tmp/err")"
done
echo "ok: a bad SOFTPACK_THREADS: one line, exit 2"

# The threads a run used (provenance.threads): as asked (--threads, SOFTPACK_THREADS); by default
# the cores the process may use, one per kSpheresPerThread (8000) spheres at most, and one under
# a parallel make (MAKEFLAGS with -jN, N > 1). A cloud of 16 000 free spheres, one step.
python3 - "$tmp/cloud.yaml" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("materials:\n  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}\neffects:\n  normal: hertz\nparticles:\n")
    for k in range(16000):
        f.write(f"  - {{x: [{(k % 40) * 3e-3}, {(k // 40 % 20) * 3e-3}, {(k // 800) * 3e-3}], r: 1.0e-3, material: grain}}\n")
    f.write("integration: {safety: 0.2, tangential_history: standard}\nneighbor: {skin: 0.2, level_ratio: 2.0}\nrun: {duration: 1.0e-9}\n")
PY
threads_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["provenance"]["threads"])' "$1"; }
cores=$(nproc)
expect_default=$(( cores < 2 ? cores : 2 ))
run_cloud() { "$bin/softpack-run" --scene "$tmp/cloud.yaml" --out "$tmp/cloud.json" --quiet "$@" || fail "softpack-run on the cloud: exit $?"; }
env -u SOFTPACK_THREADS -u MAKEFLAGS -u OMP_NUM_THREADS "$bin/softpack-run" --scene "$tmp/cloud.yaml" --out "$tmp/cloud.json" --quiet || fail "the cloud, by default"
[[ $(threads_of "$tmp/cloud.json") == "$expect_default" ]] || fail "16 000 spheres on $cores cores, by default: $(threads_of "$tmp/cloud.json") threads, not $expect_default"
env -u SOFTPACK_THREADS -u OMP_NUM_THREADS MAKEFLAGS=" -j2 --jobserver-auth=3,4" "$bin/softpack-run" --scene "$tmp/cloud.yaml" --out "$tmp/cloud.json" --quiet ||
  fail "the cloud under make -j2"
[[ $(threads_of "$tmp/cloud.json") == 1 ]] || fail "under make -j2: $(threads_of "$tmp/cloud.json") threads, not 1"
env -u SOFTPACK_THREADS -u MAKEFLAGS "$bin/softpack-run" --scene "$source_dir/experiments/scenes/sphere-on-wall.yaml" --out "$tmp/one.json" --quiet ||
  fail "one sphere, by default"
[[ $(threads_of "$tmp/one.json") == 1 ]] || fail "one sphere, by default: $(threads_of "$tmp/one.json") threads, not 1"
SOFTPACK_THREADS=3 run_cloud
[[ $(threads_of "$tmp/cloud.json") == 3 ]] || fail "SOFTPACK_THREADS=3: $(threads_of "$tmp/cloud.json") threads"
MAKEFLAGS=" -j2" run_cloud --threads 2
[[ $(threads_of "$tmp/cloud.json") == 2 ]] || fail "--threads 2 under make -j2: $(threads_of "$tmp/cloud.json") threads"
echo "ok: the threads of a run: as asked, else the cores (one per 8000 spheres, one under make -j)"
