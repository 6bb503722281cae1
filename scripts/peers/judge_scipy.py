#!/usr/bin/env python3
"""SciPy's B-spline results judged exactly by splinex (issue 16, part 3: real candidates).

    PYTHONPATH=build/python python3 scripts/peers/judge_scipy.py OUT_DIR [CASES]

On splinex's structured generator (curves: degree 0..7, C^-1 knots, single spans, unclamped ends,
knots 2^-60 apart, shifted domains; polynomial, since scipy.interpolate.BSpline has no weights),
each case rounded to double (the input SciPy gets, so SciPy is judged on its own arithmetic):
  - insert: scipy.interpolate.insert of one knot inside the domain, per coordinate;
  - eval:   scipy.interpolate.BSpline(t, c, k)(x) at 9 points of the domain.
Every result goes to splinex.verify against the exact result on the same (rounded) input. Writes
scipy.md (the table: bits lost median / max, structure mismatches, failures), scipy.json (every
case) and scipy_bits_vs_degree.svg. Debian's python3-scipy lives in /usr/lib/python3/dist-packages;
that folder is added to the path when another interpreter runs this script.
"""
import json
import math
import random
import statistics
import sys
from fractions import Fraction
from pathlib import Path

try:
    import scipy
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")
    import scipy
import numpy as np
from scipy.interpolate import BSpline, insert

import splinex


def rounded(S):
    """The spline with every number rounded to double, as exact Fractions of those doubles."""
    out = dict(S)
    out["knots"] = [[Fraction(float(u)) for u in U] for U in S["knots"]]
    out["points"] = [[Fraction(float(x)) for x in p] for p in S["points"]]
    return out


def domain(S):
    p, U = S["degrees"][0], S["knots"][0]
    n = len(S["points"])
    return U[p], U[n]


def scipy_insert(S, u):
    p = S["degrees"][0]
    t = np.array([float(x) for x in S["knots"][0]])
    P = np.array([[float(x) for x in pt] for pt in S["points"]])
    cols, t_new = [], None
    for c in range(P.shape[1]):
        tn, cn, k = insert(u, (t, P[:, c], p), m=1)
        t_new = tn
        cols.append(cn[:len(tn) - p - 1])
    pts = [[float(cols[c][i]) for c in range(len(cols))] for i in range(len(cols[0]))]
    return {"degrees": [p], "knots": [[float(x) for x in t_new]], "points": pts}


def scipy_eval(S, xs):
    p = S["degrees"][0]
    t = np.array([float(x) for x in S["knots"][0]])
    P = np.array([[float(x) for x in pt] for pt in S["points"]])
    f = BSpline(t, P, p, extrapolate=False)
    return [[float(v) for v in f(x)] for x in xs]


def svg(series, title):
    """A small line plot of bits lost against degree (one series per operation)."""
    W, H, L, B = 560, 320, 50, 40
    xs = [x for pts in series.values() for x, _ in pts] or [0, 1]
    x0, x1 = min(xs), max(max(xs), min(xs) + 1)
    y1 = max([y for pts in series.values() for _, y in pts] + [53])
    sx = lambda x: L + (x - x0) / (x1 - x0) * (W - L - 20)
    sy = lambda y: H - B - y / y1 * (H - B - 30)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           f'<text x="{W/2}" y="16" text-anchor="middle" font-size="13">{title}</text>',
           f'<line x1="{L}" y1="{H-B}" x2="{W-20}" y2="{H-B}" stroke="black"/><line x1="{L}" y1="{H-B}" x2="{L}" y2="30" stroke="black"/>',
           f'<text x="{W/2}" y="{H-8}" text-anchor="middle">degree</text>',
           f'<text x="12" y="{H/2}" transform="rotate(-90 12 {H/2})" text-anchor="middle">bits lost (worst, of 53)</text>']
    for d in range(int(x0), int(x1) + 1):
        out.append(f'<text x="{sx(d)}" y="{H-B+14}" text-anchor="middle">{d}</text>')
    for y in range(0, int(y1) + 1, 10):
        out.append(f'<text x="{L-6}" y="{sy(y)+4}" text-anchor="end">{y}</text>')
    colors = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
    for i, (name, pts) in enumerate(sorted(series.items())):
        pts = sorted(pts)
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in pts)
        out.append(f'<polyline fill="none" stroke="{colors[i % 4]}" stroke-width="2" points="{path}"/>')
        out.append(f'<text x="{W-150}" y="{40+14*i}" fill="{colors[i % 4]}">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    cases = int(sys.argv[2]) if len(sys.argv) == 3 else 200
    rng = random.Random(20261202)
    rows = []
    for seed in range(cases):
        S0, tags = splinex.structured_case(seed, max_dim=1, rational=False)
        try:
            S = splinex.validate(rounded(S0))
        except ValueError as e:  # knots closer than double can hold: not a double input at all
            rows.append({"seed": seed, "op": "input", "tags": tags, "failure": "not representable in double: " + str(e)[:80]})
            continue
        p = S["degrees"][0]
        lo, hi = domain(S)
        u = float(lo + (hi - lo) * Fraction(rng.randint(1, 999), 1000))
        for op in ("insert", "eval"):
            row = {"seed": seed, "op": op, "degree": p, "tags": tags}
            try:
                if op == "insert":
                    cand = scipy_insert(S, u)
                    rep = splinex.verify("insert-knots", S, cand, knots=[u])
                else:
                    xs = [float(lo + (hi - lo) * Fraction(i, 8)) for i in range(9)]
                    xs = [min(max(x, float(lo)), float(hi)) for x in xs]
                    vals = scipy_eval(S, xs)
                    if any(not math.isfinite(v) for r in vals for v in r):
                        raise ArithmeticError("SciPy returned NaN/inf")
                    rep = splinex.verify("eval", S, {"at": [[x] for x in xs], "values": vals})
                row.update({"structure": rep.structure, "bits_lost": rep.bits_lost, "certified": rep.certified,
                            "function_upper": float(rep.function_upper)})
            except Exception as e:  # SciPy refused or crashed on a legal input: a finding
                row["failure"] = f"{type(e).__name__}: {str(e)[:100]}"
            rows.append(row)
    (out / "scipy.json").write_text(json.dumps({"scipy": scipy.__version__, "cases": cases, "rows": rows}, indent=1) + "\n")
    md = [f"# SciPy {scipy.__version__} judged exactly by splinex", "",
          f"{cases} curves of splinex's structured generator, rounded to double; one knot inserted "
          "(`scipy.interpolate.insert`, per coordinate) and values at 9 points (`BSpline.__call__`), each judged by "
          "`splinex.verify` against the exact result on the same input. Bits lost: the worst of the coefficient "
          "(or value) error and the certified function-level bound, relative to the largest reference coefficient "
          "(or value), of 53.", "",
          "| operation | judged | bits lost, median | bits lost, max | structure differs | failures |", "|---|---|---|---|---|---|"]
    series = {}
    for op in ("insert", "eval"):
        ok = [r for r in rows if r["op"] == op and "bits_lost" in r]
        fails = [r for r in rows if r["op"] == op and "failure" in r]
        bits = [r["bits_lost"] for r in ok]
        md.append(f"| {op} | {len(ok)} | {statistics.median(bits) if bits else '-':.3g} | {max(bits) if bits else '-':.3g} | "
                  f"{sum(r['structure'] == 'different' for r in ok)} | {len(fails)} |")
        worst = {}
        for r in ok:
            worst[r["degree"]] = max(worst.get(r["degree"], 0), r["bits_lost"])
        series[op] = sorted(worst.items())
    md += ["", "Failures and structure differences (first 20):", ""]
    shown = 0
    for r in rows:
        if shown < 20 and ("failure" in r or r.get("structure") == "different"):
            md.append(f"- seed {r['seed']}, {r['op']}, structures {', '.join(r['tags']) or '-'}: "
                      f"{r.get('failure', 'structure differs')}")
            shown += 1
    not_double = sum(r["op"] == "input" for r in rows)
    md += ["", f"{not_double} of {cases} inputs are not representable in double (knots closer than double can tell apart) "
               "and were not given to SciPy.", "", "![bits lost vs degree](scipy_bits_vs_degree.svg)", ""]
    (out / "scipy.md").write_text("\n".join(md))
    (out / "scipy_bits_vs_degree.svg").write_text(svg(series, f"SciPy {scipy.__version__}: worst bits lost by degree"))
    print("\n".join(md[:10]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
