#!/usr/bin/env bash
# softpack-run answers --help, runs an example scene, and rejects bad input with one clear
# message, exit code 2 and no output file.
source "$(dirname "$0")/common.sh"
exe=$1
root=$2

"$exe" --help | grep -q -- "--scene" || fail "--help does not list --scene"

"$exe" --scene "$root/experiments/scenes/sphere-on-wall.yaml" --out "$tmp/report.json" --quiet
grep -q '"code_version"' "$tmp/report.json" || fail "report has no provenance"

# An unknown key: message with file, line, key and a suggestion; exit 2; no output file.
sed 's/friction: tsuji/frcition: tsuji/' "$root/experiments/scenes/sphere-on-wall.yaml" > "$tmp/bad.yaml"
set +e
"$exe" --scene "$tmp/bad.yaml" --out "$tmp/bad.json" --quiet 2> "$tmp/err"
code=$?
set -e
[ "$code" -eq 2 ] || fail "exit code $code, expected 2"
grep -q "bad.yaml:.*effects.frcition: unknown key; did you mean 'friction'?" "$tmp/err" || fail "message: $(cat "$tmp/err")"
[ ! -e "$tmp/bad.json" ] || fail "an output file was written for bad input"
echo "ok"
