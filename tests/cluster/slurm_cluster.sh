#!/usr/bin/env bash
# Start a private single-node Slurm cluster on the loopback (munged, slurmctld, slurmd as root,
# no systemd, no cgroups: process tracking by process group), all state in DIR.
#   source tests/cluster/slurm_cluster.sh; slurm_start DIR; ...; slurm_stop
# Exports SLURM_CONF. slurm_stop stops only the daemons slurm_start started (by their pids).
# Returns 77 (skip) when the Debian packages slurm-wlm and munge are missing and cannot be installed.

slurm_pids=()

slurm_free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

slurm_start() {
  local d=$1
  if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    return 77
  fi
  mkdir -p "$d/state" "$d/spool" "$d/munge"
  chmod 700 "$d/munge"
  dd if=/dev/urandom of="$d/munge/munge.key" bs=1024 count=1 status=none
  chmod 400 "$d/munge/munge.key"
  munged --force --socket="$d/munge/munge.socket" --key-file="$d/munge/munge.key" \
    --pid-file="$d/munge/munged.pid" --log-file="$d/munge/munged.log" --seed-file="$d/munge/munged.seed" || return 1
  slurm_pids+=("$(cat "$d/munge/munged.pid")")
  local ctl_port node_port host
  ctl_port=$(slurm_free_port); node_port=$(slurm_free_port)
  host=$(hostname -s)
  cat > "$d/slurm.conf" <<CONF
ClusterName=mhcontact-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctl_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CryptoType=crypto/munge
AuthInfo=socket=$d/munge/munge.socket
ProctrackType=proctrack/pgid
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/slurmctld.log
SlurmdLogFile=$d/slurmd.log
SlurmctldTimeout=30
SlurmdTimeout=30
MinJobAge=300
NodeName=mhnode NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=mhnode Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$d/slurm.conf
  slurmctld -f "$d/slurm.conf" -c || return 1
  local i
  for i in $(seq 50); do [ -s "$d/slurmctld.pid" ] && break; sleep 0.1; done
  slurm_pids+=("$(cat "$d/slurmctld.pid")")
  slurmd -f "$d/slurm.conf" -N mhnode || return 1
  for i in $(seq 50); do [ -s "$d/slurmd.pid" ] && break; sleep 0.1; done
  slurm_pids+=("$(cat "$d/slurmd.pid")")
  # The node is up when sinfo reports it idle.
  for i in $(seq 100); do
    sinfo -h -N -o %T 2>/dev/null | grep -q idle && return 0
    sleep 0.2
  done
  echo "slurm_start: the node did not come up; logs:" >&2
  tail -n 20 "$d/slurmctld.log" "$d/slurmd.log" >&2
  return 1
}

# Wait until job JOBID (every task of an array) has left the queue; print each task's
# "JobId=... JobState=... ExitCode=..." line (finished jobs stay known for MinJobAge, 300 s).
slurm_wait() {
  local i
  for i in $(seq 1200); do
    [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && break
    sleep 0.1
  done
  scontrol -o show job "$1" | grep -o 'JobId=[0-9]* \(ArrayJobId=[0-9]* ArrayTaskId=[0-9]* \)\?\|JobState=[A-Z_]*\|ExitCode=[0-9:]*' | paste -d' ' - - -
}

slurm_stop() {
  local p
  for p in "${slurm_pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${slurm_pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
  done
  slurm_pids=()
}

# For a test script: a scratch directory $tmp, the private cluster started in it, and on exit
# its jobs cancelled, its daemons stopped and $tmp removed (kept with KEEP_TMP=1). Exits 77 (CTest:
# skipped) when slurm-wlm and munge are not installed, 1 when the cluster does not start; $1
# names the script in that message.
slurm_test_begin() {
  tmp=$(mktemp -d)
  trap slurm_test_cleanup EXIT
  local rc=0
  slurm_start "$tmp/slurm" || rc=$?
  if [ $rc -eq 77 ]; then
    echo "SKIP: Slurm is not installed (Debian packages slurm-wlm and munge: bash scripts/deps.sh installs them)"
    exit 77
  fi
  [ $rc -eq 0 ] || { echo "$1: could not start the test cluster" >&2; exit 1; }
}

slurm_test_cleanup() {
  [ -n "${SLURM_CONF:-}" ] && scancel --quiet --full "--user=$(id -un)" 2>/dev/null || true
  slurm_stop
  [ -n "${KEEP_TMP:-}" ] || rm -rf "$tmp"
}
