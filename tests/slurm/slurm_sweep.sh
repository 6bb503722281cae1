#!/bin/bash
# Issue 21, the Slurm path for real (long label): a single-node Slurm started on this machine
# (scripts/slurm/local_slurm.sh: munged, slurmctld, slurmd on the loopback interface), a small
# untrimming tolerance sweep submitted as an array of 3 shards with a dependent merge
# (scripts/slurm/sweep.sbatch, the commands docs/sweep.md gives), waited for, and the merged files
# compared with the single-process run, timings aside. Slurm is shut down at the end.
# Also GNU parallel over 4 shards. Needs root and Debian's slurm-wlm, munge and parallel
# (scripts/run.sh long installs them).
set -euo pipefail
CLI=$(realpath "$1")
SRC=$(realpath "$2")
W=$(realpath -m "$3")
PLAN="--eps 1e-2,1e-3,1e-4 --runs 0:1e-4:4,64:1e-4:1"
rm -rf "$W"
mkdir -p "$W"
cleanup() { "$SRC/scripts/slurm/local_slurm.sh" stop "$W/slurm" || true; }
trap cleanup EXIT
eval "$("$SRC/scripts/slurm/local_slurm.sh" start "$W/slurm")"
cd "$W"
"$CLI" sweep plan untrim-tolerance $PLAN > jobs.jsonl
"$CLI" sweep single untrim-tolerance $PLAN --out single > /dev/null 2>&1
jid=$(SPLINEX="$CLI" sbatch --parsable --export=ALL --array=0-2 "$SRC/scripts/slurm/sweep.sbatch" jobs.jsonl sweep merged)
mid=$(SPLINEX="$CLI" sbatch --parsable --export=ALL --dependency=afterany:"$jid" "$SRC/scripts/slurm/sweep.sbatch" jobs.jsonl sweep merged)
for _ in $(seq 1 600); do
  if [ -z "$(squeue -h -o %i)" ]; then break; fi
  sleep 1
done
test -z "$(squeue -h -o %i)" || { echo "slurm_sweep: jobs still queued after 600 s" >&2; squeue >&2; exit 1; }
state() { scontrol show job "$1" 2> /dev/null | grep -o 'JobState=[A-Z]*' | sort -u | tr '\n' ' '; }
echo "array $jid: $(state "$jid"); merge $mid: $(state "$mid")"
test "$(state "$jid")" = "JobState=COMPLETED "
test "$(state "$mid")" = "JobState=COMPLETED "
ls slurm-*.out > /dev/null
untimed() {
  cut -d, -f1-9,11- "$1/untrim_tolerance.csv"
  sed -E 's/[0-9][0-9.e+-]* s([;.])/T s\1/g' "$1/untrim_tolerance.md"
  cat "$1/untrim_tolerance.svg" "$1/untrim_tolerance_cost.svg"
}
untimed single > single.txt
untimed merged > merged.txt
cmp single.txt merged.txt
# GNU parallel over 4 shards on this machine: the same merge
parallel "$CLI" sweep run --jobs jobs.jsonl --shard {}/4 --dir gnu --quiet ::: 0 1 2 3 > /dev/null
"$CLI" sweep merge --jobs jobs.jsonl gnu --out gnu-merged > /dev/null
untimed gnu-merged > gnu.txt
cmp single.txt gnu.txt
test "$(ls sweep/untrim-tolerance | wc -l)" -eq 15
echo "slurm: 15 jobs in a 3-task array and a dependent merge on a local Slurm, and GNU parallel over 4 shards, merged identical to the single run (timings aside)"
