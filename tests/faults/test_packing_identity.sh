#!/usr/bin/env bash
# A packing is one seed, whatever it is called (issue 28, class 3; docs/measurement.md): identity
# by content, not by name or seed number. Two seeds of one packing would enter the average twice
# and shrink its standard error (to 0 for two). Drawn each run (FAULT_SEED=N replays):
#   1. packing.import.files naming one source twice, or a byte copy of it under another name: the
#      profile is refused before anything runs (softpack-config, softpack-import), exit 2;
#   2. a source and a copy that differs in its bytes but not in its packing (a comment added, the
#      spheres listed in another order, spaces at the ends of the lines): imported as two seeds,
#      the average of their sweeps is refused, and so is a soft-soft pair of the two.
#
#   test_packing_identity.sh BIN_DIR SOURCE_DIR   (FAULT_SEED=N replays)
bin=$1 root=$2
source "$(dirname "$0")/common.sh"
source "$root/tests/cli/import_inputs.sh"
import_inputs
shell=$'    shell: {radius: 0.016, centre: [0, 0, 0]}\n'

# --- 1. one source twice -----------------------------------------------------------------------------
for round in 1 2; do
  src=$tmp/run-$(( $(random_below 2) + 1 )).txt
  if [[ $(random_below 2) == 0 ]]; then other=$src how="the same file twice"; else
    other=$tmp/copy-$(random_below 100000).txt how="a byte copy"; cp "$src" "$other"; fi
  if [[ $(random_below 2) == 0 ]]; then files=("$src" "$other"); else files=("$other" "$src"); fi
  profile "$tmp/dup.yaml" "$(import_section "${files[0]}" "${files[1]}" "$shell")" "[0.2, 0.4]"
  expect_error "are one packing" "$tmp/none" "$bin/softpack-config" "$tmp/dup.yaml" stamp normal
  expect_error "are one packing" "$tmp/q.h5" "$bin/softpack-import" --config "$tmp/dup.yaml" --seed $(( $(random_below 2) + 1 )) --out "$tmp/q.h5"
  echo "ok: round $round: $how as seeds 1 and 2 is refused before anything runs"
done

# --- 2. one packing in other bytes ---------------------------------------------------------------------
src=$tmp/run-1.txt
case $(random_below 3) in
  0) how="a comment added"; { head -1 "$src"; echo "# the same packing, copied"; tail -n +2 "$src"; } > "$tmp/variant.txt" ;;
  1) how="the spheres in another order"; { head -1 "$src"; tail -n +2 "$src" | "$py" -c "
import random, sys; random.seed($seed); lines = sys.stdin.readlines(); random.shuffle(lines); sys.stdout.writelines(lines)"; } > "$tmp/variant.txt" ;;
  2) how="spaces at the ends of the lines"; sed 's/$/   /' "$src" > "$tmp/variant.txt" ;;
esac
cmp -s "$src" "$tmp/variant.txt" && fail "the variant ($how) has the same bytes"
p=$tmp/variant.yaml
profile "$p" "$(import_section "$src" "$tmp/variant.txt" "$shell")" "[0.2, 0.4]"
for seed_ in 1 2; do
  "$bin/softpack-import" --config "$p" --seed $seed_ --out "$tmp/q$seed_.h5" --quiet
  "$bin/softpack-normal" --config "$p" --scene soft-solid --seed $seed_ --packing "$tmp/q$seed_.h5" --checkpoints "$tmp/ck$seed_" \
    --out "$tmp/n$seed_.h5" --quiet
done
expect_error "are measurements of one packing" "$tmp/avg/soft-solid.h5" "$bin/softpack-average" --scene soft-solid --profile imported \
  --config "$p" --normal "$tmp/n1.h5" "$tmp/n2.h5" --out-dir "$tmp/avg"
expect_error "is the same packing as --packing" "$tmp/ss.h5" "$bin/softpack-normal" --config "$p" --scene soft-soft --seed 1 \
  --packing "$tmp/q1.h5" --second-packing "$tmp/q2.h5" --checkpoints "$tmp/ss" --out "$tmp/ss.h5"
echo "ok: a copy of a packing in other bytes ($how) as a second seed: the average and the soft-soft pair refuse it"
