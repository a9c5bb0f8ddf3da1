#!/usr/bin/env bash
# A single-node Slurm cluster in a scratch folder, for the tests (no systemd, no cgroups, no root
# configuration touched): munged with its own key and socket, slurmctld and slurmd on free ports,
# one partition with this machine's cores.
#
#   slurm_cluster.sh start DIR   writes DIR/slurm.conf, starts the three daemons, waits until
#                                sinfo shows the node idle (exit 1 with the daemons' logs if not)
#   slurm_cluster.sh stop DIR    stops them (and any job left), whatever state they are in
#   slurm_cluster.sh env DIR     prints the export line the clients need (SLURM_CONF)
#
# Every job that ends is recorded in DIR/jobcomp.txt (jobcomp/filetxt: one line per job, its id,
# name and state), which needs no database: this is what the tests count instead of sacct, which
# needs slurmdbd.
set -euo pipefail
cmd=${1:-} dir=${2:-}
usage() { sed -n '2,13s/^# \{0,1\}//p' "$0"; }
case $cmd in -h|--help) usage; exit 0 ;; start|stop|env) ;; *) usage >&2; exit 2 ;; esac
[[ -n $dir ]] || { usage >&2; exit 2; }
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
conf=$dir/slurm.conf

if [[ $cmd == env ]]; then echo "export SLURM_CONF=$conf"; exit 0; fi

stop() {
  export SLURM_CONF=$conf
  if [[ -f $conf ]] && scancel --quiet --user="$(id -un)" 2> /dev/null; then
    # The cancel reaches the job steps through slurmd: wait (10 s at most) until no job is left.
    for _ in $(seq 1 100); do [[ -z $(squeue -h -o %i 2> /dev/null) ]] && break; sleep 0.1; done
  fi
  local f pid
  for f in slurmd slurmctld munged; do
    [[ -f $dir/$f.pid ]] || continue
    pid=$(cat "$dir/$f.pid")
    kill "$pid" 2> /dev/null || continue
    for _ in $(seq 1 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2> /dev/null || true
    rm -f "$dir/$f.pid"
  done
}
if [[ $cmd == stop ]]; then stop; exit 0; fi

# --- start -----------------------------------------------------------------------------------------
for tool in munged slurmctld slurmd sinfo srun; do
  command -v "$tool" > /dev/null || [[ -x /usr/sbin/$tool ]] ||
    { echo "slurm_cluster.sh: $tool not found (Debian packages slurm-wlm and munge; make setup)" >&2; exit 77; }
done
PATH=$PATH:/usr/sbin
used_ports=" "
free_port() {  # a TCP port nobody listens on (ss, else /proc/net/tcp), not given out before
  local p hex
  while :; do
    p=$(shuf -i 20000-60000 -n 1)
    [[ $used_ports == *" $p "* ]] && continue
    if command -v ss > /dev/null; then
      ss -Htln "sport = :$p" 2> /dev/null | grep -q . && continue
    else
      hex=$(printf ':%04X ' "$p")
      grep -qi "$hex" /proc/net/tcp /proc/net/tcp6 2> /dev/null && continue
    fi
    used_ports+="$p "
    echo "$p"
    return
  done
}
mkdir -p "$dir"/{munge,state,spool,log}
chmod 700 "$dir/munge"
host=$(hostname -s)
cpus=$(nproc)
memory=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)

# munge: a key of our own, its socket in the scratch folder (--force: the scratch folder's parent,
# /tmp, is world-writable, which munged would otherwise refuse).
head -c 1024 /dev/urandom > "$dir/munge/munge.key"
chmod 400 "$dir/munge/munge.key"
munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
  --pid-file="$dir/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munge/seed"

ctld_port=$(free_port)
used_ports+="$ctld_port "
slurmd_port=$(free_port)
cat > "$conf" <<CONF
# written by tests/cluster/slurm_cluster.sh: a one-node cluster for the tests
ClusterName=softpack-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroups (a container has none to give): processes tracked by their parent ids, no binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
DefMemPerCPU=$((memory / cpus))
SlurmdParameters=config_overrides
InactiveLimit=0
KillWait=5
MinJobAge=300
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF

export SLURM_CONF=$conf
slurmctld -f "$conf"
slurmd -f "$conf"
for _ in $(seq 1 150); do
  state=$(sinfo -h -o %T 2> /dev/null || true)
  [[ $state == idle ]] && { echo "slurm_cluster.sh: node $host idle ($cpus CPUs), SLURM_CONF=$conf"; exit 0; }
  sleep 0.2
done
echo "slurm_cluster.sh: the node did not become idle in 30 s (sinfo: '${state:-}'); the daemons' logs:" >&2
tail -n 30 "$dir"/log/*.log >&2
stop
exit 1
