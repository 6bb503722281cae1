#!/usr/bin/env python3
"""The Octave NURBS toolbox's B-spline results judged exactly by splinex (issue 16, part 3).

    PYTHONPATH=build/python python3 scripts/peers/judge_octave.py OUT_DIR [CASES]

Debian's octave-nurbs (the spline layer under GeoPDEs): bspkntins (one knot), bspdegelev (degree
+ 1) and bspeval (9 points), on splinex's structured curves (polynomial; rounded to double, the
input Octave gets), all cases in one Octave run. Numbers cross as text with 17 significant digits,
which reads back to the same double. Every result goes to splinex.verify against the exact result
on the same input. Writes octave.md (bits lost median / max, structure mismatches, failures, and
the worst cases with their structures), octave.json, octave_bits_vs_degree.svg and octave_bits_vs_spacing.svg.
"""
import json
import subprocess
from fractions import Fraction
import sys
import tempfile
from pathlib import Path

import splinex

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import double_inputs, homogeneous_input, judged_row, verify_into, verify_result, write_results  # noqa: E402  (the same input handling and figure)


def mat(rows):
    return "[" + "; ".join(" ".join(f"{float(x):.17g}" for x in r) for r in rows) + "]"


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    cases = int(sys.argv[2]) if len(sys.argv) == 3 else 200
    inputs, rows = double_inputs(cases, 20261203)
    script = ["pkg load nurbs",
              "function put(fid, tag, v)", "  fprintf(fid, '%s', tag); fprintf(fid, ' %.17g', v); fprintf(fid, '\\n');", "end",
              "args = argv(); fid = fopen(args{1}, 'w');"]
    judged_input = {}
    for seed, suite, S, tags, u, xs in inputs:
        p = S["degrees"][0]
        k = S["knots"][0]
        # Rational curves go through the NURBS layer (nrbmak with homogeneous coefficients
        # (w x, w y, w z, w), nrbkntins, nrbdegelev, nrbeval), judged against the exact input those
        # doubles are; polynomial ones through the B-spline layer (bspkntins, bspdegelev, bspeval).
        Sj, H = homogeneous_input(S)
        judged_input[seed] = Sj
        if H is not None:
            q = len(S["points"][0])
            if q > 3:
                judged_input[seed] = None  # the toolbox's NURBS are in 3D
                continue
            c4 = [row[:q] + [0.0] * (3 - q) + [row[q]] for row in H]
            script.append(f"c = {mat([list(col) for col in zip(*c4)])}; k = {mat([k])}; u = {u:.17g}; x = {mat([xs])}; "
                          "nrb = nrbmak(c, k);")
            calls = (("insert", "r = nrbkntins(nrb, u); ic = r.coefs; ik = r.knots;", True),
                     ("elevate", "r = nrbdegelev(nrb, 1); ic = r.coefs; ik = r.knots;", True),
                     ("eval", f"ic = nrbeval(nrb, x)(1:{q}, :);", False))
        else:
            c = [list(col) for col in zip(*S["points"])]  # dim x n, as the toolbox wants
            script.append(f"d = {p}; c = {mat(c)}; k = {mat([k])}; u = {u:.17g}; x = {mat([xs])};")
            calls = (("insert", "[ic, ik] = bspkntins(d, c, k, u);", True),
                     ("elevate", "[ic, ik] = bspdegelev(d, c, k, 1);", True),
                     ("eval", "ic = bspeval(d, c, k, x);", False))
        for op, call, has_knots in calls:
            script += ["try", "  " + call, f"  fprintf(fid, 'case {seed} {op} %d\\n', rows(ic));",
                       "  put(fid, 'k', ik);" if has_knots else "",
                       "  for r = 1:rows(ic), put(fid, 'c', ic(r, :)); end",
                       "catch e",
                       f"  fprintf(fid, 'case {seed} {op} ERR %s\\n', strrep(e.message, sprintf('\\n'), ' '));",
                       "end"]
    script.append("fclose(fid);")
    with tempfile.TemporaryDirectory() as tmp:
        m, res = Path(tmp) / "judge.m", Path(tmp) / "out.txt"
        m.write_text("1;\n" + "\n".join(script) + "\n")
        run = subprocess.run(["octave-cli", "--no-gui", "-q", str(m), str(res)], capture_output=True, text=True, timeout=3600)
        if run.returncode != 0 or not res.exists():
            print(run.stdout[-2000:], run.stderr[-2000:], file=sys.stderr)
            return 1
        lines = res.read_text().splitlines()
    version = subprocess.run(["octave-cli", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    results, i = {}, 0
    while i < len(lines):
        head = lines[i].split(" ", 3)
        seed, op = int(head[1]), head[2]
        if head[3].startswith("ERR"):
            results[(seed, op)] = ("ERR", head[3][4:])
            i += 1
            continue
        nrows = int(head[3])
        knots = None
        if op != "eval":
            knots = [float(v) for v in lines[i + 1].split()[1:]]
            i += 1
        coef = [[float(v) for v in lines[i + 1 + r].split()[1:]] for r in range(nrows)]
        results[(seed, op)] = (knots, coef)
        i += 1 + nrows
    for seed, suite, S0, tags, u, xs in inputs:
        p = S0["degrees"][0]
        S = judged_input[seed]
        if S is None:
            rows.append({"seed": seed, "suite": suite, "op": "input", "tags": tags,
                         "failure": "not handed over: the toolbox's NURBS have at most 3 coordinates"})
            continue
        for op in ("insert", "elevate", "eval"):
            row = judged_row(seed, suite, op, S0, tags)
            r = results.get((seed, op))
            try:
                if r is None:
                    raise RuntimeError("no output")
                if r[0] == "ERR":
                    raise RuntimeError("Octave: " + r[1][:100])
                knots, coef = r
                if op == "eval":
                    result = [list(v) for v in zip(*coef)]
                elif "weights" in S:  # homogeneous rows (w x, w y, w z, w): the rational they represent, exactly
                    q = len(S["points"][0])
                    cols = list(zip(*coef))
                    result = {"degrees": [p + (op == "elevate")], "knots": [knots],
                              "points": [[Fraction(h[c]) / Fraction(h[3]) for c in range(q)] for h in cols],
                              "weights": [h[3] for h in cols]}
                else:
                    result = {"degrees": [p + (op == "elevate")], "knots": [knots], "points": [list(v) for v in zip(*coef)]}
                rep = verify_result(S, op, u, xs, result)
                verify_into(row, rep)
            except Exception as e:
                row["failure"] = f"{type(e).__name__}: {str(e)[:120]}"
            rows.append(row)
    (out / "octave.json").write_text(json.dumps({"octave": version, "cases": cases, "rows": rows}, indent=1) + "\n")
    md = write_results(out, "octave", f"The Octave NURBS toolbox judged exactly by splinex ({version}, Debian octave-nurbs)",
                       f"{cases} curves of splinex's structured generator (C^-1 knots, unclamped ends, degree 0, single "
                       f"spans, knots 2^-60 apart, shifted domains), {cases} ordinary clamped curves of degree 1..7 with "
                       "simple knots at dyadic positions k/1024 (exact in double) and the report's adversarial curves, all "
                       "rounded to double: `bspkntins` (one knot), `bspdegelev` (degree + 1) and `bspeval` (9 points); "
                       f"and {cases} rational structured curves through the NURBS layer (`nrbmak` with homogeneous "
                       "coefficients rounded to double, `nrbkntins`, `nrbdegelev`, `nrbeval`), judged against the exact "
                       "curve those doubles are. Each result judged by `splinex.verify` against "
                       "the exact result on the same input. Bits lost: the worst of the coefficient (or value) error and "
                       "the certified function-level bound, relative to the largest reference coefficient (or value), of 53.",
                       rows, ("insert", "elevate", "eval"), cases, "Octave NURBS toolbox")
    print("\n".join(md[:10]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
