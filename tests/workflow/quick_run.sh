#!/usr/bin/env bash
# The ctest fixture quick_run (tests/CMakeLists.txt): the quick profile's whole chain computed
# once per suite, for the tests that only read a finished run (readers, the Slurm run's
# reference, the kill rounds' reference, the reruns after an edit, the archive). In a copy of the
# source tree, BUILD_DIR/test-fixtures/quick/tree:
#   make -j2 PROFILE=quick FROM_SCRATCH=1 tables, then figures (DATA=data)
# and, when both succeed, BUILD_DIR/test-fixtures/quick/done holding the milliseconds `tables`
# took. The tests copy the tree before they change anything in it (quick_fixture_copy,
# tests/workflow/common.sh).
#
#   quick_run.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.sh"
fixture=$build/test-fixtures/quick
rm -rf "$fixture"
copy_tree "$fixture/tree"
cd "$fixture/tree"
export MAKEFLAGS=
mk() { make --no-print-directory PROFILE=quick BUILD="$build" DATA=data TOOLS= "$@"; }
start=$(date +%s%N)
mk -j2 FROM_SCRATCH=1 tables > "$fixture/tables.log" 2>&1 || { cat "$fixture/tables.log"; fail "make -j2 tables (quick profile)"; }
tables_ms=$(( ($(date +%s%N) - start) / 1000000 ))
mk -j2 figures > "$fixture/figures.log" 2>&1 || { cat "$fixture/figures.log"; fail "make -j2 figures (quick profile)"; }
echo "$tables_ms" > "$fixture/done"
pass "the quick profile's tables in $tables_ms ms, then its figures, in $fixture/tree"
