#!/bin/sh
# Issue 21: a small untrimming tolerance sweep (15 jobs, its slope checks pass) planned as jobs, run in 1, 2 and 3 shards
# (xargs -P) and on 2 threads of one process, merged;
# each merge must equal the single-process run (the report's code path) byte for byte, timings
# aside (the CSV's cpu_seconds column and the seconds in the Markdown's cost line). Then resumption
# (a second run skips every job), a missing job (the merge names it, exit 2) and a failing job (the
# others finish; a rerun retries it).
set -eu
CLI=$1
W=$2
PLAN="--eps 1e-2,1e-3,1e-4 --runs 0:1e-4:4,64:1e-4:1"
rm -rf "$W"
mkdir -p "$W"
$CLI sweep plan untrim-tolerance $PLAN > "$W/jobs.jsonl"
test "$(wc -l < "$W/jobs.jsonl")" -eq 15
# the sweep's own checks (the fitted slopes) may fail on so small a plan: exit 1; the merges must
# give the same status
rc_single=0
$CLI sweep single untrim-tolerance $PLAN --out "$W/single" > /dev/null 2>&1 || rc_single=$?
test $rc_single -le 1
untimed() {  # the files of a run without their timings
  cut -d, -f1-9,11- "$1/untrim_tolerance.csv"
  sed -E 's/[0-9][0-9.e+-]* s([;.])/T s\1/g' "$1/untrim_tolerance.md"
  cat "$1/untrim_tolerance.svg" "$1/untrim_tolerance_cost.svg"
}
untimed "$W/single" > "$W/single.txt"
test -s "$W/single.txt"
for n in 1 2 3; do
  # the shards in parallel on this machine's cores (xargs -P), as docs/sweep.md shows
  seq 0 $((n - 1)) | xargs -P "$n" -I{} $CLI sweep run --jobs "$W/jobs.jsonl" --shard {}/$n --dir "$W/jobs$n" --quiet > /dev/null
  rc=0
  $CLI sweep merge --jobs "$W/jobs.jsonl" "$W/jobs$n" --out "$W/merged$n" > /dev/null || rc=$?
  test $rc -eq $rc_single
  untimed "$W/merged$n" > "$W/merged$n.txt"
  cmp "$W/single.txt" "$W/merged$n.txt"
done
# two threads in one process: the same merge
$CLI sweep run --jobs "$W/jobs.jsonl" --threads 2 --dir "$W/threads" --quiet > /dev/null
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/threads" --out "$W/merged_threads" > /dev/null
untimed "$W/merged_threads" > "$W/merged_threads.txt"
cmp "$W/single.txt" "$W/merged_threads.txt"
# resumption: everything is there, nothing runs
$CLI sweep run --jobs "$W/jobs.jsonl" --dir "$W/jobs3" --quiet | grep -q '"run":0,"shard":"0/1","skipped":15'
# a folder of another plan is refused, not skipped or merged silently
$CLI sweep plan untrim-tolerance --eps 1e-2 --runs 0:1e-2:1 > "$W/other.jsonl"
set +e
$CLI sweep run --jobs "$W/other.jsonl" --dir "$W/jobs3" --quiet > /dev/null 2> "$W/other.txt"
rc=$?
set -e
test $rc -eq 2
grep -q "^splinex: error: untrim-tolerance/m1-double-eps0.01.json: is not the result of job m1-double-eps0.01 under this plan" "$W/other.txt"
# a missing job is named by the merge
rm "$W/jobs2/untrim-tolerance/m2-double-eps0.001.json"
set +e
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/jobs2" > /dev/null 2> "$W/missing.txt"
rc=$?
set -e
test $rc -eq 2
grep -q "^splinex: error: jobs: 1 of 15 jobs have no output in .*: m2-double-eps0.001" "$W/missing.txt"
# a failing job does not stop the others: it is named on stderr at once and at the end (exit 2),
# leaves no output, and a rerun of the plan retries only it. The job fails for real: a folder
# stands where its output's temporary file goes, so its output cannot be written.
mkdir -p "$W/failing/untrim-tolerance/m2-double-eps0.01.json.tmp"
set +e
$CLI sweep run --jobs "$W/jobs.jsonl" --threads 2 --dir "$W/failing" > /dev/null 2> "$W/failing.txt"
rc=$?
set -e
test $rc -eq 2
grep -q '^\[sweep\] [0-9]*/15 m2-double-eps0.01: FAILED: .*cannot write the file' "$W/failing.txt"
grep -q "^splinex: error: jobs: 1 of 15 jobs of shard 0/1 failed (the others finished): m2-double-eps0.01 (" "$W/failing.txt"
test "$(ls "$W/failing/untrim-tolerance" | grep -c 'json$')" -eq 14
test ! -e "$W/failing/untrim-tolerance/m2-double-eps0.01.json"
rmdir "$W/failing/untrim-tolerance/m2-double-eps0.01.json.tmp"
$CLI sweep run --jobs "$W/jobs.jsonl" --dir "$W/failing" --quiet | grep -q '"run":1,"shard":"0/1","skipped":14'
rc=0
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/failing" --out "$W/merged_failing" > /dev/null || rc=$?
test $rc -eq $rc_single
untimed "$W/merged_failing" > "$W/merged_failing.txt"
cmp "$W/single.txt" "$W/merged_failing.txt"
echo "sweep: 1, 2 and 3 shards and 2 threads merged identical to the single run (timings aside); resumption, a missing and a failing job checked"
