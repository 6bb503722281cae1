#!/bin/bash
# A single-node Slurm on this machine, for testing the sweep's Slurm path (issue 21): munged,
# slurmctld and slurmd from Debian's slurm-wlm and munge packages, a minimal slurm.conf on the
# loopback interface, all state under one folder. Not for production use.
#
#   scripts/slurm/local_slurm.sh start DIR    prints the line to export (SLURM_CONF=DIR/slurm.conf)
#   scripts/slurm/local_slurm.sh stop DIR
#
# Needs root (the daemons run as root here) and the packages: apt-get install slurm-wlm munge.
set -euo pipefail
cmd=${1:?start or stop}
D=$(realpath -m "${2:?a folder for the state of Slurm}")
case "$cmd" in
  start)
    for p in slurmctld slurmd munged sbatch; do
      command -v "$p" > /dev/null || { echo "local_slurm: $p is missing (apt-get install slurm-wlm munge)" >&2; exit 2; }
    done
    mkdir -p "$D/state" "$D/spool" "$D/munge"
    host=$(hostname -s)
    cpus=$(nproc)
    # munge: its own key and socket under D (the system's key is not touched)
    if [ ! -s "$D/munge/munge.key" ]; then
      dd if=/dev/urandom of="$D/munge/munge.key" bs=1024 count=1 status=none
      chmod 600 "$D/munge/munge.key"
    fi
    munged --force --key-file="$D/munge/munge.key" --socket="$D/munge/munge.socket" \
           --pid-file="$D/munge/munged.pid" --log-file="$D/munge/munged.log" --seed-file="$D/munge/munged.seed"
    cat > "$D/slurm.conf" <<CONF
ClusterName=splinex-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$D/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/slurmctld.log
SlurmdLogFile=$D/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$D/slurm.conf"
    slurmctld -f "$SLURM_CONF"
    slurmd -f "$SLURM_CONF"
    # wait until the node is idle
    for _ in $(seq 1 60); do
      if sinfo -h -o '%T' 2>/dev/null | grep -q idle; then
        echo "export SLURM_CONF=$SLURM_CONF"
        exit 0
      fi
      sleep 1
    done
    echo "local_slurm: the node did not become idle within 60 s; logs in $D" >&2
    sinfo >&2 || true
    exit 1
    ;;
  stop)
    pids=()
    for f in slurmd slurmctld munge/munged; do
      if [ -s "$D/$f.pid" ]; then pids+=("$(cat "$D/$f.pid")"); fi
    done
    ((${#pids[@]})) || exit 0
    kill "${pids[@]}" 2> /dev/null || true
    for _ in $(seq 1 20); do  # until they have exited
      kill -0 "${pids[@]}" 2> /dev/null || exit 0
      sleep 0.5
    done
    kill -9 "${pids[@]}" 2> /dev/null || true
    ;;
  *)
    echo "usage: local_slurm.sh start|stop DIR" >&2
    exit 2
    ;;
esac
