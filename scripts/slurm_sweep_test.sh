#!/usr/bin/env bash
# Runs a small `ncinterp sweep` grid through a single-node Slurm cluster started here
# (munged, slurmctld and slurmd on localhost, all under a temporary directory) and checks
# that the collected tables equal those of the same grid run in process.
# Idea: the Slurm runner is only `ncinterp sweep --plan --slurm` (a job array whose task i
# runs line i of jobs.txt, i.e. `ncinterp sweep --run-one KEY --cache DIR`) and
# `ncinterp sweep --collect DIR`; if a real scheduler, running the tasks in its own order
# and processes, collects to the same bytes, the runner is right. Not run in CI (it needs
# root and the slurm-wlm and munge packages: apt-get install slurm-wlm munge); its output
# is in docs/bit-widths.md. Stops only the daemons it started, by their process ids.
#
#   scripts/slurm_sweep_test.sh [BUILD_DIR]      (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
ncinterp="$build/ncinterp"
for tool in munged mungekey slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || { echo "slurm_sweep_test: $tool not found (apt-get install slurm-wlm munge)" >&2; exit 2; }
done
[ -x "$ncinterp" ] || { echo "slurm_sweep_test: no $ncinterp (build the ncinterp target)" >&2; exit 2; }

work=$(mktemp -d /tmp/ncinterp_slurm.XXXXXX)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
}
trap cleanup EXIT

# munge: a key and a daemon of our own (socket, pid and log under $work).
mkdir -p "$work/munge" && chmod 700 "$work/munge"
mungekey --create --keyfile="$work/munge/munge.key" >/dev/null 2>&1 || mungekey -c -k "$work/munge/munge.key"
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
       --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/seed" \
       >"$work/munge/munged.out" 2>&1 &
pids+=($!)

cpus=$(nproc)
cat >"$work/slurm.conf" <<EOF
ClusterName=ncinterp
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=localhost CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
mkdir -p "$work/state" "$work/spool"
export SLURM_CONF="$work/slurm.conf"
sleep 1
slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 1
done
sinfo -h -o '%P %t %c' || { echo "slurm_sweep_test: the cluster did not come up; logs in $work" >&2; trap - EXIT; cleanup; exit 1; }

# The grid: 3 widths x 2 position widths x 2 BLU on two inputs; no synthesis (seconds per
# point), the point code path is the same with it.
inputs=("$root/examples/contours/circle_r50.json" "$root/examples/contours/profile.json")
grid=(--widths 10:12 --pos-widths 16,32 --blu 0.001,0.01 --no-synth --no-rtl --feed 20000 --reader-cps 100000)

echo "== in process"
start=$(date +%s.%N)
nice -n 19 "$ncinterp" sweep "${inputs[@]}" "${grid[@]}" --cache "$work/local" --jobs 2 --csv "$work/local.csv" \
  --pareto-csv "$work/local_front.csv" >/dev/null
echo "in process: $(echo "$(date +%s.%N) - $start" | bc) s"

echo "== through Slurm"
start=$(date +%s.%N)
"$ncinterp" sweep "${inputs[@]}" "${grid[@]}" --cache "$work/slurm" --plan --slurm
sbatch --wait --quiet "$work/slurm/sweep.sbatch"
echo "Slurm job array: $(echo "$(date +%s.%N) - $start" | bc) s, $(ls "$work/slurm/points" | wc -l) result files"
"$ncinterp" sweep --collect "$work/slurm" --csv "$work/slurm.csv" --pareto-csv "$work/slurm_front.csv" >/dev/null

status=0
for t in "" _front; do
  if cmp -s "$work/local$t.csv" "$work/slurm$t.csv"; then
    echo "tables equal: local$t.csv == slurm$t.csv ($(($(wc -l <"$work/local$t.csv") - 1)) rows)"
  else
    echo "tables DIFFER: local$t.csv slurm$t.csv" >&2
    diff "$work/local$t.csv" "$work/slurm$t.csv" | head -20 >&2
    status=1
  fi
done
[ $status -eq 0 ] && rm -rf "$work" || echo "kept $work"
exit $status
