#!/usr/bin/env bash
# hold_sweep.sh COMMAND...: a RUN wrapper for the Slurm test (inside the job: RUN="srun ... hold_sweep.sh").
# Runs COMMAND; when it is the sweep whose --out is $HOLD_OUT, stops it (SIGSTOP) as soon as its
# first point is in its checkpoint folder, writes $HOLD_OUT.held with the job id, and waits: the
# test then cancels the job while the sweep is, for certain, mid-way. Any other command runs as is.
out= checkpoints= prev=
for a in "$@"; do
  case $prev in --out) out=$a ;; --checkpoints) checkpoints=$a ;; esac
  prev=$a
done
[[ -n ${HOLD_OUT:-} && $out == "$HOLD_OUT" && -n $checkpoints ]] || exec "$@"
"$@" &
pid=$!
while kill -0 "$pid" 2> /dev/null && ! compgen -G "$checkpoints/point-000.h5" > /dev/null; do sleep 0.05; done
# Held only if it is still running (else it ended before its first point was seen: say nothing,
# and the test reports that the sweep was never held).
if kill -STOP "$pid" 2> /dev/null && kill -0 "$pid" 2> /dev/null; then
  echo "${SLURM_JOB_ID:-none}" > "$HOLD_OUT.held.tmp" && mv "$HOLD_OUT.held.tmp" "$HOLD_OUT.held"
fi
wait "$pid"
