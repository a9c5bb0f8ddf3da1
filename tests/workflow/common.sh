# Sourced by the workflow tests (tests/workflow/test_*.sh BUILD_DIR SOURCE_DIR ...): $build and
# $source from the arguments, a scratch folder $work removed on exit, fail and pass, and
# copy_tree DEST: the source tree as git sees it (tracked and untracked, not ignored files).
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "ok: $*"; }
copy_tree() {
  mkdir -p "$1"
  (cd "$source" && git ls-files -z --cached --others --exclude-standard | xargs -0 -I{} sh -c 'test -e "{}" && echo "{}"' |
     tar -cf - -T -) | tar -xf - -C "$1"
}
