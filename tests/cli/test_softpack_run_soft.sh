#!/usr/bin/env bash
# Soft-particles declared in a scene file (effects.soft_particles, particles[i].soft; docs/scene-
# format.md): softpack-run reads the law file the scene names, relative to the scene's folder,
# and a soft-particle held against a plane at overlap h = dn R loads it with the law file's
# Eq. 7, F = a dn^b + c. A soft-particle without effects.soft_particles, a law file that does
# not exist or is bad, an unknown grain_contact: one message naming the file, line, column and
# key, exit code 2, no output file.
source "$(dirname "$0")/common.sh"
exe=$1

# A law file of one soft-solid normal law at R0 = 0.016 m (pipeline/formats/law_file.hpp); delta
# null: the reader takes delta = (-c/a)^(1/b) (0.046 here, below the dn of this test).
a=2.5 b=1.8 c=-0.01 R=0.016 dn=0.3
mkdir -p "$tmp/scenes/laws"
law() {  # law A: the file's text with the law's a
  cat <<EOF
{"format": "softpack-laws", "version": 1,
 "reference_radius": {"value": $R, "unit": "m"},
 "scenes": {"soft-solid": {"normal": {
   "a": {"value": $1, "error": null, "unit": "N"}, "b": {"value": $b, "error": null, "unit": "1"},
   "c": {"value": $c, "error": null, "unit": "N"}, "delta": {"value": null, "error": null, "unit": "1"},
   "delta_n_range": [0.05, 0.5]}}}}
EOF
}
law $a > "$tmp/scenes/laws/soft.json"

# scene SOFT_PARTICLES [DN [SOFT]]: one soft-particle of radius R0 (its grains' mass) held at
# overlap h = DN R on the plane z = 0, for one step.
scene() {
  local z
  z=$(python3 -c "print(repr($R - ${2:-$dn} * $R))")
  cat <<EOF
materials:
  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}
effects:
  normal: hertz
$1
particles:
  - {x: [0.0, 0.0, $z], r: $R, material: grain, mass: 0.0072, soft: ${3:-true}}
planes:
  - {name: floor, point: [0.0, 0.0, 0.0], normal: [0.0, 0.0, 1.0], material: grain}
drivers:
  - {type: hold, group: all}
integration: {safety: 0.2, tangential_history: synchronized}
neighbor: {skin: 0.2, level_ratio: 2.0}
run: {duration: 1.0e-9}
EOF
}

# The plane carries Eq. 7 of the law file, to 1e-9; run from another folder: the law file's path
# is the scene's folder's.
scene "  soft_particles: {laws: laws/soft.json}" > "$tmp/scenes/soft.yaml"
(cd / && "$exe" --scene "$tmp/scenes/soft.yaml" --out "$tmp/soft.json" --quiet)
python3 - "$tmp/soft.json" "$a" "$b" "$c" "$dn" <<'EOF' || fail "the plane's force is not Eq. 7 of the law file"
import json, sys
report = json.load(open(sys.argv[1]))
a, b, c, dn = map(float, sys.argv[2:])
expected = a * dn**b + c  # Eq. 7 at R = R0
F = report["walls"]["floor"]["force"]
assert report["steps"] == 1, report["steps"]
assert F[0] == 0.0 and F[1] == 0.0, F
assert abs(-F[2] - expected) <= 1e-9 * expected, (F, expected)
print(f"plane force {-F[2]!r} N, Eq. 7 {expected!r} N")
EOF

# The rules' other choices run; beyond the law's measured range (dn 0.6 > 0.5) `report` runs on,
# `stop` stops the run (exit code 3, a numerical error, no output file).
scene "  soft_particles: {laws: laws/soft.json, grain_contact: reduced-radius, beyond_range: report}" 0.6 \
  > "$tmp/scenes/report.yaml"
"$exe" --scene "$tmp/scenes/report.yaml" --out "$tmp/report.json" --quiet
scene "  soft_particles: {laws: laws/soft.json, beyond_range: stop}" 0.6 > "$tmp/scenes/stop.yaml"
set +e
"$exe" --scene "$tmp/scenes/stop.yaml" --out "$tmp/stop.json" --quiet 2> "$tmp/err"
code=$?
set -e
[ "$code" -eq 3 ] || fail "beyond_range: stop: exit code $code (expected 3): $(cat "$tmp/err")"
grep -qF "beyond_range is 'stop'" "$tmp/err" || fail "beyond_range: stop: $(cat "$tmp/err")"
[ ! -e "$tmp/stop.json" ] || fail "beyond_range: stop wrote its report"

# Refusals: the file, line and column of the key, the value, what is allowed.
run() { "$exe" --scene "$1" --out "$tmp/bad.json" --quiet; }
scene "" > "$tmp/scenes/bad.yaml"
expect_error "bad.yaml:7:90: particles[0].soft: a soft-particle needs effects.soft_particles" "$tmp/bad.json" \
  run "$tmp/scenes/bad.yaml"
scene "  soft_particles: {laws: laws/soft.json}" "$dn" false > "$tmp/scenes/bad.yaml"
expect_error "bad.yaml:5:19: effects.soft_particles: declared, but no sphere is soft" "$tmp/bad.json" run "$tmp/scenes/bad.yaml"
scene "  soft_particles: {laws: laws/missing.json}" > "$tmp/scenes/bad.yaml"
expect_error "bad.yaml:5:26: effects.soft_particles.laws: '$tmp/scenes/laws/missing.json' does not exist; allowed: a law file" \
  "$tmp/bad.json" run "$tmp/scenes/bad.yaml"
law '"two"' > "$tmp/scenes/laws/bad.json"
scene "  soft_particles: {laws: laws/bad.json}" > "$tmp/scenes/bad.yaml"
expect_error "bad.yaml:5:26: effects.soft_particles.laws: $tmp/scenes/laws/bad.json: scenes.soft-solid.normal.a.value: 'two' is not allowed; allowed: a finite number" \
  "$tmp/bad.json" run "$tmp/scenes/bad.yaml"
scene "  soft_particles: {laws: laws/soft.json, grain_contact: bogus}" > "$tmp/scenes/bad.yaml"
expect_error "bad.yaml:5:57: effects.soft_particles.grain_contact: 'bogus' is not allowed; allowed: wall, reduced-radius" \
  "$tmp/bad.json" run "$tmp/scenes/bad.yaml"
scene "  soft_particles: {laws: laws/soft.json, beyond_range: never}" > "$tmp/scenes/bad.yaml"
expect_error "effects.soft_particles.beyond_range: 'never' is not allowed; allowed: report, stop" "$tmp/bad.json" \
  run "$tmp/scenes/bad.yaml"
scene "  soft_particles: {grain_contact: wall}" > "$tmp/scenes/bad.yaml"
expect_error "effects.soft_particles: missing required key 'laws'" "$tmp/bad.json" run "$tmp/scenes/bad.yaml"
echo "ok"
