#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for tests/farm/slurm_test.cpp: munged, slurmctld and
# slurmd with a configuration generated in DIR, every daemon in the foreground of a background
# job whose PID is kept, so that `stop` ends exactly those processes.
#   local_slurm.sh start DIR   prints SLURM_CONF=... on success; exit 77 with the reason on a
#                              line starting "twinpath-skip:" when the cluster cannot start
#   local_slurm.sh stop DIR    ends the daemons started in DIR
set -uo pipefail

cmd=${1:?usage: local_slurm.sh start|stop DIR}
dir=${2:?usage: local_slurm.sh start|stop DIR}

skip() {
  echo "twinpath-skip: $*"
  for log in "$dir"/*.log; do
    [[ -s $log ]] && { echo "--- $log"; tail -n 5 "$log"; }
  done
  exit 77
}

stop() {
  for pid_file in "$dir"/slurmd.bgpid "$dir"/slurmctld.bgpid "$dir"/munged.bgpid; do
    [[ -f $pid_file ]] || continue
    pid=$(cat "$pid_file")
    kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
    rm -f "$pid_file"
  done
}

if [[ $cmd == stop ]]; then
  stop
  exit 0
fi

for tool in munged munge slurmctld slurmd sbatch squeue sinfo scontrol; do
  command -v "$tool" >/dev/null ||
    skip "$tool is not installed (Debian packages slurm-wlm and munge; scripts/deps.sh test installs them)"
done
[[ -r /proc/self/stat ]] || skip "/proc is not mounted (slurmd tracks job processes through it)"

# munged wants its key private and every directory above its socket searchable by all.
mkdir -p "$dir" && chmod 755 "$dir"
mkdir -p -m 700 "$dir/key" && mkdir -p -m 755 "$dir/run" "$dir/state" "$dir/spool"
head -c 1024 /dev/urandom >"$dir/key/munge.key" && chmod 400 "$dir/key/munge.key"
munged -F --key-file="$dir/key/munge.key" --socket="$dir/run/munge.sock" \
  --pid-file="$dir/run/munged.pid" --log-file="$dir/munged.log" \
  --seed-file="$dir/key/munged.seed" >>"$dir/munged.log" 2>&1 &
echo $! >"$dir/munged.bgpid"
# The waits for the daemons are guards against a hang, not measures (docs/testing.md): on a
# loaded 2-core machine a daemon may take many seconds to come up, and a wait that gave up
# early would turn the test into a skip. A daemon that dies ends its wait at once.
alive() { kill -0 "$(cat "$dir/$1.bgpid")" 2>/dev/null; }
for _ in $(seq 1200); do
  [[ -S $dir/run/munge.sock ]] && break
  alive munged || break
  sleep 0.1
done
[[ -S $dir/run/munge.sock ]] || { stop; skip "munged did not start (its log follows)"; }

# Two free TCP ports on the loopback interface for slurmctld and slurmd.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
cpus=$(nproc)
user=$(id -un)
cat >"$dir/slurm.conf" <<CONF
ClusterName=twinpathtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$dir/run/munge.sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=twinpath Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >>"$dir/slurmctld.log" 2>&1 &
echo $! >"$dir/slurmctld.bgpid"
slurmd -D -f "$SLURM_CONF" >>"$dir/slurmd.log" 2>&1 &
echo $! >"$dir/slurmd.bgpid"
for _ in $(seq 600); do
  state=$(sinfo -h -N -o %t 2>/dev/null | head -n 1)
  [[ $state == idle* ]] && break
  alive slurmctld && alive slurmd || break
  sleep 0.2
done
if [[ $state != idle* ]]; then
  stop
  skip "the one-node cluster did not come up (node state '${state:-none}'; the daemons' logs follow)"
fi
echo "SLURM_CONF=$SLURM_CONF"
