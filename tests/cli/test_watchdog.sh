#!/usr/bin/env bash
# The watchdog (engine/sim/watchdog.hpp) from the command line: a run that goes wrong stops with
# "softpack-<name>: numerical error: <diagnostic>", exit code 3, and no output file; the
# profile's `watchdog` section sets the thresholds without touching the recorded configuration.
source "$(dirname "$0")/common.sh"
bin=$1
root=$2

# run NAME EXPECTED_CODE CMD...: runs CMD with stderr to $tmp/NAME.err and checks its exit code.
run() {
  local name=$1 expected=$2 code=0
  shift 2
  "$@" > "$tmp/$name.out" 2> "$tmp/$name.err" || code=$?
  [[ $code -eq $expected ]] || fail "$name: exit code $code, expected $expected; stderr: $(cat "$tmp/$name.err")"
}
has() { grep -qF -- "$2" "$tmp/$1.err" || fail "$1: '$2' not in: $(cat "$tmp/$1.err")"; }

scene_head='materials:
  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}
effects: {normal: hertz}'

# 1. Two spheres placed with 80 % overlap, above the scene's limit of half a radius.
cat > "$tmp/overlap.yaml" << EOF
$scene_head
particles:
  - {x: [0.0, 0.0, 0.0], r: 1.0e-3, material: grain}
  - {x: [1.2e-3, 0.0, 0.0], r: 1.0e-3, material: grain}
integration: {safety: 0.2, tangential_history: synchronized}
neighbor: {skin: 0.2, level_ratio: 2.0}
watchdog: {max_overlap_fraction: 0.5}
run: {duration: 0.01}
EOF
run overlap 3 "$bin/softpack-run" --scene "$tmp/overlap.yaml" --out "$tmp/overlap.json" --quiet
has overlap "softpack-run: numerical error: step 0, t = 0 s: spheres 0 and 1 (r = 0.001 m and 0.001 m) overlap by 0.0008 m, 0.8 of the smaller radius, above watchdog.max_overlap_fraction = 0.5; dt = 7.74e-05 s, stable limit 0.000387 s (Rayleigh time of sphere 0)"
[[ $(wc -l < "$tmp/overlap.err") -eq 1 ]] || fail "overlap: more than one line on stderr"
[[ ! -e $tmp/overlap.json ]] || fail "overlap: an output file was written"

# 2. A blow-up in the middle of a run: a sphere squeezed between two planes at dt = t_R, where
#    the Hertz stiffness of the overlaps makes the integration unstable.
cat > "$tmp/blowup.yaml" << EOF
$scene_head
particles:
  - {x: [0.0, 0.0, 0.65e-3], r: 1.0e-3, material: grain}
planes:
  - {name: floor, point: [0.0, 0.0, 0.0], normal: [0.0, 0.0, 1.0], material: grain}
  - {name: ceiling, point: [0.0, 0.0, 1.4e-3], normal: [0.0, 0.0, -1.0], material: grain}
integration: {safety: 1.0, tangential_history: synchronized}
neighbor: {skin: 0.2, level_ratio: 2.0}
watchdog: {check_interval: 1}
run: {duration: 0.1}
EOF
run blowup 3 "$bin/softpack-run" --scene "$tmp/blowup.yaml" --out "$tmp/blowup.json" --quiet
has blowup "softpack-run: numerical error: step "
has blowup "energy blow-up: kinetic + normal elastic energy"
has blowup "most energetic sphere 0"
has blowup "; dt = 0.000387 s, stable limit 0.000387 s (Rayleigh time of sphere 0)"
[[ ! -e $tmp/blowup.json ]] || fail "blowup: an output file was written"
# The same scene with the default interval: whatever is seen first, it stops with exit 3.
sed -i '/^watchdog:/d' "$tmp/blowup.yaml"
run blowup_default 3 "$bin/softpack-run" --scene "$tmp/blowup.yaml" --out "$tmp/blowup.json" --quiet
has blowup_default "softpack-run: numerical error: step "
[[ ! -e $tmp/blowup.json ]] || fail "blowup (default interval): an output file was written"

# 3. A sweep (the Hertz check: one solid sphere of radius Rs pressed on the wall) whose profile
#    allows 0.3 of a radius stops on the way to Delta_n = 0.4 and writes no results; the points
#    already done stay checkpointed, and with the limit raised the same sweep resumes from them.
sed 's/^watchdog: .*/watchdog: {max_overlap_fraction: 0.3}/' "$root/tests/data/sweep-profile.yaml" > "$tmp/profile.yaml"
grep -q '^watchdog: {max_overlap_fraction: 0.3}' "$tmp/profile.yaml" || fail "could not set the profile's watchdog"
sweep=(--config "$tmp/profile.yaml" --scene soft-solid --seed 1 --hertz-check --checkpoints "$tmp/points" --out "$tmp/normal.h5")
run sweep 3 "$bin/softpack-normal" "${sweep[@]}" --quiet
has sweep "softpack-normal: numerical error: soft-solid seed 1, normal point 3/5 (delta_n = 0.4): step "
has sweep "sphere 0 (r = 0.016 m) overlaps plane 'wall' by"
has sweep "of its radius, above watchdog.max_overlap_fraction = 0.3; dt = "
[[ ! -e $tmp/normal.h5 ]] || fail "sweep: the results file was written"
[[ -e $tmp/points/point-001.h5 && ! -e $tmp/points/point-002.h5 ]] || fail "sweep: checkpoints $(ls "$tmp/points")"
sed -i 's/^watchdog: .*/watchdog: {max_overlap_fraction: 1.0}/' "$tmp/profile.yaml"
run resumed 0 "$bin/softpack-normal" "${sweep[@]}"
[[ $(grep -c '(checkpoint)' "$tmp/resumed.err") -eq 2 ]] || fail "resumed: the checkpointed points were not reused: $(cat "$tmp/resumed.err")"
[[ -e $tmp/normal.h5 ]] || fail "resumed: no results file"
echo "ok"
