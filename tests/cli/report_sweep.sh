#!/bin/sh
# Issue 21: the report as a sweep. Five sections (crosscheck with composition-orders is one job,
# as they share a seeded stream) planned as jobs, run in 2 shards (xargs -P) and on 2
# threads of one process, merged; each merge must equal `splinex report --sections ... --jobs 1`
# file for file, times aside: the numbers before " s" in report.md, the crosscheck's seconds_exact
# and seconds_float in its CSV, JSON and tables (the last two columns of its rows, every number of
# its time table). Then resumption with the
# leftovers of an interrupted job (its folder is emptied before it runs again), a file a result
# names but the folder lacks (the merge names it, exit 2), and the plan's typed errors.
set -eu
CLI=$1
W=$2
rm -rf "$W"
mkdir -p "$W"
S=checkerboard,crosscheck,composition-orders,elevation-accuracy,hybrid
$CLI sweep plan report --sections $S > "$W/jobs.jsonl"
test "$(wc -l < "$W/jobs.jsonl")" -eq 4
grep -q '"id":"crosscheck+composition-orders"' "$W/jobs.jsonl"
$CLI report --out "$W/report" --sections $S --jobs 1 2> "$W/report.log"
mask() { sed -E -e '/^Run: /d' -e 's/[0-9][0-9.e+-]* s([;,.)| ])/T s\1/g' "$1"; }
untimed() {  # the timed files of folder $1, times masked
  mask "$1/report.md" | awk -F'|' -v OFS='|' '
    /^\| arith \| exact s \| float s \| exact\/float \|$/ { time = 1; print; next }
    /^$/ { time = 0 }
    time && /^\| (double|mpfr:[0-9]+) \|/ { $3 = " T "; $4 = " T "; $5 = " T " }
    NF == 12 && $4 ~ /^ (double|mpfr:[0-9]+) $/ { $10 = " T "; $11 = " T " }
    { print }'
  cut -d, -f1-18 "$1/crosscheck.csv"
  sed -E 's/"seconds_(exact|float)": [0-9.e+-]+/"seconds_\1": T/g' "$1/crosscheck.json"
}
untimed "$W/report" > "$W/report.txt"
grep -q '"seconds_exact": T' "$W/report.txt"
test "$(ls "$W/report" | wc -l)" -gt 8
same() {  # the merged folder $1 is the report's, times aside
  diff -r -x report.md -x crosscheck.csv -x crosscheck.json "$W/report" "$1"
  untimed "$1" > "$1.txt"
  cmp "$W/report.txt" "$1.txt"
}
for n in 2; do
  seq 0 $((n - 1)) | xargs -P "$n" -I{} $CLI sweep run --jobs "$W/jobs.jsonl" --shard {}/$n --dir "$W/jobs$n" --quiet > /dev/null
  $CLI sweep merge --jobs "$W/jobs.jsonl" "$W/jobs$n" --out "$W/merged$n" > /dev/null 2>&1
  same "$W/merged$n"
done
$CLI sweep run --jobs "$W/jobs.jsonl" --threads 2 --dir "$W/threads" 2> "$W/threads.log" > /dev/null
grep -q '^\[hybrid\] section hybrid finished in' "$W/threads.log"  # a job's own progress
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/threads" --out "$W/merged_threads" > /dev/null 2>&1
same "$W/merged_threads"
# an interrupted job: its result is missing and its folder holds a stray file; the rerun runs
# that job only, and the stray file is not merged
rm "$W/jobs2/report/hybrid.json"
echo stray > "$W/jobs2/report/hybrid/stray.txt"
$CLI sweep run --jobs "$W/jobs.jsonl" --dir "$W/jobs2" --quiet | grep -q '"run":1,"shard":"0/1","skipped":3'
test ! -e "$W/jobs2/report/hybrid/stray.txt"
rm -rf "$W/merged2"
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/jobs2" --out "$W/merged2" > /dev/null 2>&1
same "$W/merged2"
# a file a job's result names is gone: the merge names it
rm "$W/threads/report/checkerboard/checkerboard.svg"
set +e
$CLI sweep merge --jobs "$W/jobs.jsonl" "$W/threads" --out "$W/broken" > /dev/null 2> "$W/broken.txt"
rc=$?
set -e
test $rc -eq 2
grep -q "^splinex: error: jobs: .*checkerboard/checkerboard.svg is missing" "$W/broken.txt"
# typed errors of the plan
set +e
$CLI sweep plan report --sections composition-orders > /dev/null 2> "$W/e1.txt"
r1=$?
$CLI sweep plan report --eps 1e-3 > /dev/null 2> "$W/e2.txt"
r2=$?
$CLI sweep plan proofs --sections hybrid > /dev/null 2> "$W/e3.txt"
r3=$?
set -e
test $r1 -eq 2 && grep -q "^splinex: error: sections: composition-orders draws from the crosscheck suite" "$W/e1.txt"
test $r2 -eq 2 && grep -q "^splinex: error: sweep: --cases, --cases-per-job, --proofs, --eps and --runs are not options of report" "$W/e2.txt"
test $r3 -eq 2 && grep -q "^splinex: error: sections: is an option of report, not of proofs" "$W/e3.txt"
echo "report sweep merged identical to the report"
