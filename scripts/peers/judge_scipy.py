#!/usr/bin/env python3
"""SciPy's B-spline results judged exactly by splinex (issue 16, part 3: real candidates).

    PYTHONPATH=build/python python3 scripts/peers/judge_scipy.py OUT_DIR [CASES]

On splinex's structured generator (curves: degree 0..7, C^-1 knots, single spans, unclamped ends,
knots 2^-60 apart, shifted domains; polynomial, since scipy.interpolate.BSpline has no weights),
each case rounded to double (the input SciPy gets, so SciPy is judged on its own arithmetic):
  - insert:     scipy.interpolate.insert of one knot inside the domain, per coordinate;
  - derivative: BSpline(t, c, k).derivative() (splder), against the exact hodograph;
  - eval:       scipy.interpolate.BSpline(t, c, k)(x) at 9 points of the domain.
Every result goes to splinex.verify against the exact result on the same (rounded) input. Writes
scipy.md (the table: bits lost median / max, structure mismatches, failures), scipy.json (every
case), scipy_bits_vs_degree.svg and scipy_bits_vs_spacing.svg. Debian's python3-scipy lives in /usr/lib/python3/dist-packages;
that folder is added to the path when another interpreter runs this script.
"""
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

try:
    import scipy
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")
    import scipy
import numpy as np
from scipy.interpolate import BSpline, insert

import splinex
from common import double_inputs, judged_row, verify_into, verify_result, write_results


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


def scipy_derivative(S):
    """BSpline.derivative(): the first derivative as a B-spline (scipy.interpolate.splder)."""
    p = S["degrees"][0]
    t = np.array([float(x) for x in S["knots"][0]])
    P = np.array([[float(x) for x in pt] for pt in S["points"]])
    d = BSpline(t, P, p).derivative()
    n = len(d.t) - d.k - 1
    pts = [[float(v) for v in row] for row in np.asarray(d.c)[:n]]
    if any(not math.isfinite(v) for r in pts for v in r):
        raise ArithmeticError("SciPy's derivative has NaN/inf coefficients")
    return {"degrees": [int(d.k)], "knots": [[float(x) for x in d.t]], "points": pts}


def scipy_eval(S, xs):
    p = S["degrees"][0]
    t = np.array([float(x) for x in S["knots"][0]])
    P = np.array([[float(x) for x in pt] for pt in S["points"]])
    f = BSpline(t, P, p, extrapolate=False)
    return [[float(v) for v in f(x)] for x in xs]


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    cases = int(sys.argv[2]) if len(sys.argv) == 3 else 200
    inputs, rows = double_inputs(cases, 20261202)
    for seed, suite, S, tags, u, xs in inputs:
        if "weights" in S:
            continue  # scipy.interpolate.BSpline has no weights: the rational suite is not SciPy's
        for op in ("insert", "derivative", "eval"):
            row = judged_row(seed, suite, op, S, tags)
            try:
                if op == "insert":
                    result = scipy_insert(S, u)
                elif op == "derivative":
                    result = scipy_derivative(S)
                else:
                    result = scipy_eval(S, xs)
                    if any(not math.isfinite(v) for r in result for v in r):
                        raise ArithmeticError("SciPy returned NaN/inf")
                verify_into(row, verify_result(S, op, u, xs, result))
            except Exception as e:  # SciPy refused or crashed on a legal input: a finding
                row["failure"] = f"{type(e).__name__}: {str(e)[:100]}"
            rows.append(row)
    rows.sort(key=lambda r: r["seed"])  # stable: by case, the unrepresentable inputs in their place
    (out / "scipy.json").write_text(json.dumps({"scipy": scipy.__version__, "cases": cases, "rows": rows}, indent=1) + "\n")
    md = write_results(out, "scipy", f"SciPy {scipy.__version__} judged exactly by splinex",
                       f"{cases} curves of splinex's structured generator, {cases} ordinary clamped curves (degree 1..7, "
                       "simple dyadic knots) and the report's adversarial curves (knots 1/10 and 1/10 + 2^-50, degree 15, "
                       "1000 knots within 1e-6, knots 2^-30 apart, 200 knots), rounded to double (no rational curves: "
                       "BSpline has no weights); one knot inserted (`scipy.interpolate.insert`, per "
                       "coordinate), the first derivative as a spline (`BSpline.derivative`, splder) and values at 9 points "
                       "(`BSpline.__call__`), each judged by `splinex.verify` against "
                       "the exact result on the same input. Bits lost: the worst of the coefficient (or value) error and "
                       "the certified function-level bound, relative to the largest reference coefficient (or value), of 53.",
                       rows, ("insert", "derivative", "eval"), cases, f"SciPy {scipy.__version__}")
    print("\n".join(md[:10]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
