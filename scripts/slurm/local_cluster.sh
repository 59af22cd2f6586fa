#!/usr/bin/env bash
# A real single-node Slurm cluster on this machine, for tests and for running plans locally.
# Runs as root without systemd (containers): munged, slurmctld and slurmd are started directly,
# everything they keep (munge key, slurm.conf, state, spool, logs, sockets, pid files) lives in
# one folder, so several clusters (one per test) never share anything.
#
#   local_cluster.sh [--dir DIR] start    generate the config, start the daemons, wait until the
#                                         node is idle (timeout PROXYVIS_SLURM_START_TIMEOUT s)
#   local_cluster.sh [--dir DIR] stop     cancel its jobs, stop exactly the daemons start started
#   local_cluster.sh [--dir DIR] status   daemons alive and the node's state (exit 0 = usable)
#   local_cluster.sh [--dir DIR] env      print "export SLURM_CONF=..." for eval: sbatch, squeue,
#                                         sinfo and scripts/slurm/submit.sh then use this cluster
#
# DIR defaults to $PROXYVIS_SLURM_DIR, else /tmp/proxyvis-slurm. Exit codes: 0 done, 1 failed
# (status: not usable), 2 bad usage, 4 Slurm cannot run here (binaries missing, not root,
# daemons refuse to start, node never idle): tests skip on 4.
set -euo pipefail

PROG=local_cluster.sh
DIR=${PROXYVIS_SLURM_DIR:-/tmp/proxyvis-slurm}
START_TIMEOUT=${PROXYVIS_SLURM_START_TIMEOUT:-30}
NODE=proxyvis-node
PARTITION=local

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
}

# One line on stderr in the project's error format, then the exit code given.
fail() {
  local code=$1 what=$2
  echo "$PROG: error: $DIR: $what" >&2
  exit "$code"
}

cmd=""
while [ $# -gt 0 ]; do
  case $1 in
    --dir) [ $# -ge 2 ] || fail 2 "--dir needs a folder; none given (pass --dir DIR)"
      DIR=$2; shift 2 ;;
    --dir=*) DIR=${1#--dir=}; shift ;;
    -h|--help) usage; exit 0 ;;
    start|stop|status|env) [ -z "$cmd" ] || fail 2 "two commands given; only one allowed (start, stop, status or env)"
      cmd=$1; shift ;;
    *) fail 2 "unknown argument '$1'; not a command or option (see $PROG --help)" ;;
  esac
done
[ -n "$cmd" ] || fail 2 "no command given; one is required (start, stop, status or env)"
[[ $START_TIMEOUT =~ ^[1-9][0-9]{0,3}$ ]] ||
  fail 2 "PROXYVIS_SLURM_START_TIMEOUT is '$START_TIMEOUT'; it must be whole seconds in [1, 9999] (unset it for 30)"
DIR=$(realpath -m -- "$DIR")

CONF=$DIR/slurm.conf
RUN=$DIR/run
export SLURM_CONF=$CONF

# A pid file's process if it is alive, ours (its command line names DIR) and not a zombie.
# The check of the command line keeps a recycled pid from being mistaken for our daemon.
live_pid() {
  local file=$1 pid
  [ -s "$file" ] || return 1
  pid=$(tr -dc '0-9' <"$file")
  [ -n "$pid" ] && [ -r "/proc/$pid/cmdline" ] || return 1
  tr '\0' ' ' <"/proc/$pid/cmdline" | grep -qF -- "$DIR/" || return 1
  [ "$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null)" != Z ] || return 1
  echo "$pid"
}

# The node's state as sinfo prints it (idle, mixed, allocated, down*, ...), empty if unknown.
node_state() {
  timeout 5 sinfo -h -n "$NODE" -o %T 2>/dev/null | head -n1 || true
}

# Stop one daemon: TERM, wait up to 10 s, then KILL.
stop_daemon() {
  local name=$1 file=$2 pid
  pid=$(live_pid "$file") || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for _ in $(seq 100); do
    live_pid "$file" >/dev/null || break
    sleep 0.1
  done
  if live_pid "$file" >/dev/null; then
    kill -KILL "$pid" 2>/dev/null || true
    echo "$PROG: $name (pid $pid) did not stop in 10 s; killed"
  fi
  rm -f "$file"
}

do_stop() {
  [ -f "$CONF" ] || { echo "$PROG: no cluster in $DIR"; return 0; }
  # Jobs first, so no job step outlives its slurmd.
  if live_pid "$RUN/slurmctld.pid" >/dev/null; then
    local jobs
    jobs=$(timeout 5 squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ' || true)
    if [ -n "${jobs// /}" ]; then
      # shellcheck disable=SC2086 # job ids, one word each
      timeout 5 scancel $jobs 2>/dev/null || true
      for _ in $(seq 50); do
        [ -z "$(timeout 5 squeue -h -o %A 2>/dev/null || true)" ] && break
        sleep 0.1
      done
    fi
  fi
  stop_daemon slurmd "$RUN/slurmd.pid"
  stop_daemon slurmctld "$RUN/slurmctld.pid"
  stop_daemon munged "$RUN/munged.pid"
  echo "$PROG: stopped the cluster in $DIR"
}

# Prints the node's hardware as slurm.conf wants it, from slurmd -C (what slurmd will report,
# so the node is never drained for a mismatch), else from nproc and /proc/meminfo.
node_hardware() {
  local line
  line=$(slurmd -C 2>/dev/null | head -n1 || true)
  if [[ $line == NodeName=* ]]; then
    echo "$line" | tr ' ' '\n' | grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore|RealMemory)=' | paste -sd ' '
  else
    echo "CPUs=$(nproc) RealMemory=$(awk '/^MemTotal/ {print int($2 / 1024)}' /proc/meminfo)"
  fi
}

# Two free TCP ports on localhost (bound then released: another cluster takes other ports).
free_ports() {
  python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks:
    s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in socks))'
}

write_conf() {
  local hw cpus mem ctld_port slurmd_port
  hw=$(node_hardware)
  cpus=$(echo "$hw" | tr ' ' '\n' | sed -n 's/^CPUs=//p')
  mem=$(echo "$hw" | tr ' ' '\n' | sed -n 's/^RealMemory=//p')
  read -r ctld_port slurmd_port <<<"$(free_ports)"
  cat >"$CONF.tmp" <<EOF
# Generated by scripts/slurm/local_cluster.sh: a single-node cluster in $DIR.
ClusterName=proxyvis
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$RUN/munge.sock
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$RUN/slurmctld.pid
SlurmdPidFile=$RUN/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
# No cgroups (containers rarely delegate them): processes tracked by parent pid, no binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
# No accounting database: job records live in slurmctld until MinJobAge expires.
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MinJobAge=600
MpiDefault=none
MailProg=/bin/true
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
# Without a default, a job without --mem would take the whole node's memory (one job at a time).
DefMemPerCPU=$((mem / cpus))
SchedulerType=sched/backfill
# Schedule batch jobs (array tasks) as soon as they are submitted or resources free up.
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=$NODE NodeAddr=127.0.0.1 NodeHostname=$(hostname) $hw State=UNKNOWN
PartitionName=$PARTITION Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
EOF
  mv "$CONF.tmp" "$CONF"
}

# Last lines of a log, indented, for a failure message.
log_tail() {
  # The MPI plugins' complaints (no PMIx library) are noise here: jobs use no MPI.
  if [ -f "$1" ]; then
    grep -v 'pmix\|MPI:' "$1" | tail -n 5 | sed 's/^/    /' >&2 || true
  fi
}

# Prints why Slurm cannot run here, or nothing.
unavailable_reason() {
  local missing=() b
  for b in munged munge slurmctld slurmd sinfo squeue sbatch scancel scontrol python3; do
    command -v "$b" >/dev/null 2>&1 || missing+=("$b")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "missing programs: ${missing[*]} (install the Debian packages slurm-wlm and munge: ./setup.sh)"
  elif [ "$(id -u)" -ne 0 ]; then
    echo "needs root: slurmd starts job steps as their user (run as root)"
  fi
}

# Starts a daemon and waits up to 5 s for its pid file to name a live process.
start_daemon() {
  local name=$1 pidfile=$2 log=$3
  shift 3
  "$@" >>"$DIR/log/$name.out" 2>&1 || true
  for _ in $(seq 50); do
    live_pid "$pidfile" >/dev/null && return 0
    sleep 0.1
  done
  echo "$PROG: error: $DIR: $name did not start; it exited at once (see $log)" >&2
  log_tail "$log"
  log_tail "$DIR/log/$name.out"
  do_stop >/dev/null
  exit 4
}

do_start() {
  local why t0 state=""
  # munged serves its socket only from a folder whose every parent anyone can search.
  local up
  up=$(dirname "$DIR")
  while [ "$up" != / ]; do
    if [ -d "$up" ] && [ "$(($(stat -c %#a "$up") & 1))" -eq 0 ]; then
      fail 1 "munged would refuse its socket there; the parent folder $up is not searchable by all (chmod o+x it, or use another --dir)"
    fi
    up=$(dirname "$up")
  done
  why=$(unavailable_reason)
  [ -z "$why" ] || fail 4 "Slurm cannot run here; $why"
  if live_pid "$RUN/slurmctld.pid" >/dev/null || live_pid "$RUN/slurmd.pid" >/dev/null ||
    live_pid "$RUN/munged.pid" >/dev/null; then
    fail 1 "a cluster is already running there; one per folder (run '$PROG --dir $DIR stop' first)"
  fi
  t0=$(date +%s.%N)
  # The folder is readable by all (munged wants its socket folder searchable); the key is not.
  mkdir -p "$DIR" "$RUN" "$DIR/state" "$DIR/spool" "$DIR/log" "$DIR/munge"
  chmod 755 "$DIR" "$RUN"
  chmod 700 "$DIR/munge" "$DIR/state" "$DIR/spool"
  if [ ! -s "$DIR/munge/munge.key" ]; then
    (umask 077 && head -c 1024 /dev/urandom >"$DIR/munge/munge.key.tmp" &&
      mv "$DIR/munge/munge.key.tmp" "$DIR/munge/munge.key")
  fi
  chmod 400 "$DIR/munge/munge.key"
  write_conf

  start_daemon munged "$RUN/munged.pid" "$DIR/munge/munged.log" \
    munged --key-file="$DIR/munge/munge.key" --socket="$RUN/munge.sock" \
    --pid-file="$RUN/munged.pid" --log-file="$DIR/munge/munged.log" \
    --seed-file="$DIR/munge/munged.seed"
  start_daemon slurmctld "$RUN/slurmctld.pid" "$DIR/log/slurmctld.log" slurmctld -f "$CONF"
  start_daemon slurmd "$RUN/slurmd.pid" "$DIR/log/slurmd.log" slurmd -f "$CONF" -N "$NODE"

  for _ in $(seq $((START_TIMEOUT * 5))); do
    state=$(node_state)
    if [ "$state" = idle ]; then
      printf '%s: cluster up in %.1f s: node %s idle (%s); export SLURM_CONF=%s\n' "$PROG" \
        "$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" "$NODE" "$(node_hardware)" "$CONF"
      return 0
    fi
    if ! live_pid "$RUN/slurmctld.pid" >/dev/null || ! live_pid "$RUN/slurmd.pid" >/dev/null; then
      break
    fi
    sleep 0.2
  done
  echo "$PROG: error: $DIR: node $NODE not idle (state '${state:-unknown}') after start; a daemon died or refused the node (see $DIR/log)" >&2
  log_tail "$DIR/log/slurmctld.log"
  log_tail "$DIR/log/slurmd.log"
  do_stop >/dev/null
  exit 4
}

do_status() {
  local ok=0 name pid state
  [ -f "$CONF" ] || { echo "$PROG: no cluster in $DIR"; return 1; }
  for name in munged slurmctld slurmd; do
    if pid=$(live_pid "$RUN/$name.pid"); then
      echo "$name: running (pid $pid)"
    else
      echo "$name: not running"
      ok=1
    fi
  done
  state=$(node_state)
  echo "node $NODE: ${state:-unknown}"
  case $state in idle | mixed | allocated | completing) ;; *) ok=1 ;; esac
  return $ok
}

case $cmd in
  start) do_start ;;
  stop) do_stop ;;
  status) do_status ;;
  env) printf 'export SLURM_CONF=%q\n' "$CONF" ;;
esac
