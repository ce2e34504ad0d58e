#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for the suite's Slurm test and for trying
# `./rl reproduce ... --slurm` without a real cluster.
#
#   tools/slurm_local.sh start    configure and start munged, slurmctld and slurmd (as root)
#   tools/slurm_local.sh stop     stop them (the state folder stays, for the logs)
#   tools/slurm_local.sh status   sinfo of the running cluster
#   tools/slurm_local.sh env      the line that points Slurm's commands at this cluster
#
# Everything lives in one state folder ($RL_SLURM_DIR, default /var/tmp/rl-slurm): slurm.conf,
# the daemons' logs, pid files and spool. /etc/slurm is left alone, so a machine that is already
# a cluster's node keeps its configuration; Slurm's commands find this one through SLURM_CONF
# (`eval "$(tools/slurm_local.sh env)"`). The node is this machine with its own CPUs and memory
# (`slurmd -C`); one partition, `local`. No accounting database: sacct needs slurmdbd and
# MariaDB, which a one-node test does not need; jobs are followed with squeue and
# `scontrol show job`, and finished ones with the job-completion log (jobcomp/filetxt).
#
# If a daemon does not come up, `start` prints the last lines of its log and exits non-zero.
set -euo pipefail

export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
DIR=${RL_SLURM_DIR:-/var/tmp/rl-slurm}
CONF=$DIR/slurm.conf
MUNGE_SOCKET_DIR=/run/munge

log() { printf '[slurm_local] %s\n' "$*" >&2; }
die() {
  log "$*"
  exit 1
}

show_log() {
  local file=$1
  if [ -f "$file" ]; then
    log "last lines of $file:"
    tail -n 20 "$file" >&2
  else
    log "$file was not written"
  fi
}

need() {
  command -v "$1" >/dev/null || die "$1 is not installed (./rl setup installs slurmctld, slurmd, slurm-client and munge)"
}

write_conf() {
  local node cpus mem
  node=$(hostname -s)
  cpus=$(nproc)
  # RealMemory from slurmd's own reading, so the node never registers with less than configured.
  mem=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p')
  [ -n "$mem" ] || die "slurmd -C printed no RealMemory"
  mkdir -p "$DIR/spool/ctld" "$DIR/spool/d" "$DIR/log"
  cat >"$CONF" <<CONF
# Written by tools/slurm_local.sh: a one-node cluster on $node.
ClusterName=rllocal
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
SlurmctldPort=6817
SlurmdPort=6818
StateSaveLocation=$DIR/spool/ctld
SlurmdSpoolDir=$DIR/spool/d
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
# No cgroups: the test machine may be a container without a writable cgroup tree.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$DIR/log/jobcomp.log
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmdTimeout=60
InactiveLimit=0
MinJobAge=300
KillWait=10
NodeName=$node CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
}

running() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

start_munge() {
  if munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1; then
    return 0
  fi
  [ -f /etc/munge/munge.key ] || die "/etc/munge/munge.key is missing (the munge package makes it)"
  mkdir -p "$MUNGE_SOCKET_DIR" /var/log/munge /var/lib/munge
  chown munge:munge "$MUNGE_SOCKET_DIR" /var/log/munge /var/lib/munge
  chmod 0755 "$MUNGE_SOCKET_DIR"
  runuser -u munge -- /usr/sbin/munged || { show_log /var/log/munge/munged.log; die "munged did not start"; }
  local i
  for i in $(seq 1 50); do
    munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  show_log /var/log/munge/munged.log
  die "munged does not answer"
}

cmd_start() {
  [ "$(id -u)" -eq 0 ] || die "start needs root (the daemons run as root on this one-node cluster)"
  need slurmctld
  need slurmd
  need sbatch
  need munged
  write_conf
  start_munge
  export SLURM_CONF=$CONF
  if ! running "$DIR/slurmctld.pid"; then
    # -i: ignore state files of an earlier run that a different configuration may have left.
    slurmctld -i -f "$CONF" || { show_log "$DIR/log/slurmctld.log"; die "slurmctld did not start"; }
  fi
  if ! running "$DIR/slurmd.pid"; then
    slurmd -f "$CONF" || { show_log "$DIR/log/slurmd.log"; die "slurmd did not start"; }
  fi
  local i state=""
  for i in $(seq 1 100); do
    state=$(sinfo -h -o '%t' 2>/dev/null | head -n 1 || true)
    case "$state" in
    idle* | mix* | alloc*)
      log "cluster up: node $(hostname -s), partition local ($state); export SLURM_CONF=$CONF"
      return 0
      ;;
    esac
    sleep 0.2
  done
  log "the node did not become idle (sinfo state: '${state:-none}')"
  show_log "$DIR/log/slurmctld.log"
  show_log "$DIR/log/slurmd.log"
  exit 1
}

stop_pid() {
  local file=$1 name=$2 i
  running "$file" || return 0
  kill "$(cat "$file")" 2>/dev/null || true
  for i in $(seq 1 50); do
    running "$file" || return 0
    sleep 0.1
  done
  log "$name did not stop on SIGTERM; killing it"
  kill -9 "$(cat "$file")" 2>/dev/null || true
}

cmd_stop() {
  if [ -f "$CONF" ]; then
    SLURM_CONF=$CONF scancel --user="$(id -un)" 2>/dev/null || true
  fi
  stop_pid "$DIR/slurmd.pid" slurmd
  stop_pid "$DIR/slurmctld.pid" slurmctld
  log "stopped (logs kept in $DIR/log; munged left running: other services may use it)"
}

case "${1:-}" in
start) cmd_start ;;
stop) cmd_stop ;;
status)
  [ -f "$CONF" ] || die "not configured: run start first"
  SLURM_CONF=$CONF sinfo
  ;;
env) echo "export SLURM_CONF=$CONF" ;;
*)
  sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
  ;;
esac
