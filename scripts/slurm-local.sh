#!/usr/bin/env bash
# Stand up a real one-node SLURM cluster on this machine, run a small
# spinball campaign on it as a job array with a dependent merge job, and
# check that every merged result equals a single-process run bitwise.
#
#   scripts/slurm-local.sh            # needs root (apt-get) unless slurm and munge are installed
#   SPINBALL=/path/to/spinball scripts/slurm-local.sh
#
# Debian's slurm-wlm (22.05 on bookworm) with a generated munge key,
# ProctrackType=proctrack/linuxproc and TaskPlugin=task/none runs in a VM
# or container without cgroups. Everything lives in a temporary directory;
# the daemons this script started are stopped by their process ids on exit.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

say() { printf '[slurm-local] %s\n' "$*"; }

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  say "installing slurm-wlm and munge"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -q slurm-wlm munge >/dev/null 2>&1 ||
    { apt-get update -q >/dev/null && apt-get install -y -q slurm-wlm munge >/dev/null; }
fi

if [ -z "${SPINBALL:-}" ]; then
  say "building the spinball binary"
  cargo build --release --quiet -p spinball-cli
  SPINBALL=$root/target/release/spinball
fi

work=$(mktemp -d /tmp/spinball-slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
  done
  if [ "${KEEP:-0}" = 1 ]; then say "kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT

# munge: a fresh key and a private socket.
mkdir -p "$work/munge"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
  --seed-file="$work/munge/munged.seed"
for _ in $(seq 50); do [ -s "$work/munge/munged.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$work/munge/munged.pid")")

node=$(hostname -s)
mkdir -p "$work/state" "$work/spool"
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=spinball
SlurmctldHost=$node(127.0.0.1)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -i
for _ in $(seq 100); do [ -s "$work/slurmctld.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$work/slurmctld.pid")")
slurmd
for _ in $(seq 100); do [ -s "$work/slurmd.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$work/slurmd.pid")")
for _ in $(seq 150); do
  sinfo -h -o '%t' 2>/dev/null | grep -qE '^idle' && break
  sleep 0.2
done
sinfo -h -o '%t' | grep -qE '^idle' || { say "the node did not come up"; cat "$work"/slurm*.log; exit 1; }
say "one-node cluster up: $(sinfo -h -o '%N %c CPUs %t')"

# The campaign: 2 tables x 2 alphas x 3 shards = 12 tasks.
campaign=$work/campaign
run=(--alpha 0,0.5 --ics 14 --collisions 600 --method tangent --seed 5)
"$SPINBALL" slurm --table stadium:a=1 --and-table docs/tables/mushroom.toml "${run[@]}" \
  --shards 3 --time 5 --cpus-per-task 1 --dir "$campaign" --spinball "$SPINBALL"
cd "$campaign"
start=$SECONDS
array=$(sbatch --parsable --wait array.sbatch) || { say "the array failed"; tail -n 20 logs/*; exit 1; }
sbatch --parsable --wait --dependency=afterok:"${array%%;*}" merge.sbatch >/dev/null ||
  { say "the merge job failed"; tail -n 20 logs/*; exit 1; }
say "array job $array and its merge job finished in $((SECONDS - start)) s"

# The same runs in one process each, compared with the merged results.
cd "$root"
t=0
for table in stadium:a=1 docs/tables/mushroom.toml; do
  a=0
  for alpha in 0 0.5; do
    single=$work/single_t${t}_a${a}.json
    "$SPINBALL" lyapunov --table "$table" --alpha "$alpha" --ics 14 --collisions 600 \
      --method tangent --seed 5 --quiet --json "$single"
    python3 - "$campaign/results/t${t}_a${a}.json" "$single" <<'PY'
import json, sys
merged, single = (json.load(open(p)) for p in sys.argv[1:3])
for doc in (merged, single):
    for p in doc["points"]:
        p.pop("wall_time_s")
assert merged == single, f"{sys.argv[1]} differs from {sys.argv[2]}"
PY
    say "$table alpha=$alpha: merged shards == single run (bitwise)"
    a=$((a + 1))
  done
  t=$((t + 1))
done
say "passed"
