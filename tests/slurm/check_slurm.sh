#!/usr/bin/env bash
# cluster/sweetspot.slurm under a real one-node Slurm (Debian's slurmctld, slurmd, munge), as
# root in CI: a private cluster in a temporary directory (its own munge socket and key, its own
# ports, MpiDefault=none as Slurm's default, so the script's own --mpi=pmix is what starts the
# ranks), torn down on exit. Checks, against a plain `sweetspot run` of the same study:
#   2 ranks x 1 thread and 1 rank x 2 threads: the job succeeds, the log reports the ranks and
#   threads, each rank's cores without a false warning, and the dataset is bit for bit the same;
#   a rank bound to one core for its 2 threads warns;
#   a job cancelled mid-run (scancel) and submitted again resumes from the journal, same bits;
#   no program to be found: the script says so and fails.
# With --one-job (tests/slurm/check_two_clusters.sh runs two at once): only a 2-rank run of a
# study of a few seconds, which must end.
# Exit 77 (CTest's SKIP_RETURN_CODE) when the Slurm or munge packages are absent.
#
# Usage: check_slurm.sh PROGRAM SOURCE_DIR [--one-job]
set -euo pipefail

program=$(realpath "$1")
source_dir=$(realpath "$2")
one_job=${3:-}
python=/usr/bin/python3

for tool in slurmctld slurmd sbatch srun squeue scancel scontrol sinfo munged mungekey; do
  if ! PATH=$PATH:/usr/sbin command -v "$tool" >/dev/null; then
    echo "SKIP: $tool not installed (Debian: apt-get install slurmctld slurmd slurm-client munge)"
    exit 77
  fi
done
export PATH=$PATH:/usr/sbin

# A short path: munge's socket path must fit in a sockaddr_un (108 bytes).
dir=$(mktemp -d /tmp/sweetspot-slurm.XXXXXX)
chmod 755 "$dir"  # munged wants its socket's directory searchable by all
pids=()
cleanup() {
  local status=$?
  # Jobs first: a job's slurmstepd and tasks outlive slurmd, so cancel every job of this private
  # cluster and wait (a few seconds at most) until they are gone, then stop the daemons.
  if [ -n "${SLURM_CONF:-}" ] && [ "$(squeue -h 2>/dev/null | wc -l)" -gt 0 ]; then
    scancel --user="$(id -un)" 2>/dev/null || true
    for _ in $(seq 100); do
      [ "$(squeue -h 2>/dev/null | wc -l)" -eq 0 ] && break
      sleep 0.1
    done
  fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [ "$status" -ne 0 ]; then
    for log in "$dir"/*.log "$dir"/work/*.log; do
      [ -f "$log" ] && { echo "=== $log"; tail -n 30 "$log"; }
    done
  fi
  rm -rf "$dir"
}
trap cleanup EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Two free TCP ports, and TmpFS (where srun's PMIx plugin makes a directory named by job id) in
# the temporary directory: another test's cluster may run beside this one.
read -r ctld_port slurmd_port < <($python -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in socks))')

# Job ids from a random start, not from 1: srun's PMIx namespace is "slurm.pmix.JOB.STEP", and
# Open MPI names its job, its session directory and its shared-memory segments (/dev/shm/
# vader_segment.HOST.UID.HASH.RANK) after that namespace. Two private clusters on one machine
# (two engineers' test suites) that both number their jobs from 1 run job N at the same time
# under the same names, and their ranks meet in each other's segments: one job's ranks crashed,
# the other's waited in MPI_Probe forever (tests/slurm/check_two_clusters.sh). A job killed
# before MPI_Finalize also leaves its segment behind for the next cluster's job N.
first_job=$(( (RANDOM * 32768 + RANDOM) % 60000000 + 1000 ))  # below Slurm's MaxJobId, 67043328

node=$(hostname -s)
cpus=$(nproc)
user=$(id -un)
mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/tmp" "$dir/work"
chmod 700 "$dir/munge"
mungekey --create --keyfile="$dir/munge/munge.key"
cat >"$dir/slurm.conf" <<CONF
ClusterName=sweetspot-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
TmpFS=$dir/tmp
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
PlugStackConfig=/dev/null
ProctrackType=proctrack/linuxproc
TaskPlugin=task/affinity
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
ReturnToService=2
KillWait=2
FirstJobId=$first_job
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus Sockets=1 CoresPerSocket=$cpus ThreadsPerCore=1 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

munged --foreground --force --socket="$dir/munge/socket" --key-file="$dir/munge/munge.key" \
  --pid-file="$dir/munge/pid" --seed-file="$dir/munge/seed" >>"$dir/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -S "$dir/munge/socket" ] && break; sleep 0.05; done
slurmctld -D -i >>"$dir/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D -N "$node" >>"$dir/slurmd.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 200); do
  [ "$(sinfo -h -o %t 2>/dev/null)" = idle ] && break
  sleep 0.05
done
[ "$(sinfo -h -o %t 2>/dev/null)" = idle ] || fail "the node never became idle: $(sinfo 2>&1)"
echo "slurm up: node $node, $cpus cpus, ports $ctld_port $slurmd_port"

cd "$dir/work"
# A study of a real bat: 54 impact points x 8 ball speeds, a few tenths of a second.
cat >small.toml <<STUDY
title = "sweetspot.slurm under Slurm"
[scene]
bat = "$source_dir/studies/bats/r161.toml"
cm_speed = 0
omega = 0
e0 = 0.5
modes = 18
[axes]
z = { start = 0.305, stop = 0.835, step = 0.01 }
ball_speed = [1, 5, 10, 20, 30, 40, 50, 60]
[output]
variables = ["vf", "e_eff", "contact_time", "status", "energy_vibration"]
STUDY
OMP_NUM_THREADS=1 "$program" run small.toml -o plain.h5 --quiet

# Waits for job $1 to end (polling: sbatch --wait polls every few seconds, which would make this
# test three times as long) and prints its state; succeeds if it completed with exit status 0.
job_state() { scontrol show job "$1" 2>/dev/null | grep -o "JobState=[A-Z_]*" | cut -d= -f2; }
# Gives up after 90 s (a job that hangs fails the test while CTest's time is left for cleanup).
wait_job() {
  local state deadline=$((SECONDS + 90))
  while [ "$SECONDS" -lt "$deadline" ]; do
    state=$(job_state "$1")
    case $state in PENDING | CONFIGURING | RUNNING | COMPLETING | SUSPENDED | "") sleep 0.05 ;; *) break ;; esac
  done
  echo "$state"
  [ "$state" = COMPLETED ]
}

# Submits the script with sbatch OPTIONS... -- ARGUMENTS..., waits for it; prints the log's path.
submit_and_wait() {
  local options=() job state
  while [ "$1" != -- ]; do options+=("$1"); shift; done
  shift
  job=$(SWEETSPOT=$program sbatch --parsable "${options[@]}" "$source_dir/cluster/sweetspot.slurm" "$@")
  state=$(wait_job "$job") || fail "job $job (${options[*]}) ended $state: $(cat "sweetspot-$job.log" 2>/dev/null)"
  echo "sweetspot-$job.log"
}

same_bits() {
  $python "$source_dir/tests/compare_datasets.py" "$1" "$2" >/dev/null || fail "$2 differs from $1"
}

expect() {  # expect LOG PATTERN: the log holds a line matching the extended regex
  grep -Eq -- "$2" "$1" || fail "$1 lacks /$2/:"$'\n'"$(cat "$1")"
}

refuse() {  # refuse LOG PATTERN: no line of the log matches
  if grep -Eq -- "$2" "$1"; then fail "$1 has /$2/:"$'\n'"$(cat "$1")"; fi
}

if [ "$one_job" = --one-job ]; then
  # The 4320 points of long.toml below: a few seconds, so that the other cluster's job overlaps.
  sed 's/^ball_speed = .*/ball_speed = { start = 1, stop = 60, count = 80 }/' small.toml >long.toml
  log=$(submit_and_wait -N1 --ntasks-per-node=2 -c1 -- long.toml one.h5)
  expect "$log" "wrote one.h5: 4320 points"
  echo "ok: one 2-rank job (first job id $first_job)"
  exit 0
fi

# 2 ranks x 1 thread: one core each.
log=$(submit_and_wait -N1 --ntasks-per-node=2 -c1 -- small.toml ranks.h5)
expect "$log" "points on 2 rank\(s\) x 1 thread\(s\)"
expect "$log" "rank 0: 1 OpenMP thread\(s\) on core\(s\) [0-9]+ \(1 allowed\)"
expect "$log" "rank 1: 1 OpenMP thread\(s\) on core\(s\) [0-9]+ \(1 allowed\)"
refuse "$log" "but only"
same_bits plain.h5 ranks.h5
echo "ok: 2 ranks x 1 thread"

# 1 rank x 2 threads: both cores for the rank, each thread pinned to one (OMP_PROC_BIND=close).
log=$(submit_and_wait -N1 --ntasks-per-node=1 -c2 -- small.toml threads.h5)
expect "$log" "points on 1 rank\(s\) x 2 thread\(s\)"
expect "$log" "rank 0: 2 OpenMP thread\(s\) on core\(s\) [0-9]+-[0-9]+ \(2 allowed\)"
refuse "$log" "but only"
same_bits plain.h5 threads.h5
echo "ok: 1 rank x 2 threads"

# The wrong binding the warning is for, a rank with 2 threads bound to one core, as srun without
# --cpus-per-task makes it on Slurm 22.05 with several ranks per node (here, with one rank, this
# srun would still bind both cores, so the step asks for one core outright).
job=$(sbatch --parsable -N1 -n1 -c2 --output=crowded-%j.log \
  --wrap "OMP_NUM_THREADS=2 OMP_PLACES=cores OMP_PROC_BIND=close srun --mpi=pmix --cpus-per-task=1 $program run small.toml -o crowded.h5")
state=$(wait_job "$job") || fail "the crowded job ended $state: $(cat crowded-*.log)"
expect "crowded-$job.log" "rank 0: 2 OpenMP threads but only 1 core\(s\) allowed"
echo "ok: a rank on one core for 2 threads warns"

# Cancelled mid-run, then submitted again: resumes from the journal, same bits as a plain run.
# The same study with 80 ball speeds (4320 points, a second or two), long enough to cancel it once
# its journal holds points (past its 56-byte header) and before it ends.
sed 's/^ball_speed = .*/ball_speed = { start = 1, stop = 60, count = 80 }/' small.toml >long.toml
OMP_NUM_THREADS=1 "$program" run long.toml -o long_plain.h5 --quiet &
plain_pid=$!
job=$(SWEETSPOT=$program sbatch --parsable -N1 --ntasks-per-node=2 -c1 "$source_dir/cluster/sweetspot.slurm" long.toml long.h5)
for _ in $(seq 400); do
  [ "$(stat -c %s long.h5.journal 2>/dev/null || echo 0)" -gt 100 ] && break
  sleep 0.025
done
scancel "$job"
state=$(wait_job "$job") || true
[ "$state" = CANCELLED ] || fail "job $job ended $state, not CANCELLED"
[ -f long.h5.journal ] || fail "the cancelled job left no journal (did it end before the cancel?)"
[ ! -f long.h5 ] || fail "the cancelled job finished before the cancel: make long.toml longer"
# Submitted again as 2 ranks x 1 thread. (It hung here, both ranks in MPI_Probe, while job ids
# started from 1: see first_job above.)
log=$(submit_and_wait -N1 --ntasks-per-node=2 -c1 -- long.toml long.h5)
expect "$log" "points on 2 rank\(s\) x 1 thread\(s\)"
expect "$log" "resuming: [1-9][0-9]* of 4320 points already done"
wait "$plain_pid"
same_bits long_plain.h5 long.h5
echo "ok: cancelled and resubmitted, resumed"

# No program: the script says how to give one, and fails.
mkdir empty && cd empty
job=$(env -u SWEETSPOT PATH=/usr/bin:/bin sbatch --parsable -N1 --ntasks-per-node=1 -c1 "$source_dir/cluster/sweetspot.slurm" x.toml)
state=$(wait_job "$job") || true
[ "$state" = FAILED ] || fail "the job without a program ended $state, not FAILED"
expect sweetspot-*.log "sweetspot.slurm: error: no program at $dir/work/empty/build/sweetspot"
echo "ok: no program, a clear error"
