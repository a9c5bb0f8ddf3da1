#!/usr/bin/env bash
# A checkpoint is taken only as what it is (issue 28, class 4; docs/measurement.md): a point file
# names its stage, its scene and packings (so its seed), its point (delta_n, alpha, ht) and its
# configuration, and the sweeps check all of them before they reuse it or start from its state.
# Each round (FAULT_SEED=N replays) copies a valid point file of the samples (odd rounds: of the
# same folder, so of the same configuration; even rounds: of either seed and stage) over another
# point of seed 1 and runs the stage that point belongs to again: the results
# are those of the intact checkpoints, and a misfiled point of the same configuration is named
# in a warning.
#
#   test_checkpoint_identity.sh BIN_DIR SOURCE_DIR   (FAULT_SEED=N replays)
bin=$(cd "$1" && pwd) root=$2
source "$(dirname "$0")/common.sh"
copy_samples "$tmp/s"
s=$tmp/s
# The points record their packings by path (and content): the stages run on the samples' own
# packing, where the checkpoints were made, so that the intact points are reused as such.
packing=$samples_fixture/s/p1.h5
# same_points A B: the results of A and B agree, every dataset exact, time and provenance aside.
same_points() { h5diff -q --exclude-path /seconds --exclude-path /timing --exclude-path /provenance "$1" "$2" > /dev/null 2>&1; }
mapfile -t points < <(cd "$s" && ls ck1/point-*.h5 tk1/point-*.h5 ck2/point-*.h5 tk2/point-*.h5)
mapfile -t targets < <(cd "$s" && ls ck1/point-*.h5 tk1/point-*.h5)

for round in 1 2 3 4 5 6; do
  target=${targets[$(random_below ${#targets[@]})]}
  # Odd rounds: a point of the target's own folder (its configuration: only the point differs);
  # even rounds: any point file of either seed and stage.
  source_=$target
  while [[ $source_ == "$target" || ($((round % 2)) == 1 && ${source_%%/*} != "${target%%/*}") ]]; do
    source_=${points[$(random_below ${#points[@]})]}
  done
  rm -rf "$tmp/r" && mkdir "$tmp/r" && cp -r "$s/ck1" "$s/tk1" "$tmp/r/"
  cp "$s/$source_" "$tmp/r/$target"
  # A misfiled normal point is found by the normal stage and by the tangential one, which first
  # checks the normal states it shears (drawn: either).
  if [[ $target == tk1/* || $(random_below 2) == 0 ]]; then
    stage=tangential
    tangential 1 "$packing" "$tmp/r/ck1" "$tmp/r/tk1" "$tmp/r/out.h5" 2> "$tmp/log" || fail "$source_ over $target: $(cat "$tmp/log")"
    reference=$s/t1.h5
  else
    stage=normal
    normal 1 "$packing" "$tmp/r/ck1" "$tmp/r/out.h5" 2> "$tmp/log" || fail "$source_ over $target: $(cat "$tmp/log")"
    reference=$s/n1.h5
  fi
  same_points "$tmp/r/out.h5" "$reference" || fail "round $round: $source_ copied over $target: the $stage results differ from the intact run's"
  if [[ ${source_%%/*} == "${target%%/*}" ]]; then
    grep -q "checkpoint not used.*$target: holds" "$tmp/log" || fail "round $round: $source_ over $target: no warning naming it: $(cat "$tmp/log")"
  fi
  echo "ok: round $round: $source_ copied over $target; the $stage stage computed it again, results as intact"
done
