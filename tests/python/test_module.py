#!/usr/bin/env python3
"""The Python module splinex (pybind11): exact operations with Fractions, and verify judging a
candidate computed here in plain Python floats. Run by ctest (python.module) with PYTHONPATH set
to the build's python/ folder; plain asserts, no pytest needed."""
import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import splinex

DATA = Path(__file__).resolve().parents[1] / "data"

S = {"degrees": [3], "knots": [[0, 0, 0, 0, "1/3", 0.5, 1, 1, 1, 1]],
     "points": [[0, 0], [1, 2], ["22/7", "1e-3"], [3, 0.784], [4, 1], [5, "-1/2"]]}


def boehm_float(spline, u):
    """One knot inserted into a curve by Boehm's algorithm (NURBS Book A5.1), in floats."""
    p = spline["degrees"][0]
    num = lambda x: float(Fraction(x)) if isinstance(x, str) else float(x)
    U = [num(x) for x in spline["knots"][0]]
    P = [[num(c) for c in pt] for pt in spline["points"]]
    k = max(i for i in range(len(U) - 1) if U[i] <= u < U[i + 1])
    Q = []
    for i in range(len(P) + 1):
        if i <= k - p:
            Q.append(P[i])
        elif i > k:
            Q.append(P[i - 1])
        else:
            a = (u - U[i]) / (U[i + p] - U[i])
            Q.append([(1 - a) * x + a * y for x, y in zip(P[i - 1], P[i])])
    return {"degrees": [p], "knots": [U[:k + 1] + [u] + U[k + 1:]], "points": Q}


def main():
    # Exact operations: Fractions out; "1/3" and 0.5 read exactly; elevation keeps the function.
    E = splinex.elevate(S, by=1)
    assert E["degrees"] == [4]
    assert all(isinstance(x, Fraction) for x in E["knots"][0])
    for t in (Fraction(1, 7), Fraction(1, 3), Fraction(2, 3), Fraction(99, 100)):
        assert splinex.evaluate(E, t) == splinex.evaluate(S, t)
    assert Fraction(1, 3) in splinex.validate(S)["knots"][0]
    # A float is the double it is: 0.1 is not 1/10.
    assert splinex.validate({"degrees": [1], "knots": [[0, 0, 1, 1]], "points": [[0.1], [1]]})["points"][0][0] != Fraction(1, 10)

    # verify: the exact result itself.
    rep = splinex.verify("elevate", S, E, by=1)
    assert rep.structure == "equal" and rep.bits_lost == 0 and rep.function_upper == 0 and rep.certified, rep

    # verify: a candidate computed here in floats (Boehm in plain Python) loses a few bits at most.
    C = boehm_float(S, 0.7)
    rep = splinex.verify("insert-knots", S, C, knots=[0.7])
    assert rep.structure in ("equal", "equal after rounding"), rep.report
    assert rep.bits_lost < 4, rep.report
    assert rep.certified and rep.within_factor
    assert rep.function_lower <= rep.function_upper

    # A wrong candidate (one coordinate off by 1e-6) is found, with the place.
    C["points"][3][1] += 1e-6
    rep = splinex.verify("insert-knots", S, C, knots=[0.7])
    assert rep.bits_lost > 20, rep.report
    assert rep.function_upper >= Fraction(1, 10**7), rep.report
    lo, hi = C["knots"][0][3], C["knots"][0][3 + 4]
    assert lo <= rep.at[0] <= hi, (rep.at, lo, hi)

    # Values at points.
    rep = splinex.verify("eval", S, {"at": [[0.25]], "values": [[float(x) for x in splinex.evaluate(S, 0.25)]]})
    assert rep.bits_lost <= 1, rep.report

    # Bad input: a ValueError with splinex's one-line text naming the field.
    for bad, field in (({"degrees": [3], "knots": [[0, 1]], "points": [[0]]}, "knots[0]"),
                       ({"degrees": [1], "knots": [[0, 0, 1, 1]], "points": [[0], ["NaN"]]}, "points[1][0]")):
        try:
            splinex.validate(bad)
        except ValueError as e:
            assert field in str(e), str(e)
        else:
            raise AssertionError("no error for " + repr(bad))
    try:
        splinex.verify("elevate", S, {"degrees": [4, 1], "knots": [[0, 1], [0, 1]], "points": [[0]]})
    except ValueError:
        pass
    else:
        raise AssertionError("a candidate of another dimension was accepted")
    # Arguments are checked as the CLI checks them (issue 47): types and ranges are ValueErrors naming
    # the field, an argument the operation does not take is a TypeError, never pybind11's untyped
    # RuntimeError; nesting is limited, so a list that contains itself is refused, not a crash.
    R = splinex.reverse(S)
    def raises(kind, text, f, *a, **kw):
        try:
            f(*a, **kw)
        except kind as e:
            assert text in str(e), (text, str(e))
        else:
            raise AssertionError("no %s for %s" % (kind.__name__, text))
    raises(ValueError, "precision: -5 is outside [2, 100000]", splinex.verify, "reverse", S, R, precision=-5)
    raises(ValueError, "precision: is not an integer", splinex.verify, "reverse", S, R, precision=53.5)
    raises(TypeError, "reverse takes no argument 'bogus'", splinex.verify, "reverse", S, R, bogus=1)
    raises(TypeError, "eval takes no argument 'by'", splinex.verify, "eval", S, {"at": [[0.5]], "values": [[0, 0]]}, by=1)
    raises(ValueError, "dir: 3 is outside [0, 2]", splinex.verify, "reverse", S, R, dir=3)
    raises(ValueError, "dir: direction 1 does not exist", splinex.verify, "reverse", S, R, dir=1)
    raises(ValueError, "dir: direction 5 does not exist", splinex.elevate, S, 1, 5)
    raises(ValueError, "order: 0 is outside [1, 1000]", splinex.verify, "derivative", S, R, order=0)
    raises(ValueError, "max_dim: 0 is outside [1, 3]", splinex.structured_case, 1, max_dim=0)
    for degrees, text in (([1.5], "degrees[0]: is not an integer"), (["1"], "degrees[0]: is not an integer"),
                          (1, "degrees: is not a list"), (None, "degrees: is not a list"),
                          ([2 ** 31], "degrees[0]: 2147483648 is outside")):
        raises(ValueError, text, splinex.validate, {"degrees": degrees, "knots": [[0, 0, 1, 1]], "points": [[0], [1]]})
    L = []
    L.append(L)
    raises(ValueError, "contains itself", splinex.validate, {"degrees": [1], "knots": [[0, 0, 1, 1]], "points": L})
    # The CLI's candidate documents: extract-bezier's {"pieces": [{"box": ..., "spline": ...}]} as JSON.
    pieces = {"pieces": [{"box": [[str(lo), str(hi)] for lo, hi in pc["box"]],
                          "spline": {k: ([[str(x) for x in r] for r in v] if k in ("knots", "points") else v)
                                     for k, v in pc["spline"].items()}} for pc in splinex.extract_bezier(S)]}
    rep = splinex.verify("extract-bezier", S, pieces)
    assert rep.structure == "equal" and rep.function_upper == 0 and rep.certified, rep.report
    # Functions not compared (another domain): no certified bound, so function_upper is None.
    moved = dict(R, knots=[[x + 5 for x in R["knots"][0]]])
    rep = splinex.verify("reverse", S, moved)
    assert rep.structure == "different" and rep.function_upper is None and not rep.certified, rep.report

    # The rest of verify's operations as functions (issue 48): refine, derivative, reparametrize,
    # checked against closed forms, not against the code under test.
    cubic = {"degrees": [3], "knots": [[0, 0, 0, 0, 1, 1, 1, 1]], "points": [[0], [0], [0], [1]]}  # t^3
    D = splinex.derivative(cubic, order=1)
    D2 = splinex.derivative(cubic, order=2)
    for t in (Fraction(0), Fraction(1, 3), Fraction(5, 7), Fraction(1)):
        assert splinex.evaluate(D, t) == [3 * t * t], (t, splinex.evaluate(D, t))
        assert splinex.evaluate(D2, t) == [6 * t]
    Rp = splinex.reparametrize(cubic, interval=("2", 5))
    assert Rp["knots"][0][0] == 2 and Rp["knots"][0][-1] == 5
    for t in (Fraction(1, 3), Fraction(5, 7)):
        assert splinex.evaluate(Rp, 2 + 3 * t) == [t ** 3]
    F = splinex.refine(S, knots=["1/5", "1/5"])
    assert len(F["knots"][0]) == len(S["knots"][0]) + 2 and F["knots"][0].count(Fraction(1, 5)) >= 2
    for t in (Fraction(1, 7), Fraction(1, 5), Fraction(2, 3)):
        assert splinex.evaluate(F, t) == splinex.evaluate(S, t)
    rep = splinex.verify("refine", S, F, knots=["1/5", "1/5"])
    assert rep.structure == "equal" and rep.function_upper == 0 and rep.certified, rep.report
    raises(ValueError, "spline: the hodograph of a rational spline", splinex.derivative,
           dict(cubic, weights=[1, 2, 2, 1]))
    raises(ValueError, "interval: needs two numbers", splinex.reparametrize, cubic, interval=[1])
    raises(TypeError, "incompatible function arguments", splinex.derivative, cubic, by=2)
    assert splinex.derivative(cubic, 2) == D2 and splinex.refine(S, ["1/5", "1/5"]) == F

    # Compositions: Algorithm 1's trimmed patches from splinex compose in double (argv[1]: the
    # splinex command), read by json as Python floats, judged exactly.
    if len(sys.argv) > 1:
        T = json.loads((DATA / "outer_bilinear.json").read_text())
        Sin = json.loads((DATA / "inner_surface.json").read_text())
        out = subprocess.run([sys.argv[1], "compose", "--method", "trimmed", "--arith", "double", "--outer",
                              str(DATA / "outer_bilinear.json"), "--inner", str(DATA / "inner_surface.json")],
                             check=True, capture_output=True, text=True).stdout
        cand = json.loads(out)
        rep = splinex.verify_compose(T, Sin, cand, method="trimmed")
        assert rep.structure != "different" and rep.certified and rep.bits_lost < 4, rep.report
        assert rep.report["sampled"]["points"] == 17 * 17 and rep.report["sampled"]["misassigned"] == 0, rep.report
        cand["pieces"][0]["patch"]["points"][0][0] += 2.0 ** -30
        rep = splinex.verify_compose(T, Sin, cand, method="trimmed")
        assert rep.bits_lost > 15 and rep.function_upper <= 2.0 ** -30, rep.report
    print("python module: all checks passed")


if __name__ == "__main__":
    main()
