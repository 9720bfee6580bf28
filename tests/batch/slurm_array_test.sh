#!/usr/bin/env bash
# A real Slurm cluster of one node on this machine runs tools/slurm/submit.sh
# on three scenes: the job array solves them, the summary job lists three
# solved scenes. Debian's slurmctld, slurmd and munge are installed when
# missing (as root); every daemon runs from a scratch directory with a
# generated configuration on free ports, and is stopped at the end.
#
#   slurm_array_test.sh REGIO_SOLVE SOURCE_DIR
# Exit 77 (CTest: skipped) with the reason where Slurm cannot be run.
set -euo pipefail
regio_solve=$1; source_dir=$2
skip() { echo "SKIPPED: $*"; exit 77; }

packages=(slurmctld slurmd slurm-client munge)
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null ||
   ! command -v sbatch >/dev/null; then
  [ "$(id -u)" -eq 0 ] || skip "Slurm is not installed and installing it needs root: apt-get install ${packages[*]}"
  command -v apt-get >/dev/null || skip "Slurm is not installed and there is no apt-get to install it"
  echo "installing ${packages[*]} from Debian's archive"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null 2>&1 ||
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null; } ||
    skip "apt-get could not install ${packages[*]}"
fi
[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start jobs"

work=$(mktemp -d /tmp/regio-slurm-test.XXXXXX)
stop_daemons() {
  for daemon in slurmd slurmctld munged; do
    [ -f "$work/$daemon.pid" ] && kill "$(cat "$work/$daemon.pid")" 2>/dev/null || true
  done
  for daemon in slurmd slurmctld munged; do
    for _ in $(seq 50); do
      [ -f "$work/$daemon.pid" ] && kill -0 "$(cat "$work/$daemon.pid")" 2>/dev/null || break
      sleep 0.1
    done
  done
}
show_logs() {
  for log in "$work"/*.log "$work"/out/slurm/*.out; do
    [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }
  done
}
trap 'status=$?; [ $status -ne 0 ] && [ $status -ne 77 ] && show_logs; stop_daemons; rm -rf "$work"; exit $status' EXIT

# munge: its own key and socket.
mkdir -p "$work/state" "$work/spool"
mungekey --create --keyfile="$work/munge.key" --bits=1024
chmod 400 "$work/munge.key"
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munge.seed"

# Two free ports for the controller and the node daemon.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
cpus=$(nproc)
export SLURM_CONF="$work/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=regiotest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=regio Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
  sinfo -h -o %t 2>/dev/null | grep -qx idle && break
  sleep 0.5
done
sinfo -h -o %t | grep -qx idle || { echo "the node did not come up"; exit 1; }

# Three variants of the Cornell box, quick to solve.
"$regio_solve" sweep "$source_dir/resources/scenes/cornell-box.json" --set solver.hemicube=40,60,80 \
  --out-dir "$work/scenes" -q
out="$work/out"
fail() { echo "FAILED: $*"; exit 1; }
# Submits the three scenes and waits (bounded) for the array and the summary
# job to leave the queue; sets array_job.
submit_and_wait() {
  REGIO_SOLVE=$regio_solve "$source_dir/tools/slurm/submit.sh" --cpus 1 "$work/scenes" "$out" -- \
    --iterations 20 --adaptive off --format png --size 64x48 | tee "$work/submit.txt"
  local jobs
  jobs=$(sed -n 's/^submitted job array \([0-9]*\) .* summary job \([0-9]*\)$/\1,\2/p' "$work/submit.txt")
  [ -n "$jobs" ] || fail "submit.sh did not say which jobs it submitted"
  array_job=${jobs%%,*}
  for _ in $(seq 240); do
    [ -z "$(squeue -h -j "$jobs" 2>/dev/null)" ] && return 0
    sleep 0.5
  done
  squeue
  fail "the jobs did not finish within 120 s"
}
submit_and_wait

for n in 001 002 003; do
  report="$out/cornell-box-$n.report.json"
  [ -f "$report" ] || fail "no report $report"
  grep -q '"status": "solved"' "$report" || fail "$report does not say solved"
  [ -s "$out/cornell-box-$n.png" ] || fail "no picture for cornell-box-$n"
done
[ -f "$out/summary.txt" ] || fail "the summary job wrote no summary.txt"
cat "$out/summary.txt"
grep -q "^3 scenes: 3 solved, 0 skipped, 0 failed" "$out/summary.txt" || fail "the summary does not list three solved scenes"
python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["counts"]; sys.exit(0 if c["solved"] == 3 else 1)' \
  "$out/summary.json" || fail "summary.json does not count three solved scenes"
echo "the job array solved three scenes and the summary lists them"

# Submitted again, every task finds its scene solved and skips it.
submit_and_wait
for task in 0 1 2; do
  grep -q "skipped" "$out/slurm/${array_job}_$task.out" || fail "task $task of the second array solved again"
done
grep -q "^3 scenes: 3 solved" "$out/summary.txt" || fail "the second summary does not list three solved scenes"
echo "submitted again, the array skipped all three"
