#!/usr/bin/env bash
# softpack-config, what Make learns of a profile: --help; the seeds, scenes and section lists the
# stages use; a stamp that changes exactly when a section its stage reads changes (not for a
# comment, the description or the watchdog); the sections it covers are those a stage records
# with its results; a profile the stages would refuse is refused, with the same message.
source "$(dirname "$0")/common.sh"
bin=$1
root=$2
cfg="$bin/softpack-config"
quick=$root/experiments/quick.yaml

"$cfg" --help | grep -q -- "stamp" || fail "softpack-config --help"
[ "$("$cfg" "$quick" seeds)" = "1 2" ] || fail "seeds: $("$cfg" "$quick" seeds)"
[ "$("$cfg" "$quick" scenes)" = "soft-solid soft-soft" ] || fail "scenes: $("$cfg" "$quick" scenes)"
[ "$("$cfg" "$quick" sections tangential)" = "packing material simulation relaxation normal tangential" ] ||
  fail "sections tangential: $("$cfg" "$quick" sections tangential)"
[[ "$("$cfg" "$quick" stamp normal)" =~ ^[0-9a-f]{16}$ ]] || fail "stamp: $("$cfg" "$quick" stamp normal)"
[ "$("$cfg" "$quick" name)" = "quick" ] || fail "name: $("$cfg" "$quick" name)"
"$cfg" "$quick" gnuplot | grep -qx 'Rs=0.016; E=500000; nu=0.3' || fail "gnuplot: $("$cfg" "$quick" gnuplot)"

# stamps STAGE...: the stamps of the stages for the profile $tmp/p.yaml
stamps() { for s in packing normal tangential average; do "$cfg" "$tmp/p.yaml" stamp "$s"; done; }
cp "$quick" "$tmp/p.yaml"
before=$(stamps)
{ echo "# a comment"; cat "$quick"; } | sed 's/^description: .*/description: "another"/; s/energy_growth: [0-9.]*/energy_growth: 20.0/' > "$tmp/p.yaml"
[ "$(stamps)" = "$before" ] || fail "a comment, the description or the watchdog changed a stamp"
changed() {  # changed SED STAGES...: the stages whose stamps change when SED edits the profile
  sed "$1" "$quick" > "$tmp/p.yaml"
  cmp -s "$tmp/p.yaml" "$quick" && fail "edit $1 changed nothing"
  paste -d' ' <(echo "$before") <(stamps) | awk '$1 != $2 { print NR }' | tr '\n' ' '
}
[ "$(changed 's/^  rate: .*/  rate: 0.12/')" = "3 4 " ] || fail "tangential.rate must change the tangential and average stamps only"
[ "$(changed 's/^  speed: .*/  speed: 0.025/')" = "2 3 4 " ] || fail "normal.speed must change normal, tangential, average"
[ "$(changed 's/^  beta: .*/  beta: 2.5/')" = "1 2 3 4 " ] || fail "packing.beta must change every stamp"
[ "$(changed 's/^seeds: .*/seeds: [1, 3]/')" = "4 " ] || fail "the seeds must change the average stamp only"
[ "$("$cfg" "$quick" stamp normal --release 9.9.9)" != "$("$cfg" "$quick" stamp normal)" ] || fail "the release is not in the stamp"

# A sliding section (issue 16): a stage of its own at the end of the list, which changes no
# other stage's stamp, and whose stamp follows its own keys and the normal ones.
{ cat "$quick"; printf 'sliding: {delta_n: [0.5], ht_over_Rs: [0.01, 0.1], speed: 0.01}\n'; } > "$tmp/p.yaml"
[ "$("$cfg" "$tmp/p.yaml" stages)" = "packing normal tangential average sliding" ] || fail "stages with sliding: $("$cfg" "$tmp/p.yaml" stages)"
[ "$(stamps)" = "$before" ] || fail "a sliding section changed another stage's stamp"
slide=$("$cfg" "$tmp/p.yaml" stamp sliding)
sed -i 's/speed: 0.01}/speed: 0.02}/' "$tmp/p.yaml"
[ "$("$cfg" "$tmp/p.yaml" stamp sliding)" != "$slide" ] || fail "sliding.speed does not change the sliding stamp"
sed -i 's/^  speed: .*/  speed: 0.025/' "$tmp/p.yaml"
[ "$("$cfg" "$tmp/p.yaml" stamp sliding)" != "$slide" ] || fail "normal.speed does not change the sliding stamp"
{ cat "$quick"; printf 'sliding: {delta_n: [0.42], ht_over_Rs: [0.01], speed: 0.01}\n'; } > "$tmp/p.yaml"
"$cfg" "$tmp/p.yaml" stages > /dev/null 2> "$tmp/err.txt" && fail "a sliding delta_n outside the normal grid is accepted"
grep -q "sliding.delta_n.*0.42 is not in normal.delta_n" "$tmp/err.txt" || fail "sliding.delta_n refusal: $(cat "$tmp/err.txt")"

# The sections a stamp covers are those the stage records with its results.
"$bin/softpack-pack" --config "$quick" --seed 1 --out "$tmp/p1.h5" --quiet
h5dump -d /provenance/config -y "$tmp/p1.h5" > "$tmp/recorded.txt"
while IFS= read -r line; do
  grep -qF -- "${line//\"/\\\"}" "$tmp/recorded.txt" || fail "the packing's provenance lacks '$line' of 'softpack-config text packing'"
done < <("$cfg" "$quick" text packing)

# A profile the stages refuse.
sed 's/safety: [0-9.]*/safety: 1.5/' "$quick" > "$tmp/bad.yaml"
expect_error "bad.yaml:27:25: simulation.integration.safety: 1.5 is not allowed; allowed: 0 < safety <= 1" "$tmp/none" \
  "$cfg" "$tmp/bad.yaml" seeds
expect_error "no-such.yaml: cannot open the file" "$tmp/none" "$cfg" "$tmp/no-such.yaml" seeds
set +e
"$cfg" "$quick" stamp spreading > /dev/null 2>&1
[ $? -ne 0 ] || fail "an unknown stage was accepted"
set -e
echo "softpack-config: ok"
