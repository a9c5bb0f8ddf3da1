#!/usr/bin/env bash
# softpack-pack, softpack-section and softpack-apollonian from the command line: --help, the
# same seed gives the same datasets, another seed another packing, and every bad input gives
# one message naming the key, exit code 2 and no output file.
source "$(dirname "$0")/common.sh"
bin=$1
root=$2

"$bin/softpack-pack" --help | grep -q -- "--seed" || fail "softpack-pack --help"
"$bin/softpack-section" --help | grep -q -- "--packing" || fail "softpack-section --help"
"$bin/softpack-apollonian" --help | grep -q -- "--depth" || fail "softpack-apollonian --help"

pack() { "$bin/softpack-pack" --config "$1" --seed "$2" --out "$3" --quiet; }
pack "$root/experiments/quick.yaml" 1 "$tmp/a.h5"
pack "$root/experiments/quick.yaml" 1 "$tmp/b.h5"
pack "$root/experiments/quick.yaml" 2 "$tmp/c.h5"
datasets() { h5dump -d /centres -d /radii -d /radii_inserted -d /stats/radial_profile/solid_fraction "$1" | tail -n +2; }
[ "$(datasets "$tmp/a.h5")" = "$(datasets "$tmp/b.h5")" ] || fail "same seed, different datasets"
[ "$(datasets "$tmp/a.h5")" != "$(datasets "$tmp/c.h5")" ] || fail "different seeds, same packing"
h5dump -d /provenance/config "$tmp/a.h5" | grep -q "polydispersity" || fail "no configuration in the provenance"

"$bin/softpack-section" --packing "$tmp/a.h5" --out "$tmp/section.dat" 2> /dev/null
grep -q "^# shell" "$tmp/section.dat" || fail "section file has no shell line"

# edit SED: the quick profile with one key changed (whatever its value there), which must change.
edit() { sed "$1" "$root/experiments/quick.yaml" > "$tmp/bad.yaml"; ! cmp -s "$tmp/bad.yaml" "$root/experiments/quick.yaml" || fail "edit $1 changed nothing"; }
out=$tmp/bad.h5
edit 's/polydispersity: [0-9.]*/polydispersity: 1/'
expect_error "packing.polydispersity: 1 is not allowed; allowed: 1 < Pi <= 1e6" "$out" pack "$tmp/bad.yaml" 1 "$out"
edit 's/exponent: [0-9.]*/exponent: 1/'
expect_error "packing.exponent: 1 is not allowed" "$out" pack "$tmp/bad.yaml" 1 "$out"
edit 's/beta: [0-9.]*/beta: 0/'
expect_error "packing.beta: 0 is not allowed; allowed: 0 < beta <= 100" "$out" pack "$tmp/bad.yaml" 1 "$out"
edit 's/trials: [0-9]*/trials: 0/'
expect_error "packing.trials: 0 is not allowed; allowed: 1 <= I <= 1e6" "$out" pack "$tmp/bad.yaml" 1 "$out"
edit 's/r_max_over_Rs: [0-9.]*/r_max_over_Rs: 1.2/'
expect_error "packing.r_max_over_Rs: 1.2 is not allowed" "$out" pack "$tmp/bad.yaml" 1 "$out"
edit '/beta:/d'
expect_error "packing: missing required key 'beta'" "$out" pack "$tmp/bad.yaml" 1 "$out"
printf 'packing: {Rs: [0.016\n' > "$tmp/bad.yaml"
expect_error "malformed YAML" "$out" pack "$tmp/bad.yaml" 1 "$out"
expect_error "cannot open the file" "$out" pack "$tmp/none.yaml" 1 "$out"
expect_error "--seed: '-3' is not allowed" "$out" pack "$root/experiments/quick.yaml" -3 "$out"
echo "not hdf5" > "$tmp/garbage.h5"
expect_error "not an HDF5 file" "$tmp/s.dat" "$bin/softpack-section" --packing "$tmp/garbage.h5" --out "$tmp/s.dat"
expect_error "--depth" "$tmp/ap.dat" "$bin/softpack-apollonian" --depth -1 --out "$tmp/ap.dat"
echo "ok"
