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
