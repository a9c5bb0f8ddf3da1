#!/usr/bin/env bash
# One run per data folder: runs COMMAND while holding DATA/.softpack.lock, an flock(2) lock that
# the kernel releases when COMMAND ends, however it ends (an error, Ctrl-C, SIGKILL, a reboot).
#
#   workflow/with_lock.sh DATA COMMAND...
#
# When another run holds the lock, says which one (process, host, start, goals) and waits for
# it; LOCK_WAIT=N waits at most N seconds, LOCK_WAIT=0 refuses at once (exit 2). On a cluster's
# shared file system the lock works where flock does across nodes (NFSv3 with lockd, NFSv4:
# Linux maps flock to POSIX locks there; Lustre mounted with -o flock; GPFS, BeeGFS).
set -uo pipefail
if [[ $# -lt 2 || $1 == -h || $1 == --help ]]; then
  echo "usage: $0 DATA COMMAND...  (LOCK_WAIT=seconds: how long to wait for another run; default: as long as it takes)" >&2
  exit 2
fi
data=$1
shift
mkdir -p -- "$data" || { echo "make: cannot create the data folder $data" >&2; exit 2; }
lock=$data/.softpack.lock
exec 219>> "$lock" || { echo "make: cannot open the lock $lock (is $data writable?)" >&2; exit 2; }
if ! flock -n 219; then
  holder=$(cat -- "$lock" 2> /dev/null)
  wait=${LOCK_WAIT:-}
  [[ -z $wait || ($wait =~ ^[0-9]+$ && ${#wait} -le 8 && $wait -le 31536000) ]] ||
    { echo "make: LOCK_WAIT=$wait is not allowed; allowed: a whole number of seconds from 0 to 31536000 (a year)" >&2; exit 2; }
  if [[ $wait == 0 ]]; then
    echo "make: $data is in use by another run (${holder:-unknown}); not started (LOCK_WAIT=0). Wait for it, or use another DATA=" >&2
    exit 2
  fi
  echo "make: $data is in use by another run (${holder:-unknown}); waiting for it to end${wait:+ (at most $wait s)}" >&2
  flock ${wait:+-w "$wait"} 219
  rc=$?
  if [[ $rc == 1 && -n $wait ]]; then  # flock's own code for a timeout
    echo "make: $data is still in use by another run after $wait s (${holder:-unknown}); not started" >&2
    exit 2
  elif [[ $rc != 0 ]]; then
    echo "make: cannot take the lock $lock (flock exit $rc); not started" >&2
    exit 2
  fi
fi
# Who holds it, for the message of a run that has to wait (the lock is the open file, not this text).
printf 'pid %s on %s since %s: %s\n' "$$" "$(hostname)" "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$*" > "$lock"
exec "$@"
