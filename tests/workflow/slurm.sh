# SPDX-License-Identifier: Apache-2.0
# A real single-node Slurm cluster on this machine, for the workflow tests:
# munged, slurmctld and slurmd started as root on localhost (no systemd, no
# accounting database, no cgroups), everything under one scratch directory.
# Source it, then: slurm_start DIR (exports SLURM_CONF, returns once the node
# is idle), slurm_stop (idempotent; call it from an EXIT trap).
# Needs Debian's slurm-wlm and munge.

slurm_dir=""

# A TCP port nobody listens on (the cluster must not meet another one).
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

slurm_start() {  # DIR
  slurm_dir=$1
  local d=$slurm_dir node k
  mkdir -p "$d/munge" "$d/state" "$d/spool" "$d/log"
  chmod 700 "$d/munge"
  mungekey --create --keyfile="$d/munge/munge.key" || return 1
  # --force: the scratch directory lies under a world-writable /tmp.
  munged --force --key-file="$d/munge/munge.key" --socket="$d/munge/socket" \
         --pid-file="$d/munge/munged.pid" --seed-file="$d/munge/munged.seed" \
         --log-file="$d/log/munged.log" || return 1
  # The node as slurmd sees it (CPUs, sockets, cores, memory), first line.
  node=$(slurmd -C | head -n 1)
  cat >"$d/slurm.conf" <<EOF
ClusterName=alphapocket-test
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/socket
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF=$d/slurm.conf
  slurmctld -c -i || return 1   # -c: no state from an earlier cluster
  slurmd || return 1
  for ((k = 0; k < 300; ++k)); do
    [[ $(sinfo -h -o %T 2>/dev/null) == idle ]] && return 0
    sleep 0.1
  done
  echo "slurm: the node is not idle after 30 s: $(sinfo 2>&1)" >&2
  return 1
}

# Stops what slurm_start started, by the pid files it wrote.
slurm_stop() {
  [[ -n $slurm_dir ]] || return 0
  local f pid k
  # Jobs first, so that no slurmstepd outlives its slurmd.
  if scancel --user=root 2>/dev/null; then
    for ((k = 0; k < 100; ++k)); do
      [[ -z $(squeue -h 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  for f in slurmd.pid slurmctld.pid munge/munged.pid; do
    [[ -f $slurm_dir/$f ]] || continue
    pid=$(<"$slurm_dir/$f")
    kill "$pid" 2>/dev/null || continue
    for ((k = 0; k < 100; ++k)); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
  slurm_dir=""
}
