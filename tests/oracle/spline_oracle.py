#!/usr/bin/env python3
"""An independent exact oracle for splinex's command line: it shares no code with splinex.

It reads spline documents, evaluates them by the Cox-de Boor recursion in Python's Fraction
(half-open spans U[i] <= x < U[i+1], the last non-empty span closed at the domain end), runs a
splinex command, and checks its JSON output against the input function exactly at many rational
points: every breakpoint of input and output, the midpoints between them, and seeded random
rationals. A sampled check, not a proof: it exists so that command-line tests fail on wrong values.

  spline_oracle.py same      INPUT  -- splinex ARGS...   output spline(s) = input function
  spline_oracle.py pieces    INPUT  -- splinex ARGS...   extract-bezier: pieces tile the domain, each = input
  spline_oracle.py split     INPUT DIR AT -- splinex ARGS...   the two halves = input on each side
  spline_oracle.py affine    INPUT DIR LO HI -- splinex ARGS... R(lo + (x-a)(hi-lo)/(b-a)) = S(x) (LO > HI: reversal)
  spline_oracle.py compose   OUTER INNER -- splinex ARGS...  output spline R = T(S)
  spline_oracle.py trimmed   OUTER INNER -- splinex ARGS...  Algorithm 1 output: owning patch(r) = T(S(r))
Exit 0 and "ok: N points" when every comparison holds; exit 1 with the first difference otherwise.
"""
import itertools
import json
import random
import subprocess
import sys
from fractions import Fraction as Q


def num(v):
    if isinstance(v, (int, Q)):
        return Q(v)
    if isinstance(v, float):
        return Q(v)  # a double output: its exact value
    if isinstance(v, str):
        return Q(v)
    raise ValueError("not a number: %r" % (v,))


def load(text):
    return json.loads(text, parse_float=Q, parse_int=Q)


class Spline:
    def __init__(self, doc):
        self.degrees = [int(p) for p in doc["degrees"]]
        self.knots = [[num(u) for u in U] for U in doc["knots"]]
        pts = [[num(c) for c in p] for p in doc["points"]]
        self.q = len(pts[0])
        self.weights = [num(w) for w in doc["weights"]] if doc.get("weights") else None
        self.counts = [len(U) - p - 1 for U, p in zip(self.knots, self.degrees)]
        self.points = pts
        n = 1
        for c in self.counts:
            n *= c
        assert n == len(pts), "point count"

    def dim(self):
        return len(self.degrees)

    def domain(self, d):
        return self.knots[d][self.degrees[d]], self.knots[d][self.counts[d]]

    def breakpoints(self, d):
        lo, hi = self.domain(d)
        return sorted({u for u in self.knots[d] if lo <= u <= hi})

    def basis(self, d, x):
        """All n basis values at x: Cox-de Boor, half-open, closed at the domain end."""
        U, p, n = self.knots[d], self.degrees[d], self.counts[d]
        lo, hi = self.domain(d)
        if not (lo <= x <= hi):
            raise ValueError("parameter %s outside [%s, %s]" % (x, lo, hi))
        m = len(U) - 1
        N = [Q(0)] * m
        if x == hi:  # last non-empty span
            s = max(i for i in range(p, n) if U[i] < U[i + 1])
            N[s] = Q(1)
        else:
            for i in range(m):
                if U[i] <= x < U[i + 1]:
                    N[i] = Q(1)
        for k in range(1, p + 1):
            M = [Q(0)] * (m - k)
            for i in range(m - k):
                v = Q(0)
                if U[i + k] != U[i]:
                    v += (x - U[i]) / (U[i + k] - U[i]) * N[i]
                if U[i + k + 1] != U[i + 1]:
                    v += (U[i + k + 1] - x) / (U[i + k + 1] - U[i + 1]) * N[i + 1]
                M[i] = v
            N = M
        return N[:n]

    def __call__(self, x):
        bases = [self.basis(d, x[d]) for d in range(self.dim())]
        num_ = [Q(0)] * self.q
        den = Q(0)
        for flat, P in enumerate(self.points):
            b, rem = Q(1), flat
            for d in range(self.dim()):
                b *= bases[d][rem % self.counts[d]]
                rem //= self.counts[d]
            if b == 0:
                continue
            w = self.weights[flat] if self.weights else Q(1)
            for c in range(self.q):
                num_[c] += b * w * P[c]
            den += b * w
        return [v / den for v in num_] if self.weights else num_


def samples(lo, hi, cuts, rng, extra=7):
    """Cut values inside [lo, hi], midpoints between them, and random rationals."""
    vals = sorted({c for c in cuts if lo <= c <= hi} | {lo, hi})
    out = set(vals)
    for a, b in zip(vals, vals[1:]):
        out.add((a + b) / 2)
        out.add(a + (b - a) / 3)
    for _ in range(extra):
        out.add(lo + (hi - lo) * Q(rng.randrange(1, 997), 997))
    return sorted(out)


def grid(axes, limit=4000):
    pts = list(itertools.product(*axes))
    if len(pts) > limit:
        pts = random.Random(7).sample(pts, limit)
    return pts


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("splinex exited %d: %s" % (r.returncode, r.stderr.strip()))
    return load(r.stdout)


def fail(msg):
    print("MISMATCH: " + msg)
    sys.exit(1)


def show(v):
    return "(" + ", ".join(str(c) for c in v) + ")"


def check_equal(F, G, pts, what, mapx=lambda x: x):
    for x in pts:
        a, b = F(list(x)), G(mapx(list(x)))
        if a != b:
            fail("%s at x = %s: expected %s, got %s" % (what, show(x), show(a), show(b)))
    return len(pts)


def main(argv):
    rng = random.Random(20261201)
    mode = argv[1]
    sep = argv.index("--")
    args, cmd = argv[2:sep], argv[sep + 1:]
    out = run(cmd)
    n = 0
    if mode in ("same", "pieces", "split", "affine"):
        S = Spline(load(open(args[0]).read()))
    if mode == "same":
        R = Spline(out)
        if [R.domain(d) for d in range(R.dim())] != [S.domain(d) for d in range(S.dim())]:
            fail("the domain changed")
        axes = [samples(*S.domain(d), S.breakpoints(d) + R.breakpoints(d), rng) for d in range(S.dim())]
        n = check_equal(S, R, grid(axes), "output")
    elif mode == "pieces":
        boxes = []
        for pc in out["pieces"]:
            P = Spline(pc["spline"])
            box = [(num(a), num(b)) for a, b in pc["box"]]
            boxes.append(tuple(box))
            for d in range(P.dim()):
                if P.domain(d) != box[d] or P.counts[d] != P.degrees[d] + 1:
                    fail("piece with box %s is not a Bezier piece on its box" % (box,))
            # The piece's polynomial on its closed box = S's piece on the half-open box: compare
            # inside, and at the box's corners by S's one-sided limit (take points 1/10^9 inside).
            axes = [samples(a, b, [], rng, 5) for a, b in box]
            pts = [x for x in grid(axes) if all(a < x[d] < b or (x[d] == a) for d, (a, b) in enumerate(box))
                   or all(x[d] < b or b == S.domain(d)[1] for d, (a, b) in enumerate(box))]
            n += check_equal(S, P, pts, "piece %s" % (box,))
        # Tiling: the boxes are the products of consecutive values of their own end points, each
        # once, those end points include every breakpoint of S, and they span S's domain.
        ends = [sorted({b[d][0] for b in boxes} | {b[d][1] for b in boxes}) for d in range(S.dim())]
        want = set(itertools.product(*[list(zip(e, e[1:])) for e in ends]))
        if set(boxes) != want or len(boxes) != len(want):
            fail("the boxes do not tile the domain: %d boxes, %d cells" % (len(boxes), len(want)))
        for d in range(S.dim()):
            if (ends[d][0], ends[d][-1]) != S.domain(d) or not set(S.breakpoints(d)) <= set(ends[d]):
                fail("the boxes do not span the domain or miss a breakpoint in direction %d" % d)
    elif mode == "split":
        d, at = int(args[1]), num(args[2])
        L, R = (Spline(s) for s in out["splines"])
        lo, hi = S.domain(d)
        if L.domain(d) != (lo, at) or R.domain(d) != (at, hi):
            fail("the halves have the wrong domains")
        for H, a, b in ((L, lo, at), (R, at, hi)):
            axes = [samples(*S.domain(e), S.breakpoints(e), rng) if e != d else
                    [x for x in samples(a, b, S.breakpoints(d), rng) if a <= x < b or (x == b == hi)]
                    for e in range(S.dim())]
            n += check_equal(S, H, grid(axes), "half")
    elif mode == "affine":
        d, lo2, hi2 = int(args[1]), num(args[2]), num(args[3])
        R = Spline(out)
        a, b = S.domain(d)
        phi = lambda x: [lo2 + (x[e] - a) * (hi2 - lo2) / (b - a) if e == d else x[e] for e in range(len(x))]
        if sorted(R.domain(d)) != sorted((lo2, hi2)):
            fail("the new domain is %s" % (R.domain(d),))
        axes = [samples(*S.domain(e), S.breakpoints(e), rng) for e in range(S.dim())]
        # A reversal maps half-open spans to the other side: compare off the breakpoints.
        pts = [x for x in grid(axes) if lo2 < hi2 or all(u not in S.breakpoints(d)[1:-1] for u in [x[d]])]
        n = check_equal(S, R, pts, "reparametrized output", phi)
    elif mode in ("compose", "trimmed"):
        T = Spline(load(open(args[0]).read()))
        S = Spline(load(open(args[1]).read()))
        TS = lambda r: T(S(r))
        axes = [samples(*S.domain(d), S.breakpoints(d), rng) for d in range(S.dim())]
        if mode == "compose":
            R = Spline(out)
            axes = [samples(*S.domain(d), S.breakpoints(d) + R.breakpoints(d), rng) for d in range(S.dim())]
            n = check_equal(TS, R, grid(axes), "composition")
        else:
            pieces = out["pieces"]

            def owner(r):
                s = S(r)
                found = []
                for pc in pieces:
                    box = [(num(a), num(b)) for a, b in pc["inner_box"]]
                    if not all(a <= r[d] and (r[d] < b or b == S.domain(d)[1]) for d, (a, b) in enumerate(box)):
                        continue
                    ok = True
                    for c in pc["region"]:
                        v = s[int(c["coordinate"])]
                        if "at_least" in c and v < num(c["at_least"]):
                            ok = False
                        if "below" in c and not v < num(c["below"]):
                            ok = False
                        if "at_most" in c and v > num(c["at_most"]):
                            ok = False
                    if ok:
                        found.append(pc)
                if len(found) != 1:
                    fail("%d patches own r = %s" % (len(found), show(r)))
                P = Spline(found[0]["patch"])
                v = P(r)
                if found[0]["homogeneous"]:
                    v = [c / v[-1] for c in v[:-1]]
                return v
            n = check_equal(TS, owner, grid(axes, 1500), "trimmed composition")
    else:
        sys.exit("unknown mode " + mode)
    print("ok: %d points agree exactly" % n)


if __name__ == "__main__":
    main(sys.argv)
