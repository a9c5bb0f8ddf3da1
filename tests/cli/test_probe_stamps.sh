#!/usr/bin/env bash
# The many-body probe's files are made again by what decided them, not by their times
# (workflow/coarse.mk, probe_stale): on a copy of the committed runs, make many-body-probe has
# nothing to do — even with every file older than the plan, as in a fresh clone — and makes again
# exactly the file whose first line holds another stamp, none, a stamp that is a prefix of its
# group's, or that is missing.
#
#   test_probe_stamps.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
build=$(cd "$1" && pwd) root=$(cd "$2" && pwd)
cd "$root"
export MAKEFLAGS=
cp -r data/many-body/probe "$tmp/probe"
# The release is in every group's stamp: the committed runs are those of the release their files
# record (all one release), which is this build's until a release changes result bits and they
# are made again. Under a later release every file is planned; under theirs, what follows.
current=$(awk '/^project/ { print $3; exit }' CMakeLists.txt)
releases=$(head -2 -q "$tmp"/probe/*/*.dat | grep -o "multi-contact: .*, [0-9]*\.[0-9]*\.[0-9]* (" | grep -o "[0-9]*\.[0-9]*\.[0-9]* ($" | tr -d ' (' | sort -u)
[ "$(echo "$releases" | wc -l)" = 1 ] || fail "the committed runs are of several releases: $(echo $releases)"
files=$(find "$tmp/probe" -name '*.dat' | sort)
# TOOLS= : the tools are built (ctest runs after the build); nothing recompiles under the test.
planned_in() { make --no-print-directory -n BUILD="$build" TOOLS= VERSION="$1" PROBE_DIR="$tmp/probe" many-body-probe 2>&1 | grep -o "[^ ]*\.dat" | sort -u || true; }
if [ "$releases" != "$current" ]; then
  # The gap, asserted and said: until make many-body-probe remakes them, a fresh clone's
  # make many-body-report runs every probe again.
  [ "$(planned_in "$current")" = "$files" ] || fail "under release $current the runs of release $releases are not all made again"
  echo "note: the committed probe runs are of release $releases: under $current make many-body-probe makes all $(echo "$files" | wc -l) again" >&2
fi
planned() { planned_in "$releases"; }
[ -z "$(planned)" ] || fail "the committed runs are made again: $(planned | head -3)"
find "$tmp/probe" -name '*.dat' -exec touch -d '2001-01-01' {} +
[ -z "$(planned)" ] || fail "files older than the plan are made again: $(planned | head -3)"
file=$tmp/probe/half/shear-501.dat
cp "$file" "$tmp/kept.dat"
stamp=$(head -1 "$tmp/kept.dat")
[[ $stamp =~ ^#\ stamp\ [0-9a-f]{16}$ ]] || fail "the committed file's first line is '$stamp', not a stamp"
for first in "# stamp 0000000000000000" "${stamp%?}" "# softpack-coarse multi-contact" ""; do
  { echo "$first"; tail -n +2 "$tmp/kept.dat"; } > "$file"
  [ "$(planned)" = "$file" ] || fail "with the first line '$first' make plans '$(planned)', not $file alone"
done
rm "$file"
[ "$(planned)" = "$file" ] || fail "a missing file: make plans '$(planned)'"
cp "$tmp/kept.dat" "$file"
[ -z "$(planned)" ] || fail "the file put back is made again"
echo "ok"
