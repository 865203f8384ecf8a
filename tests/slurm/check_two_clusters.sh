#!/usr/bin/env bash
# Two private one-node Slurm clusters on this machine at once (as when two engineers run the test
# suite), each running a 2-rank job of cluster/sweetspot.slurm (check_slurm.sh --one-job): both
# must end. While each cluster numbered its jobs from 1, both jobs were job 1 with one PMIx
# namespace, so one Open MPI job id and one set of shared-memory segments: a rank crashed or
# both ranks of a job waited in MPI_Probe forever (the "2-rank resume hangs" of check_slurm.sh).
# Exit 77 when Slurm or munge is absent, as check_slurm.sh.
# Usage: check_two_clusters.sh PROGRAM SOURCE_DIR
set -uo pipefail
here=$(dirname "$(realpath "$0")")
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT

bash "$here/check_slurm.sh" "$1" "$2" --one-job >"$logs/a" 2>&1 &
a=$!
bash "$here/check_slurm.sh" "$1" "$2" --one-job >"$logs/b" 2>&1 &
b=$!
wait "$a"; status_a=$?
wait "$b"; status_b=$?
for cluster in a b; do echo "=== cluster $cluster"; cat "$logs/$cluster"; done
if [ "$status_a" -eq 77 ] || [ "$status_b" -eq 77 ]; then exit 77; fi
[ "$status_a" -eq 0 ] && [ "$status_b" -eq 0 ]
