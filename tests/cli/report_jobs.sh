#!/bin/sh
# report --jobs: the files a part of the report writes do not depend on the number of threads
# its sections run on, times aside (the numbers before " s" in report.md). Four sections, so that
# two threads each run two.
set -eu
CLI=$1
D=$2
rm -rf "$D"
mkdir -p "$D"
S=checkerboard,curved-untrim,elevation-accuracy,hybrid
"$CLI" report --out "$D/one" --sections $S --jobs 1 2>"$D/one.log"
"$CLI" report --out "$D/two" --sections $S --jobs 2 2>"$D/two.log"
grep -q "sections on 2 threads" "$D/two.log" || { echo "the second run did not use 2 threads"; exit 1; }
diff -r -x report.md "$D/one" "$D/two"
mask() { sed -E -e '/^Run: /d' -e 's/[0-9][0-9.e+-]* s([;,.)| ])/T s\1/g' "$1"; }
mask "$D/one/report.md" >"$D/one.md"
mask "$D/two/report.md" >"$D/two.md"
cmp "$D/one.md" "$D/two.md"
test "$(ls "$D/one" | wc -l)" -gt 5
echo "report on 1 and 2 threads: the same files"
