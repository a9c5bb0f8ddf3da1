# Sourced by the command-line tests (tests/cli/test_*.sh): a scratch folder $tmp removed on
# exit, fail MESSAGE, and expect_error for the bad-input cases.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_error MESSAGE OUTPUT COMMAND...: exit code 2, MESSAGE (a fixed string) on stderr, OUTPUT
# not created, and no temporary (*.tmp.*) left anywhere under $tmp.
expect_error() {
  local message=$1 output=$2
  shift 2
  set +e
  "$@" 2> "$tmp/err" > /dev/null
  local code=$?
  set -e
  [ "$code" -eq 2 ] || fail "exit code $code (expected 2) for: $*: $(cat "$tmp/err")"
  grep -qF -- "$message" "$tmp/err" || fail "expected '$message', got: $(cat "$tmp/err")"
  [ ! -e "$output" ] || fail "$output was written for bad input: $*"
  ! find "$tmp" -name '*.tmp.*' | grep -q . || fail "a temporary file was left behind: $*"
}
