#!/bin/sh
# Issue 21: a jobs file is checked against its plan before any job runs. Every line must be a job
# that `sweep plan` writes for the plan the line carries; an edited or foreign line is a typed error
# (exit 2) naming the line, and nothing runs. The cases: an id that would name a folder outside the
# run's folder (a report job empties DIR/report/ID before it runs: the folder beside must survive),
# a range of 10^9 cases, a proof this splinex lacks, a limit raised in the plan, and a plan too
# large to write. Unedited plans (with their lines in another order) are read.
set -u
CLI=$1
W=$2
rm -rf "$W"
mkdir -p "$W/keep"
touch "$W/keep/file"
fails() {  # $1: jobs file, $2: the expected start of the error
  out=$($CLI sweep run --jobs "$1" --dir "$W/run" --quiet 2>&1)
  rc=$?
  if [ $rc -ne 2 ] || ! printf '%s\n' "$out" | grep -q "^splinex: error: $2"; then
    echo "FAIL: $1 gave exit $rc: $out"
    exit 1
  fi
}
$CLI sweep plan report --sections tolerance > "$W/report.jsonl"
sed 's#"id":"tolerance"#"id":"../../keep"#' "$W/report.jsonl" > "$W/escape.jsonl"
fails "$W/escape.jsonl" "jobs line 1: '../../keep' is not a job of its plan"
test -f "$W/keep/file" || { echo "FAIL: the folder beside was removed"; exit 1; }
$CLI sweep plan proofs --cases 4 --cases-per-job 2 > "$W/proofs.jsonl"
sed '3s#"count":2#"count":1000000000#' "$W/proofs.jsonl" > "$W/count.jsonl"
fails "$W/count.jsonl" "jobs line 3: '[a-z0-9.-]*' is not a job of its plan"
sed '1s#"name":"[a-z0-9.-]*"#"name":"no-such-proof"#' "$W/proofs.jsonl" > "$W/name.jsonl"
fails "$W/name.jsonl" "jobs line 1: '[a-z0-9.-]*' is not a job of its plan"
$CLI sweep plan untrim-tolerance --eps 1e-2 --runs 0:1e-2:1 > "$W/untrim.jsonl"
sed 's#"max_control_points":20000000#"max_control_points":900000000000#' "$W/untrim.jsonl" > "$W/limit.jsonl"
cmp -s "$W/untrim.jsonl" "$W/limit.jsonl" && { echo "FAIL: the limit edit did not apply"; exit 1; }
fails "$W/limit.jsonl" "jobs line 1.plan: is not a plan that this splinex writes"
out=$($CLI sweep plan proofs --cases 100000 --cases-per-job 1 2>&1 > /dev/null)
printf '%s\n' "$out" | grep -q "^splinex: error: cases-per-job: 100000 cases in ranges of 1 make [0-9]* jobs, more than 1000000" ||
  { echo "FAIL: a plan of millions of jobs: $out"; exit 1; }
# unedited plans, reversed, are read (the run of a job that does not exist is refused after reading)
for f in report proofs untrim; do
  sed -n '1!G;h;$p' "$W/$f.jsonl" > "$W/$f.rev.jsonl"
  out=$($CLI sweep run --jobs "$W/$f.rev.jsonl" --only no-such-id --dir "$W/run" 2>&1)
  printf '%s\n' "$out" | grep -q "^splinex: error: only: 'no-such-id' is no job of the plan" || { echo "FAIL: $f: $out"; exit 1; }
done
test ! -e "$W/run" || { echo "FAIL: something ran"; exit 1; }
echo "edited jobs refused before any work"
