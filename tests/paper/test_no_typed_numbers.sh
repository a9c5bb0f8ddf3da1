#!/usr/bin/env bash
# paper.no_typed_numbers (issue 29): paper/paper.tex states no result outside a generated macro
# (tests/paper/check_numbers.py), and the check can fail: a copy with a typed result (a number that
# is neither a macro, a reference, an input of the profile nor allowed) is refused, naming it.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
python3 "$root/tests/paper/check_numbers.py" "$root/paper/paper.tex"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/\\vSolidFThree/2.72 \\pm 0.03/' "$root/paper/paper.tex" > "$tmp/paper.tex"
cmp -s "$tmp/paper.tex" "$root/paper/paper.tex" && { echo "FAIL: the injection did not change paper.tex" >&2; exit 1; }
if python3 "$root/tests/paper/check_numbers.py" "$tmp/paper.tex" 2> "$tmp/err"; then
  echo "FAIL: a typed result (2.72 ± 0.03 N) passed the check" >&2; exit 1
fi
grep -q "'2.72'" "$tmp/err" && grep -q "'0.03'" "$tmp/err" ||
  { echo "FAIL: the refusal does not name the typed numbers: $(cat "$tmp/err")" >&2; exit 1; }
echo "ok: a typed result in the report is refused"
