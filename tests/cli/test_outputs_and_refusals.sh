#!/usr/bin/env bash
# Defects of the hostile probe (issue 28), one case each; each failed on release 0.5.0:
#   defect 5: an output naming one of the command's own inputs (by name, or a hard link of it) is
#             refused, exit 2, the input intact: softpack-normal --packing p.h5 --out p.h5,
#             softpack-fit --average a.h5 --out a.h5, softpack-run --scene s.yaml --out s.yaml,
#             softpack-import --out <its source>, softpack-pack --config P --vtp P;
#   defect 7: a full disk behind stdout (softpack-run > /dev/full) is exit 2 with a message, not
#             exit 0 with an empty report; behind stderr (an error to report), exit 2, not 134;
#   defect 8: softpack-table refusing its input (damaged averages, --Rs 0) writes no table;
#   defect 12: softpack-config refuses what only a later stage refused: normal.scenes listing a
#             scene twice, scenes: [], effects.normal: bogus (exit 2, file:line);
#   defect 13: (law file: unit tests LawFile.*, test_law_file.cpp);
#   defect 14: a packing of one radius imports (exit 0, not an internal error); a folder, a symlink
#             loop or /dev/zero given as a YAML or JSON input is exit 2 with a message, read
#             without bound no more;
#   defect 15: a path with a line break (or another control character) on the command line is
#             refused (exit 2) before it can reach a .dat file's comment lines;
#   defect 17: messages that say what is wrong: an unclosed '[[[' (not "a key must be text"); a
#             direction [1e300, 1e300, 0] (too long, not "non-finite"); Pi = 5e5 (at its file and
#             line, naming packing.polydispersity, not a key that does not exist); Rs = 1e-9 (Rs is
#             the problem: no "Pi <= 0.3"); ht_over_Rs: one range in every message; LOCK_WAIT beyond
#             a year refused (it claimed to have waited 1e20 s);
#   defect 18: numbers read one way by every reader: E: 0500000 (octal to YAML 1.1), !!str 5.0e5,
#             0x1p19 refused (exit 2, file:line).
#
#   test_outputs_and_refusals.sh BIN_DIR SOURCE_DIR
bin=$1 root=$2
source "$root/tests/faults/common.sh"
copy_samples "$tmp/s"
s=$tmp/s

# --- defect 5 -------------------------------------------------------------------------------------------
# same_after NAME FILE COMMAND...: COMMAND refuses (exit 2, "an output never overwrites an input") and FILE is unchanged.
same_after() {
  local name=$1 file=$2 before
  shift 2
  before=$(sha256sum < "$file")
  set +e; "$@" > /dev/null 2> "$tmp/err"; local code=$?; set -e
  [[ $code == 2 ]] && grep -q "an output never overwrites an input" "$tmp/err" || fail "defect 5: $name: exit $code: $(cat "$tmp/err")"
  [[ $(sha256sum < "$file") == "$before" ]] || fail "defect 5: $name: the input was changed"
}
same_after "normal --out its packing" "$s/p1.h5" "$bin/softpack-normal" --config "$profile" --scene soft-solid --seed 1 \
  --packing "$s/p1.h5" --checkpoints "$tmp/ck" --out "$s/p1.h5"
ln "$s/p1.h5" "$tmp/link.h5"
same_after "normal --out a hard link of its packing" "$s/p1.h5" "$bin/softpack-normal" --config "$profile" --scene soft-solid \
  --seed 1 --packing "$s/p1.h5" --checkpoints "$tmp/ck" --out "$tmp/link.h5"
same_after "fit --out its average" "$s/avg/soft-solid.h5" "$bin/softpack-fit" --average "$s/avg/soft-solid.h5" --out "$s/avg/soft-solid.h5"
cp "$root/experiments/scenes/sphere-on-wall.yaml" "$tmp/scene.yaml"
same_after "run --out its scene" "$tmp/scene.yaml" "$bin/softpack-run" --scene "$tmp/scene.yaml" --out "$tmp/scene.yaml" --quiet
cp "$profile" "$tmp/profile.yaml"
same_after "pack --vtp its profile" "$tmp/profile.yaml" "$bin/softpack-pack" --config "$tmp/profile.yaml" --seed 1 --out "$tmp/x.h5" \
  --vtp "$tmp/profile.yaml"
printf '# x y z r\n0 0 0 0.004\n0.008 0 0 0.003\n' > "$tmp/source.txt"
printf '# x y z r\n0 0 0 0.005\n-0.009 0 0 0.003\n' > "$tmp/source2.txt"
awk '/^packing:/ {print "packing:\n  import:\n    files: {1: '"$tmp"'/source.txt, 2: '"$tmp"'/source2.txt}\n    shell: {radius: 0.016, centre: [0, 0, 0]}"; skip = 1; next}
     skip && /^  / {next} {skip = 0; print}' "$profile" > "$tmp/import.yaml"
same_after "import --out its source" "$tmp/source.txt" "$bin/softpack-import" --config "$tmp/import.yaml" --seed 1 --out "$tmp/source.txt"
echo "ok: defect 5: no command overwrites its own input (by name or hard link)"

# --- defect 7 -------------------------------------------------------------------------------------------
set +e; "$bin/softpack-run" --scene "$root/experiments/scenes/sphere-on-wall.yaml" --quiet > /dev/full 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 ]] && grep -q "standard output: cannot write" "$tmp/err" || fail "defect 7: softpack-run > /dev/full: exit $code: $(cat "$tmp/err")"
set +e; "$bin/softpack-fit" --average "$tmp/missing.h5" --out "$tmp/f.json" 2> /dev/full; code=$?; set -e
[[ $code == 2 ]] || fail "defect 7: an error reported on a full stderr: exit $code (expected 2)"
echo "ok: defect 7: a full disk behind stdout or stderr is exit 2, not 0 or 134"

# --- defect 8 -------------------------------------------------------------------------------------------
table=("$bin/softpack-table" --fits "$s/fit.json" --published "$root/experiments/published.yaml" --out-dir "$tmp/tables")
set +e; "${table[@]}" --averages "$s/avg/soft-solid.h5" --Rs 0 > /dev/null 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 && ! -e $tmp/tables ]] || fail "defect 8: --Rs 0: exit $code, wrote: $(ls "$tmp/tables" 2> /dev/null)"
"$py" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'a'); del f['kt']" "$s/avg/soft-solid.h5" 2> /dev/null ||
  cp "$s/p1.h5" "$s/avg/soft-solid.h5"  # an average that cannot serve: the table's kt_unit.md needs /kt
set +e; "${table[@]}" --averages "$s/avg/soft-solid.h5" --Rs 0.016 > /dev/null 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 && ! -e $tmp/tables ]] || fail "defect 8: a damaged average: exit $code, wrote: $(ls "$tmp/tables" 2> /dev/null)"
echo "ok: defect 8: softpack-table refusing its input writes no table"

# --- defect 12 ------------------------------------------------------------------------------------------
refused() {  # refused WHAT SED_EXPRESSION MESSAGE
  sed "$2" "$profile" > "$tmp/bad.yaml"
  cmp -s "$profile" "$tmp/bad.yaml" && fail "defect 12: $1: the edit changed nothing"
  set +e; "$bin/softpack-config" "$tmp/bad.yaml" stamp packing > /dev/null 2> "$tmp/err"; code=$?; set -e
  [[ $code == 2 ]] && grep -q "bad.yaml:[0-9]*:[0-9]*: .*$3" "$tmp/err" || fail "defect 12: $1: exit $code: $(cat "$tmp/err")"
}
refused "a scene twice" 's/scenes: \[soft-solid, soft-soft\]/scenes: [soft-solid, soft-solid]/' "listed twice"
refused "no scene" 's/scenes: \[soft-solid, soft-soft\]/scenes: []/' "at least one scene"
refused "an unknown normal law" 's/normal: hertz/normal: bogus/' "'bogus' is not a contact model"
echo "ok: defect 12: softpack-config refuses a scene twice, no scene, an unknown law (exit 2, file:line)"

# --- defect 18 ------------------------------------------------------------------------------------------
refused "a leading zero" 's/E: 5.0e5/E: 0500000/' "leading zero is not allowed"
refused "a number tagged as text" 's/E: 5.0e5/E: !!str 5.0e5/' "tagged !!str"
refused "a hexadecimal float" 's/E: 5.0e5/E: 0x1p19/' "only decimal numbers"
echo "ok: defect 18: a leading zero, !!str and a hexadecimal number are refused where a number is expected"

# --- defect 14 ------------------------------------------------------------------------------------------
printf '# x y z r\n0 0 0 0.004\n0.009 0 0 0.004\n' > "$tmp/mono.txt"
sed "s|$tmp/source.txt|$tmp/mono.txt|" "$tmp/import.yaml" > "$tmp/mono.yaml"
"$bin/softpack-import" --config "$tmp/mono.yaml" --seed 1 --out "$tmp/mono.h5" --quiet 2> "$tmp/err" ||
  fail "defect 14: a packing of one radius: $(cat "$tmp/err")"
mkdir "$tmp/folder.yaml"
ln -s "$tmp/loop.yaml" "$tmp/loop.yaml"
for input in "$tmp/folder.yaml" "$tmp/loop.yaml" /dev/zero; do
  for cmd in "softpack-config $input seeds" "softpack-run --scene $input --quiet" "softpack-table --fits $input --published $root/experiments/published.yaml --out-dir $tmp/t14"; do
    set +e; timeout 20 "$bin"/$cmd > /dev/null 2> "$tmp/err"; code=$?; set -e
    [[ $code == 2 ]] && grep -qE "is a directory|symlink loop|not a regular file" "$tmp/err" ||
      fail "defect 14: $cmd: exit $code: $(head -c 300 "$tmp/err")"
  done
done
echo "ok: defect 14: a packing of one radius imports; a folder, a symlink loop, /dev/zero as an input: exit 2"

# --- defect 15 ------------------------------------------------------------------------------------------
odd=$tmp/$'n1\n0.5 99 99'.h5
cp "$s/n1.h5" "$odd"
set +e; "$bin/softpack-average" --scene soft-solid --profile sweep --normal "$odd" "$s/n2.h5" --out-dir "$tmp/a15" 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 && ! -e $tmp/a15 ]] && grep -q "control character" "$tmp/err" || fail "defect 15: a line break in --normal: exit $code: $(cat "$tmp/err")"
echo "ok: defect 15: a path with a line break is refused before it reaches a .dat file"

# --- defect 17 ------------------------------------------------------------------------------------------
refused "an unclosed bracket" 's/^seeds: \[1, 2\]/seeds: [[[1, 2]/' "this '\[' is not closed before line"
refused "a polydispersity of 5e5" 's/polydispersity: 3/polydispersity: 5e5/' "packing.polydispersity: 5e5 is not allowed .* about 2.6.e+15 spheres"
refused "Rs of 1e-9 m" 's/Rs: 0.016/Rs: 1e-9/' "packing.Rs: 1e-9 m is not allowed"
grep -q "Pi <=" "$tmp/err" && fail "defect 17: Rs = 1e-9 suggests a polydispersity: $(cat "$tmp/err")"
sed 's/normal: \[0.0, 0.0, 1.0\]/normal: [1e300, 1e300, 0]/' "$root/experiments/scenes/sphere-on-wall.yaml" > "$tmp/long.yaml"
set +e; "$bin/softpack-run" --scene "$tmp/long.yaml" --quiet > /dev/null 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 ]] && grep -q "planes\[0\].normal: \[1e300, 1e300, 0\] is too long" "$tmp/err" || fail "defect 17: a long normal: $(cat "$tmp/err")"
sliding=$(printf 'sliding: {delta_n: [0.5], ht_over_Rs: [%s], speed: 0.01}' "$(echo '0.0|1.5|-0.1' | tr '|' '\n' | sed -n "$(( $(random_below 3) + 1 ))p")")
{ cat "$profile"; echo "$sliding"; } > "$tmp/sliding.yaml"
set +e; "$bin/softpack-config" "$tmp/sliding.yaml" seeds > /dev/null 2> "$tmp/err"; code=$?; set -e
[[ $code == 2 ]] && grep -q "sliding.ht_over_Rs\[0\]: .* is not allowed; allowed: 0 < value < 1" "$tmp/err" ||
  fail "defect 17: $sliding: exit $code: $(cat "$tmp/err")"
for wait in 100000000000000000000 1e20 31536001; do
  set +e; LOCK_WAIT=$wait "$root/workflow/with_lock.sh" "$tmp/lockdata" true 2> "$tmp/err"; set -e  # free lock: runs
  exec 217>> "$tmp/lockdata/.softpack.lock"; flock -n 217
  set +e; LOCK_WAIT=$wait "$root/workflow/with_lock.sh" "$tmp/lockdata" true 2> "$tmp/err"; code=$?; set -e
  exec 217>&-
  [[ $code == 2 ]] && grep -q "LOCK_WAIT=$wait is not allowed; allowed: a whole number of seconds from 0 to 31536000" "$tmp/err" ||
    fail "defect 17: LOCK_WAIT=$wait: exit $code: $(cat "$tmp/err")"
done
echo "ok: defect 17: an unclosed bracket, a long direction, Pi = 5e5, Rs = 1e-9, ht_over_Rs and LOCK_WAIT say what is wrong"
