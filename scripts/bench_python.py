#!/usr/bin/env python3
"""The Python peer of the kernel benchmark: knot insertion (A5.1) and evaluation (A2.2 and the sum
of basis functions times control points) in Python's exact `fractions.Fraction`, on the cases that
`bench_kernel --write-cases DIR` wrote (the same data as the C++ run). Every result is checked equal
to splinex's exact one before anything is timed.

    scripts/bench_python.py CASE_DIR OUT.json

Written as a Python user would: lists of Fractions, list slices for the untouched control points
(slices copy references, not numbers, which is why Python is fast where C++ value semantics copy).
"""
import json
import sys
import timeit
from bisect import bisect_left, bisect_right
from fractions import Fraction
from pathlib import Path


def frac(v):
    return Fraction(v) if not isinstance(v, str) else Fraction(v)


def read_curve(doc):
    p = doc["degrees"][0]
    U = [frac(u) for u in doc["knots"][0]]
    P = [[frac(c) for c in pt] for pt in doc["points"]]
    return p, U, P


def insert_one(p, U, P, x):
    """A5.1 with r = 1: the new knot x once."""
    k = bisect_right(U, x) - 1
    s = bisect_right(U, x) - bisect_left(U, x)  # multiplicity of x, by binary search
    if s >= p:  # multiplicity p to p+1: repeat P[k-p]
        return U[:k + 1] + [x] + U[k + 1:], P[:k - p + 1] + [P[k - p]] + P[k - p + 1:]
    new = []
    for i in range(k - p + 1, k - s + 1):
        a = (x - U[i]) / (U[i + p] - U[i])
        new.append([(1 - a) * q0 + a * q1 for q0, q1 in zip(P[i - 1], P[i])])
    return U[:k + 1] + [x] + U[k + 1:], P[:k - p + 1] + new + P[k - s:]


def evaluate(p, U, P, x):
    n = len(P)
    s = min(bisect_right(U, x) - 1, n - 1)
    N = [Fraction(1)] + [Fraction(0)] * p
    left, right = [Fraction(0)] * (p + 1), [Fraction(0)] * (p + 1)
    for j in range(1, p + 1):
        left[j] = x - U[s + 1 - j]
        right[j] = U[s + j] - x
        saved = Fraction(0)
        for r in range(j):
            temp = N[r] / (right[r + 1] + left[j - r])
            N[r] = saved + right[r + 1] * temp
            saved = left[j - r] * temp
        N[j] = saved
    q = len(P[0])
    return [sum(N[i] * P[s - p + i][c] for i in range(p + 1)) for c in range(q)]


def timed(fn):
    number, total = 1, 0.0
    while True:
        total = timeit.timeit(fn, number=number)
        if total >= 0.2:
            return total / number
        number *= 2


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    out = []
    for f in sorted(Path(sys.argv[1]).glob("case_p*_n*.json")):
        doc = json.load(open(f))
        p, U, P = read_curve(doc["spline"])
        x = frac(doc["knot"])
        at = [frac(a) for a in doc["at"]]
        V, Q = insert_one(p, U, P, x)
        pe, Ue, Pe = read_curve(doc["inserted"])
        if V != Ue or Q != Pe:
            print(f"bench_python: insertion differs from splinex's exact result on {f.name}", file=sys.stderr)
            return 1
        values = [v for a in at for v in evaluate(p, U, P, a)]
        if values != [frac(v) for v in doc["values"]]:
            print(f"bench_python: evaluation differs from splinex's exact result on {f.name}", file=sys.stderr)
            return 1
        out.append({"op": "insert", "p": p, "n": doc["n"], "seconds": timed(lambda: insert_one(p, U, P, x))})
        out.append({"op": "eval", "p": p, "n": doc["n"], "seconds": timed(lambda: [evaluate(p, U, P, a) for a in at])})
        print(f"{f.name}: insert {out[-2]['seconds'] * 1e6:.1f} us, eval {out[-1]['seconds'] * 1e6:.1f} us", file=sys.stderr)
    json.dump({"python": sys.version.split()[0], "checked_equal": True, "cases": out}, open(sys.argv[2], "w"), indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
