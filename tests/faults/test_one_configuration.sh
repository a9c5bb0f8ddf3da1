#!/usr/bin/env bash
# One configuration per result (issue 28, class 1; docs/measurement.md): a result carries the
# stamp of the configuration it was computed with, and every consumer refuses inputs whose stamps
# differ from each other or from the profile's now. Each run draws new instances (FAULT_SEED=N
# replays): a key of the profile that a stage reads and a new value for it; the edited profile P'
# stands for an edit made during a run.
#   1. a stage given the stamp make planned it with (--stamp) refuses to run under P': exit 2,
#      nothing written;
#   2. results of one seed computed under P' and of another under P: softpack-average refuses to
#      average them (without --config: with each other; with --config P: with the profile), and
#      the message names the edited key; averages, fits and tables made under P are refused under
#      P' by the next consumer (softpack-fit --config, softpack-table --config);
#   3. make's up-to-date check: a result computed under P' in a data folder, P restored (the edit
#      reverted before the run ended), is out of date for make (make -q), which computes that
#      result again and nothing else; softpack-config PROFILE stale names exactly it.
#
#   test_one_configuration.sh BUILD_DIR SOURCE_DIR   (FAULT_SEED=N replays)
build=$(cd "$1" && pwd) root=$(cd "$2" && pwd)
bin=$build/bin
source "$(dirname "$0")/common.sh"
copy_samples "$tmp/s"
s=$tmp/s

# edit PROFILE OUT STAGE: OUT is PROFILE with one key of a section STAGE reads set to a new value
# (drawn; the key is echoed). The keys of the normal stage are also the tangential's and the
# average's (profile/profile.cpp, stage_sections).
edit() {
  local in=$1 out=$2 stage=$3 pick
  local -a normal=("E: 5.0e5|E: $(( $(random_below 40) + 55 )).0e4" "nu: 0.3,|nu: 0.$(( $(random_below 9) + 21 )),"
    "speed: 0.02|speed: 0.0$(( $(random_below 5) + 1 ))5" "restitution: 0.3|restitution: 0.$(( $(random_below 5) + 4 ))"
    "force_tolerance: 1.0e-3|force_tolerance: $(( $(random_below 8) + 2 )).0e-3")
  local -a tangential=("rate: 0.1|rate: 0.$(( $(random_below 8) + 2 ))" "after_rotation: release|after_rotation: hold")
  if [[ $stage == normal ]]; then pick=${normal[$(random_below ${#normal[@]})]}; else pick=${tangential[$(random_below ${#tangential[@]})]}; fi
  grep -qF -- "${pick%%|*}" "$in" || fail "the profile has no '${pick%%|*}'"
  sed "s/${pick%%|*}/${pick#*|}/" "$in" > "$out"
  echo "${pick#*|}"
}

# --- 1 and 2: the commands ---------------------------------------------------------------------------
for round in 1 2; do
  stage=$([[ $(random_below 2) == 0 ]] && echo normal || echo tangential)
  edited=$(edit "$profile" "$tmp/edited.yaml" $stage)
  key=${edited%%:*}
  echo "round $round: the $stage stage's '$edited' (was: $(grep -oE "$key: [^,}]*" "$profile" | head -1))"
  planned=$("$bin/softpack-config" "$profile" stamp $stage)
  if [[ $stage == normal ]]; then
    expect_error "changed since make planned this run" "$tmp/x.h5" "$bin/softpack-normal" --config "$tmp/edited.yaml" \
      --stamp "$planned" --scene soft-solid --seed 1 --packing "$s/p1.h5" --checkpoints "$tmp/ckx" --out "$tmp/x.h5"
  else
    expect_error "changed since make planned this run" "$tmp/x.h5" "$bin/softpack-tangential" --config "$tmp/edited.yaml" \
      --stamp "$planned" --scene soft-solid --seed 1 --packing "$s/p1.h5" --normal-checkpoints "$tmp/ckx" \
      --checkpoints "$tmp/tkx" --out "$tmp/x.h5"
  fi
  [[ ! -e $tmp/ckx && ! -e $tmp/tkx ]] || fail "a stage refused for its planned stamp wrote checkpoints"
  rm -rf "$tmp/ckx" "$tmp/tkx"

  # Seed 2 again under the edited profile (its normal states reused where the edit leaves them).
  rm -rf "$tmp/mixed" && mkdir -p "$tmp/mixed" && cp -r "$s/ck2" "$tmp/mixed/ck2"
  if [[ $stage == normal ]]; then
    "$bin/softpack-normal" --config "$tmp/edited.yaml" --scene soft-solid --seed 2 --packing "$s/p2.h5" \
      --checkpoints "$tmp/mixed/ck2" --out "$tmp/mixed/n2.h5" --quiet
    mixed=(--normal "$s/n1.h5" "$tmp/mixed/n2.h5" --tangential "$s/t1.h5" "$s/t2.h5")
  else
    "$bin/softpack-tangential" --config "$tmp/edited.yaml" --scene soft-solid --seed 2 --packing "$s/p2.h5" \
      --normal-checkpoints "$tmp/mixed/ck2" --checkpoints "$tmp/mixed/tk2" --out "$tmp/mixed/t2.h5" --quiet
    mixed=(--normal "$s/n1.h5" "$s/n2.h5" --tangential "$s/t1.h5" "$tmp/mixed/t2.h5")
  fi
  avg=("$bin/softpack-average" --scene soft-solid --profile sweep-test)
  expect_error "were computed with different configurations" "$tmp/a/soft-solid.h5" "${avg[@]}" "${mixed[@]}" --out-dir "$tmp/a"
  grep -qF "$edited" "$tmp/err" || fail "the message does not name the edited key '$edited': $(cat "$tmp/err")"
  expect_error "were computed with different configurations" "$tmp/a/soft-solid.h5" "${avg[@]}" --config "$profile" \
    "${mixed[@]}" --out-dir "$tmp/a"
  expect_error "than $tmp/edited.yaml holds now" "$tmp/a/soft-solid.h5" "${avg[@]}" --config "$tmp/edited.yaml" \
    --normal "$s/n1.h5" "$s/n2.h5" --tangential "$s/t1.h5" "$s/t2.h5" --out-dir "$tmp/a"
  grep -qF "$edited" "$tmp/err" || fail "the message does not name the edited key '$edited': $(cat "$tmp/err")"

  # The consumers after the average: an average and a fit of P, read under P'.
  "${avg[@]}" --config "$profile" --normal "$s/n1.h5" "$s/n2.h5" --tangential "$s/t1.h5" "$s/t2.h5" --out-dir "$tmp/a" 2> /dev/null
  expect_error "made with another configuration of the average stage" "$tmp/fit.json" "$bin/softpack-fit" \
    --average "$tmp/a/soft-solid.h5" --config "$tmp/edited.yaml" --out "$tmp/fit.json" --quiet
  "$bin/softpack-fit" --average "$tmp/a/soft-solid.h5" --config "$profile" --out "$tmp/a/fit.json" --quiet
  expect_error "made with another configuration of the average stage" "$tmp/tables/table1.md" "$bin/softpack-table" \
    --fits "$tmp/a/fit.json" --config "$tmp/edited.yaml" --published "$root/experiments/published.yaml" --out-dir "$tmp/tables"
  rm -rf "$tmp/a"
done
echo "ok: a stage refuses a changed profile; average, fit and table refuse results of another configuration"

# --- 3. make's up-to-date check ------------------------------------------------------------------------
export MAKEFLAGS=
p=$tmp/profile.yaml
sed 's/scenes: \[soft-solid, soft-soft\]/scenes: [soft-solid]/' "$profile" > "$p"
mk() { make -C "$root" --no-print-directory BUILD="$build" TOOLS= PROFILE=sweep-test PROFILE_FILE="$p" DATA="$tmp/data" "$@"; }
mk normal > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; fail "make normal"; }
seed=$(( $(random_below 2) + 1 ))
result=$tmp/data/sweep-test/normal/soft-solid-seed-$seed.h5
cp "$p" "$tmp/original.yaml"
edited=$(edit "$tmp/original.yaml" "$p" normal)
# What an edit during the run leaves when the stage reads the profile after it: the result made
# under the edited profile (with the checkpoints of the original, which it does not reuse).
"$bin/softpack-normal" --config "$p" --scene soft-solid --seed $seed --packing "$tmp/data/sweep-test/packings/seed-$seed.h5" \
  --checkpoints "$tmp/data/sweep-test/checkpoints/normal/soft-solid/seed-$seed" --out "$result" --quiet
cp "$tmp/original.yaml" "$p"  # reverted
stale=$("$bin/softpack-config" "$p" stale "$tmp"/data/sweep-test/normal/*.h5 "$tmp"/data/sweep-test/packings/*.h5)
[[ $stale == "$result" ]] || fail "softpack-config stale names '$stale', not $result (edited: $edited)"
if mk -q normal; then fail "make -q takes $result, made with '$edited', as up to date"; fi
mk normal > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; fail "make normal after the revert"; }
[[ $(grep -c '^normal: ' "$tmp/make.log") == 1 ]] && grep -q "^normal: sweep-test soft-solid seed $seed " "$tmp/make.log" \
  || { cat "$tmp/make.log"; fail "make did not compute exactly $result again"; }
[[ -z $("$bin/softpack-config" "$p" stale "$result") ]] || fail "$result is still of another configuration"
mk -q normal || fail "make -q: not up to date after the rerun"
echo "ok: a result of the edited profile, the edit reverted, is out of date for make, which computes it again (and only it)"
