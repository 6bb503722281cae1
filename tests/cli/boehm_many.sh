#!/usr/bin/env bash
# boehm_many.sh SPLINEX DOC N: inserts the N-1 knots i/N (0 < i < N) by Boehm (A5.1 knot by knot)
# and by A5.4 refinement; prints "same" if the two documents are identical (exact arithmetic).
set -eu
knots=$(python3 -c "import sys; n = int(sys.argv[1]); print(','.join('%d/%d' % (i, n) for i in range(1, n)))" "$3")
a=$("$1" insert-knots --method boehm --knots "$knots" "$2")
b=$("$1" insert-knots --knots "$knots" "$2")
[ "$a" = "$b" ] && echo "same (${#a} bytes)" || echo "different"
