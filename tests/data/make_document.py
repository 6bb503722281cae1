#!/usr/bin/env python3
"""Large spline documents for the resource tests, written to stdout (not stored in the repo).

  make_document.py long N     degree 1, N control points, knots 0..N-1 (about 11 bytes per point)
  make_document.py degree P   degree P, one Bezier piece on [0, 1], every control point 1
"""
import sys

kind, n = sys.argv[1], int(sys.argv[2])
if kind == "long":
    knots = [0] + list(range(n)) + [n - 1]
    points = [[1]] * n
    degree = 1
elif kind == "degree":
    knots = [0] * (n + 1) + [1] * (n + 1)
    points = [[1]] * (n + 1)
    degree = n
else:
    sys.exit("unknown kind " + kind)
sys.stdout.write('{"type":"bspline","degrees":[%d],"knots":[[%s]],"points":[%s]}\n'
                 % (degree, ",".join(map(str, knots)), ",".join("[%d]" % p[0] for p in points)))
