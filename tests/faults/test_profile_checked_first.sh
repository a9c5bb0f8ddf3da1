#!/usr/bin/env bash
# The whole profile is checked before anything runs (issue 28, class 12; docs/architecture.md):
# softpack-config, which make asks first, reads every section with every stage's reader, so that
# a profile it accepts is accepted by every stage, and one it refuses is refused there, exit 2,
# placed at its file and line. Each run draws new instances (FAULT_SEED=N replays) from a
# catalogue of edits of the small sweep profile — a list emptied or with an item twice, a value
# out of its range, a word no reader knows, a grid point outside the normal grid — and checks
# either: softpack-config refuses (exit 2, "FILE:LINE:COL: key"), or softpack-pack,
# softpack-normal and softpack-tangential (each stopped after its first point) accept the
# profile too (the `fit` section, softpack-fit's, is read by softpack-config with its reader).
#
#   test_profile_checked_first.sh BIN_DIR SOURCE_DIR   (FAULT_SEED=N replays)
bin=$(cd "$1" && pwd) root=$2
source "$(dirname "$0")/common.sh"

# The catalogue: "what|sed expression" (on tests/data/sweep-profile.yaml).
edits=(
  "seeds twice|s/^seeds: \[1, 2\]/seeds: [1, 1]/"
  "no seeds|s/^seeds: \[1, 2\]/seeds: []/"
  "E <= 0|s/E: 5.0e5/E: -5.0e5/"
  "nu beyond 0.5|s/nu: 0.3,/nu: 0.7,/"
  "mu < 0|s/mu: 0.3,/mu: -0.1,/"
  "density 0|s/density: 250000.0/density: 0/"
  "Rs 0|s/Rs: 0.016/Rs: 0/"
  "polydispersity < 1|s/polydispersity: 3/polydispersity: 0.5/"
  "trials not an integer|s/trials: 3000/trials: 1.5/"
  "an unknown normal law|s/normal: hertz/normal: hooke-ish/"
  "an unknown friction|s/friction: tsuji/friction: sticky/"
  "restitution > 1|s/restitution: 0.3/restitution: 1.5/"
  "safety 0|s/safety: 0.2/safety: 0/"
  "skin < 0|s/skin: 0.5/skin: -1/"
  "an unknown contact radius|s/contact_radius: concave/contact_radius: round/"
  "an unknown relaxation protocol|s/protocol: converged/protocol: patient/"
  "a scene twice|s/scenes: \[soft-solid, soft-soft\]/scenes: [soft-soft, soft-soft]/"
  "no scene|s/scenes: \[soft-solid, soft-soft\]/scenes: []/"
  "an unknown scene|s/scenes: \[soft-solid, soft-soft\]/scenes: [soft-solid, soft-rigid]/"
  "normal grid decreasing|s/delta_n: \[0.0, 0.2, 0.4, 0.5, 0.6\]/delta_n: [0.0, 0.4, 0.2, 0.5, 0.6]/"
  "normal grid point twice|s/delta_n: \[0.0, 0.2, 0.4, 0.5, 0.6\]/delta_n: [0.0, 0.2, 0.2, 0.5, 0.6]/"
  "normal grid beyond 1|s/delta_n: \[0.0, 0.2, 0.4, 0.5, 0.6\]/delta_n: [0.0, 0.2, 0.4, 0.5, 1.5]/"
  "speed 0|s/speed: 0.02/speed: 0/"
  "an unknown path|s/path: incremental/path: sideways/"
  "tangential point outside the normal grid|s/delta_n: \[0.5, 0.6\]/delta_n: [0.55, 0.6]/"
  "no angle|s/alpha_deg: \[-0.5, 0.0, 0.5\]/alpha_deg: []/"
  "an angle twice|s/alpha_deg: \[-0.5, 0.0, 0.5\]/alpha_deg: [0.5, 0.5]/"
  "rate 0|s/rate: 0.1/rate: 0/"
  "an unknown after_rotation|s/after_rotation: release/after_rotation: spin/"
  "watchdog overlap < 0|s/max_overlap_fraction: 2.0/max_overlap_fraction: -1/"
  "an unknown section|\$a\\
surprise: {a: 1}"
  "a key twice in a section|s/^  trials: 3000/  trials: 3000\n  trials: 4000/"
)

accepted=0 refused=0
for round in $(seq 8); do
  edit=${edits[$(random_below ${#edits[@]})]}
  what=${edit%%|*}
  sed "${edit#*|}" "$profile" > "$tmp/p.yaml"
  cmp -s "$profile" "$tmp/p.yaml" && fail "'$what': the edit changed nothing"
  set +e; "$bin/softpack-config" "$tmp/p.yaml" stamp average > /dev/null 2> "$tmp/err"; code=$?; set -e
  if [[ $code == 2 ]]; then
    grep -qE "p\.yaml(:[0-9]+:[0-9]+)?: " "$tmp/err" || fail "'$what': refused without naming the file: $(cat "$tmp/err")"
    refused=$((refused + 1))
    echo "ok: round $round: '$what' refused by softpack-config: $(cut -c1-160 "$tmp/err")"
    continue
  fi
  [[ $code == 0 ]] || fail "'$what': softpack-config exit $code: $(cat "$tmp/err")"
  # Accepted: every stage must accept it too (a refusal there is one softpack-config missed).
  stage() {
    set +e; "$@" > /dev/null 2> "$tmp/err"; local c=$?; set -e
    [[ $c != 2 ]] || fail "'$what': accepted by softpack-config, refused by ${1##*/}: $(cat "$tmp/err")"
  }
  rm -rf "$tmp/run"
  stage "$bin/softpack-pack" --config "$tmp/p.yaml" --seed 1 --out "$tmp/run/p1.h5" --quiet
  stage "$bin/softpack-normal" --config "$tmp/p.yaml" --scene soft-solid --seed 1 --packing "$tmp/run/p1.h5" \
    --checkpoints "$tmp/run/ck" --out "$tmp/run/n.h5" --quiet --stop-after 1
  stage "$bin/softpack-tangential" --config "$tmp/p.yaml" --scene soft-solid --seed 1 --packing "$tmp/run/p1.h5" \
    --normal-checkpoints "$tmp/run/ck" --checkpoints "$tmp/run/tk" --out "$tmp/run/t.h5" --quiet --stop-after 1
  accepted=$((accepted + 1))
  echo "ok: round $round: '$what' accepted by softpack-config and by every stage"
done
echo "ok: $refused edits refused before anything ran, $accepted accepted by softpack-config and every stage"
