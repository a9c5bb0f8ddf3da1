#!/usr/bin/env bash
# docs.readme_numbers (issue 31): every number in README.md is a claim recomputed from the
# committed results, a reference, an input of experiments/ or allowed with its source
# (tests/docs/check_readme_numbers.py); and the check can fail: a claim with a stale value and a
# typed timing are refused, each named.
#
#   test_readme_numbers.sh BIN_DIR
set -euo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
python3 "$root/tests/docs/check_readme_numbers.py" "$bin" "$root/README.md"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$root/README.md" "$tmp/README.md" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
t = re.sub(r"\((\d+\.\d) CPU-minutes", lambda m: f"({float(m.group(1)) + 0.3:.1f} CPU-minutes", s, count=1)
assert t != s, "no CPU-minutes claim to make stale"
open(sys.argv[2], "w").write(t + "\nA packing of 1647 grains takes 26.3 s.\n")
PY
if python3 "$root/tests/docs/check_readme_numbers.py" "$bin" "$tmp/README.md" 2> "$tmp/err"; then
  echo "FAIL: a stale claim and a typed timing passed the check" >&2; exit 1
fi
grep -q "is not stated with today's value" "$tmp/err" && grep -q "'1647'" "$tmp/err" && grep -q "'26.3'" "$tmp/err" ||
  { echo "FAIL: the refusal does not name the stale claim and the typed numbers: $(cat "$tmp/err")" >&2; exit 1; }
echo "ok: a stale claim and a typed number in the README are refused"
