#!/usr/bin/env bash
# softpack-coarse (the coarse-grain validation, docs/coarse-grain.md) answers --help, builds a
# tiny medium, runs both models on it, refuses a medium made with other settings and bad input with
# one message, exit code 2 and no output file. (Their report is a study's: workflow.coarse_study.)
source "$(dirname "$0")/common.sh"
exe=$1
root=$2
config=$root/tests/data/coarse-grain-tiny.yaml
cd "$root"  # the settings' paths (profile, law file) are the repository's

"$exe" --help | grep -q "medium" || fail "--help does not list the medium subcommand"
"$exe" run --help | grep -q -- "--model" || fail "run --help does not list --model"
[ "$("$exe" seeds --config "$config")" = "901 902 " ] || fail "seeds: $("$exe" seeds --config "$config")"

"$exe" medium --config "$config" --seed 901 --out "$tmp/medium.h5" --quiet
for model in resolved soft; do
  "$exe" run --config "$config" --model $model --medium "$tmp/medium.h5" --out "$tmp/runs/$model-901.h5" --quiet
  h5dump -d /provenance/model "$tmp/runs/$model-901.h5" | grep -q "\"$model\"" || fail "the $model run's file does not say its model"
done

sed 's/    grains: 12/    grains: 13/' "$config" > "$tmp/other.yaml"
expect_error "made with other settings than" "$tmp/x.h5" "$exe" run --config "$tmp/other.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"
expect_error "--model: coarse not in {resolved,soft}" "$tmp/x.h5" "$exe" run --config "$config" --model coarse --medium "$tmp/medium.h5" --out "$tmp/x.h5"
sed 's/    speed: 0.05/    speed: -1/' "$config" > "$tmp/bad.yaml"
expect_error "compression.speed: -1 is not allowed" "$tmp/x.h5" "$exe" run --config "$tmp/bad.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"
sed 's/    grains: 12/    grian: 12/' "$config" > "$tmp/typo.yaml"
expect_error "coarse_grain.medium.grian: unknown key" "$tmp/m.h5" "$exe" medium --config "$tmp/typo.yaml" --seed 1 --out "$tmp/m.h5"
sed 's/    shear: 0.02/    shear: 0.0/' "$config" > "$tmp/noshear.yaml"
expect_error "record_shear is not read; remove it" "$tmp/x.h5" "$exe" run --config "$tmp/noshear.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"
sed 's/    placement_trials: 10000/    placement_trials: 10000\n    content_sample: 8/' "$config" > "$tmp/sample.yaml"
expect_error "coarse_grain.medium.content_sample: the sites hold no soft-particles" "$tmp/m.h5" \
  "$exe" medium --config "$tmp/sample.yaml" --seed 1 --out "$tmp/m.h5"
# Nested sites whose own sites' contents are sampled (medium.content_sample): the medium keeps the
# mean, the soft model runs on it, the resolved model is refused, the estimate counts the spheres
# with an error (the measured cost: the one-level resolved run above).
sed 's/^  polydispersity: 3$/  polydispersity: 3\n  levels: 2/' experiments/quick.yaml > "$tmp/quick-nested.yaml"
grep -q '^  levels: 2$' "$tmp/quick-nested.yaml" || fail "the nested profile was not written"
echo "content: {form: soft, laws: data/radius/report/laws.json, grain_contact: wall, shell_mass_fraction: 0.05}" >> "$tmp/quick-nested.yaml"
sed -e "s|    profile: experiments/quick.yaml|    profile: $tmp/quick-nested.yaml|" "$tmp/sample.yaml" > "$tmp/nested.yaml"
"$exe" medium --config "$tmp/nested.yaml" --seed 901 --out "$tmp/nested-medium.h5" 2> "$tmp/nested-medium.log"
grep -q "their contents sampled (8 per level)" "$tmp/nested-medium.log" || fail "medium: $(tr '\r' '\n' < "$tmp/nested-medium.log" | tail -1)"
h5dump -d /contents/sample "$tmp/nested-medium.h5" | grep -q "(0): 8" || fail "the medium file does not keep its sample"
"$exe" run --config "$tmp/nested.yaml" --model soft --medium "$tmp/nested-medium.h5" --out "$tmp/runs/nested-soft-901.h5" --quiet
expect_error "has no resolved model: its contents are weighed, not made" "$tmp/x.h5" \
  "$exe" run --config "$tmp/nested.yaml" --model resolved --medium "$tmp/nested-medium.h5" --out "$tmp/x.h5"
"$exe" estimate --config "$tmp/nested.yaml" --medium "$tmp/nested-medium.h5" --soft "$tmp/runs/nested-soft-901.h5" \
  --measured "$tmp/runs/resolved-901.h5" --out "$tmp/estimate.json" --quiet
python3 -c "
import json, sys
e = json.load(open(sys.argv[1]))
assert e['contents'].startswith('sampled: 8'), e['contents']
assert e['resolved_spheres']['error'] > 0 and e['resolved_cpu_estimate']['error'] > 0, e
assert (e['soft_beyond_range'], e['soft_max_dn']) == (int(sys.argv[2]), float(sys.argv[3])), e  # the soft run's own
" "$tmp/estimate.json" \
  "$(h5dump -d /soft/beyond_range "$tmp/runs/nested-soft-901.h5" | sed -n 's/^ *(0): //p')" \
  "$(h5dump -m %.17g -d /soft/max_dn "$tmp/runs/nested-soft-901.h5" | sed -n 's/^ *(0): //p')" \
  || fail "the estimate of a sampled medium: $(cat "$tmp/estimate.json")"
# The four-decade plan (plan.levels_added): the same medium a level deeper, in the estimate only.
printf '  plan:\n    levels_added: 1\n' > "$tmp/plan.txt"
sed "/^  seeds:/e cat $tmp/plan.txt" "$tmp/nested.yaml" > "$tmp/nested-plan.yaml"
grep -q '^    levels_added: 1$' "$tmp/nested-plan.yaml" || fail "the plan was not written"
"$exe" estimate --config "$tmp/nested-plan.yaml" --medium "$tmp/nested-medium.h5" --soft "$tmp/runs/nested-soft-901.h5" \
  --measured "$tmp/runs/resolved-901.h5" --out "$tmp/estimate-plan.json" --quiet
python3 -c "
import json, sys
e = json.load(open(sys.argv[1]))
p = e['plan']
assert p['levels_added'] == 1 and p['depth_ratio'] > 1, p
assert p['resolved_spheres']['value'] > e['resolved_spheres']['value'], p
assert p['resolved_dt']['value'] < e['resolved_dt']['value'] and p['speed_up_estimate']['value'] > e['speed_up_estimate']['value'], p
assert 'plan' not in json.load(open(sys.argv[2])), 'a plan without plan.levels_added'
" "$tmp/estimate-plan.json" "$tmp/estimate.json" || fail "the plan: $(cat "$tmp/estimate-plan.json")"
sed "/^  seeds:/e cat $tmp/plan.txt" "$config" > "$tmp/plan-one-level.yaml"
expect_error "coarse_grain.plan.levels_added: the sites hold no soft-particles" "$tmp/x.h5" \
  "$exe" medium --config "$tmp/plan-one-level.yaml" --seed 1 --out "$tmp/x.h5"
sed 's/    content_sample: 8/    content_sample: 9/' "$tmp/nested.yaml" > "$tmp/nested-9.yaml"
expect_error "made with other settings than" "$tmp/x.h5" \
  "$exe" run --config "$tmp/nested-9.yaml" --model soft --medium "$tmp/nested-medium.h5" --out "$tmp/x.h5"
# rotation: locked (the soft-particles' spin held at zero, a bound) runs on the same medium.
sed 's/    grain_contact: wall/    grain_contact: wall\n    rotation: locked/' "$config" > "$tmp/locked.yaml"
"$exe" run --config "$tmp/locked.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/runs/locked-901.h5" --quiet
sed 's/    grain_contact: wall/    grain_contact: wall\n    rotation: spinning/' "$config" > "$tmp/spinning.yaml"
expect_error "coarse_grain.soft_particle.rotation: 'spinning' is not allowed; allowed: free, locked" "$tmp/x.h5" \
  "$exe" run --config "$tmp/spinning.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"

# The stages' stamps (workflow/coarse.mk): each changes with exactly what its stage reads.
stamps() { "$exe" stamp --config "$1" --release 9.9.9 | tr '\n' ' '; }
base=$(stamps "$config")
[[ $base =~ ^medium=[0-9a-f]{16}\ resolved=[0-9a-f]{16}\ soft=[0-9a-f]{16}\ $ ]] || fail "stamp: '$base'"
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
same_but() {  # same_but CONFIG WHAT STAGES-THAT-CHANGE
  local other; other=$(stamps "$1")
  for stage in medium resolved soft; do
    if [[ " $3 " == *" $stage "* ]]; then
      [[ $(field "$other" $stage) != $(field "$base" $stage) ]] || fail "$2 left the $stage stamp as it was"
    else
      [[ $(field "$other" $stage) == $(field "$base" $stage) ]] || fail "$2 changed the $stage stamp"
    fi
  done
}
sed 's/    grain_contact: wall/    grain_contact: reduced-radius/' "$config" > "$tmp/contact.yaml"
same_but "$tmp/contact.yaml" "grain_contact" "soft"
same_but "$tmp/locked.yaml" "rotation: locked" "soft"
sed 's/    grain_contact: wall/    grain_contact: wall\n    rotation: free/' "$config" > "$tmp/free.yaml"
same_but "$tmp/free.yaml" "rotation: free (the default, written out)" ""
[[ $(stamps "$tmp/nested-plan.yaml") == $(stamps "$tmp/nested.yaml") ]] || fail "plan changed a stage's stamp (it is the estimate's)"
sed 's/    speed: 0.05/    speed: 0.04/' "$config" > "$tmp/speed.yaml"
same_but "$tmp/speed.yaml" "compression.speed" "resolved soft"
sed 's/    grains: 12/    grains: 13/' "$config" > "$tmp/grains.yaml"
same_but "$tmp/grains.yaml" "medium.grains" "medium resolved soft"
cp data/radius/report/laws.json "$tmp/laws.json"
sed "s|    laws: data/radius/report/laws.json|    laws: $tmp/laws.json|" "$config" > "$tmp/laws.yaml"
same_but "$tmp/laws.yaml" "the same law file elsewhere" ""
touch -d '2001-01-01' "$tmp/laws.json"
same_but "$tmp/laws.yaml" "an older law file of the same content" ""
sed -i 's/"version": 1/"version": 1 /' "$tmp/laws.json"
same_but "$tmp/laws.yaml" "a law file of other bytes" "soft"
[[ $(field "$(stamps "$config")" medium) == $(field "$(stamps "$tmp/contact.yaml")" medium) ]] || fail "stamps are not stable"
# many_body: the soft-particles follow another file's many-body law (the nested chain's medium):
# its file is in the soft stamp only, the run names it, and a file without one is refused (the
# law it takes: LawFile.ASectionTakesTheManyBodyLawOfTheFileItNames).
sed 's|    grain_contact: wall|    grain_contact: wall\n    many_body: data/many-body/report/laws-v6.json|' "$config" > "$tmp/many-body.yaml"
same_but "$tmp/many-body.yaml" "many_body" "soft"
"$exe" run --config "$tmp/many-body.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/runs/many-body-901.h5" --quiet
h5dump -d /provenance/settings "$tmp/runs/many-body-901.h5" | grep -q "many_body: data/many-body/report/laws-v6.json" \
  || fail "the run's provenance does not name its many-body law file"
sed 's|    grain_contact: wall|    grain_contact: wall\n    many_body: data/radius/report/laws.json|' "$config" > "$tmp/pairwise.yaml"
expect_error "coarse_grain.soft_particle.many_body: ./data/radius/report/laws.json has no many-body law" "$tmp/x.h5" \
  "$exe" run --config "$tmp/pairwise.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"
sed 's|    grain_contact: wall|    grain_contact: wall\n    many_body: ""|' "$config" > "$tmp/empty.yaml"
expect_error "coarse_grain.soft_particle.many_body: allowed: the path of a law file" "$tmp/x.h5" \
  "$exe" run --config "$tmp/empty.yaml" --model soft --medium "$tmp/medium.h5" --out "$tmp/x.h5"

# A probe run's file begins with its group's stamp (workflow/coarse.mk compares that line, not
# times): here a confined kind of the plan, on a grid of one Δn, one seed, the small radius.
sed 's/delta_n: &shallow \[[^]]*\]/delta_n: \&shallow [0.05]/' experiments/many-body.yaml > "$tmp/probe.yaml"
grep -q 'delta_n: &shallow \[0.05\]' "$tmp/probe.yaml" || fail "the probe plan's shallow grid was not replaced"
release=$(awk '/^project/ { print $3; exit }' CMakeLists.txt)
group_stamp=$("$exe" seeds --probe "$tmp/probe.yaml" --runs-stamp "$release" | tr ' ' '\n' | sed -n 's/^bodies-wall+walls-0.1=//p')
[[ $group_stamp =~ ^[0-9a-f]{16}$ ]] || fail "seeds --runs-stamp gave no stamp for bodies-wall+walls-0.1"
"$exe" multi-contact --probe "$tmp/probe.yaml" --radius half --part bodies --kind wall+walls-0.1 --packing-seed 501 --out "$tmp/probe.dat" 2> /dev/null
[ "$(head -1 "$tmp/probe.dat")" = "# stamp $group_stamp" ] || fail "the probe file's first line is '$(head -1 "$tmp/probe.dat")', not its group's stamp"
[ "$(grep -c '^[0-9] 0.0500 ' "$tmp/probe.dat")" = 3 ] || fail "the probe file has not its three arrangements at Δn 0.05"
echo "ok"
