#!/usr/bin/env bash
# A throw-away single-node Slurm cluster on this machine, for trying the sweep's job
# array without a real cluster (and for the CI test, tests/slurm_test.cpp):
#   local_cluster.sh start DIR   writes DIR/slurm.conf and a munge key, starts munged,
#                                slurmctld and slurmd (state, logs and pid files in DIR)
#                                and waits until the node is idle; prints the SLURM_CONF
#                                to export.
#   local_cluster.sh stop DIR    stops the three daemons by their pid files.
# Needs Debian's slurm-wlm and munge; ports are picked from the folder's name hash so that
# parallel test runs do not collide. Nothing outside DIR is written.
set -euo pipefail
action="${1:?usage: local_cluster.sh start|stop DIR}"
dir="$(mkdir -p "${2:?usage: local_cluster.sh start|stop DIR}" && cd "$2" && pwd)"

stop() {
  local name pid
  for name in slurmd slurmctld munged; do
    [ -f "$dir/$name.pid" ] || continue
    pid="$(cat "$dir/$name.pid")"
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$dir/$name.pid"
  done
}

if [ "$action" = stop ]; then stop; exit 0; fi
[ "$action" = start ] || { echo "local_cluster.sh: unknown action '$action' (start|stop)" >&2; exit 2; }
for tool in munged slurmctld slurmd sinfo; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || { echo "local_cluster.sh: $tool not found (Debian slurm-wlm, munge)" >&2; exit 3; }
done
export PATH="$PATH:/usr/sbin"
user="$(id -un)"
host="$(hostname -s)"
port=$((20000 + $(printf '%s' "$dir" | cksum | cut -d' ' -f1) % 20000))
cpus="$(nproc)"
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
chmod 700 "$dir/munge"
# A fresh random key, readable by its owner only, as munged demands.
head -c 1024 /dev/urandom > "$dir/munge/munge.key"
chmod 400 "$dir/munge/munge.key"
cat > "$dir/slurm.conf" <<CONF
# Written by scripts/slurm/local_cluster.sh: a single-node cluster on $host.
ClusterName=testbed-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
SchedulerType=sched/builtin
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"
trap 'stop' ERR
munged --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" --pid-file="$dir/munged.pid" \
  --log-file="$dir/munged.log" --seed-file="$dir/munge/munged.seed" --force
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
# Up when the node accepts jobs (idle). The bound (60 s) only stops a cluster that never comes
# up; a loaded machine's daemons may take many seconds.
for _ in $(seq 300); do
  if sinfo -h -N -o '%t' 2>/dev/null | grep -q '^idle'; then echo "export SLURM_CONF=$SLURM_CONF"; exit 0; fi
  sleep 0.2
done
echo "local_cluster.sh: the node did not come up; see $dir/slurmctld.log, $dir/slurmd.log" >&2
stop
exit 1
