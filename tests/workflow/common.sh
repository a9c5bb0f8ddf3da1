# Sourced by the workflow tests (tests/workflow/test_*.sh BUILD_DIR SOURCE_DIR ...): $build and
# $source from the arguments, a scratch folder $work removed on exit, fail and pass,
# copy_tree DEST: the source tree as git sees it (tracked and untracked, not ignored files),
# quick_fixture_copy DEST: the quick profile's finished run of the fixture quick_run, and
# same_results A B: two data folders hold the same results.
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "ok: $*"; }
copy_tree() {
  mkdir -p "$1"
  (cd "$source" && git ls-files -z --cached --others --exclude-standard |
     while IFS= read -r -d '' f; do if [[ -e $f ]]; then printf '%s\0' "$f"; fi; done |
     tar --null -cf - -T -) | tar -xf - -C "$1"
}

# The fixture quick_run (tests/workflow/quick_run.sh): a copy of the source tree in which the
# quick profile's tables and figures were made from scratch (make -j2, DATA=data).
quick_fixture=$build/test-fixtures/quick
# quick_fixture_copy DEST: a copy of that tree, timestamps kept (make sees it as up to date), for
# a test that changes it; sets $quick_tables_ms, what its `make tables` took.
quick_fixture_copy() {
  [[ -f $quick_fixture/done ]] || fail "no finished quick run in $quick_fixture: the fixture quick_run (workflow.quick_run) failed or did not run"
  quick_tables_ms=$(cat "$quick_fixture/done")
  mkdir -p "$(dirname "$1")"
  cp -a "$quick_fixture/tree" "$1"
}

# same_results A B: the results of data folders A and B (A/quick, B/quick) agree: every HDF5
# dataset identical (h5diff, exact) except the wall-clock timings (/seconds, /timing,
# /provenance, which record time spent and code version), and the text outputs (.dat, .gp, .md)
# identical except their provenance comments; checkpoints aside. Files of A only are compared.
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
