#!/usr/bin/env python3
"""Large spline documents for the resource tests, written to stdout (not stored in the repo).

  make_document.py long N     degree 1, N control points, knots 0..N-1 (about 11 bytes per point)
  make_document.py degree P   degree P, one Bezier piece on [0, 1], every control point 1
  make_document.py circle N   a trimmed domain: one loop of N vertices on the unit circle (rounded to
                              9 decimals) in the box [-2, 2]^2
  make_document.py surface P  degrees (P, P), two pieces per direction ([0, 1/2], [1/2, 1]),
                              (P+2)^2 control points all 1
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
elif kind == "circle":
    import math
    pts = ",".join('["%.9f","%.9f"]' % (math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n))
    sys.stdout.write('{"type":"trimmed_domain","domain":[[-2,2],[-2,2]],"loops":[[%s]]}\n' % pts)
    sys.exit(0)
elif kind == "surface":
    U = ",".join(["0"] * (n + 1) + ['"1/2"'] + ["1"] * (n + 1))
    sys.stdout.write('{"type":"bspline","degrees":[%d,%d],"knots":[[%s],[%s]],"points":[%s]}\n'
                     % (n, n, U, U, ",".join(["[1]"] * (n + 2) ** 2)))
    sys.exit(0)
else:
    sys.exit("unknown kind " + kind)
sys.stdout.write('{"type":"bspline","degrees":[%d],"knots":[[%s]],"points":[%s]}\n'
                 % (degree, ",".join(map(str, knots)), ",".join("[%d]" % p[0] for p in points)))
