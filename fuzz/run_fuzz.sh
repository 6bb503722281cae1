#!/usr/bin/env bash
# run_fuzz.sh FUZZER SEED_DIR CORPUS_DIR RUNS [JOBS]: seeds the corpus from the JSON documents
# (each prefixed with every operation byte and a parameter byte; 40: the certified solver) and runs libFuzzer for RUNS
# executions with a 10 s per-input timeout and a 2 GB RSS limit; exits non-zero on any finding.
set -euo pipefail
fuzzer=$1; seeds=$2; corpus=$3; runs=$4; jobs=${5:-1}
mkdir -p "$corpus"
for f in "$seeds"/*.json; do
  for op in 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 40; do
    name="$corpus/seed-$(basename "$f" .json)-$op"
    [[ -e $name ]] || { printf "\\x$(printf %02x "$op")\\x2a"; cat "$f"; } > "$name"
  done
done
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
parallel=()
((jobs > 1)) && parallel=(-jobs="$jobs" -workers="$jobs")
exec "$fuzzer" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 "${parallel[@]}" "$corpus"
