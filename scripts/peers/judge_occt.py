#!/usr/bin/env python3
"""OpenCASCADE's B-spline results judged exactly by splinex (issue 16, part 3).

    PYTHONPATH=build/python python3 scripts/peers/judge_occt.py OUT_DIR [CASES] [OCCT_PEER]

OpenCASCADE (Debian libocct-modeling-data-dev, Geom_BSplineCurve) through build/bin/occt_peer
(bench/occt_peer.cpp, built where OCCT is installed): InsertKnot of one knot, IncreaseDegree by
one and D0 at 9 points, on the same cases as the SciPy and Octave judges (splinex's structured
curves and ordinary clamped curves of degree 1..7, rounded to double). All cases cross to one
occt_peer process as JSON lines, numbers with 17 significant digits (they read back to the same
double). Every result goes to splinex.verify against the exact result on the same input. Writes
occt.md, occt.json, occt_bits_vs_degree.svg and occt_bits_vs_spacing.svg.
"""
import json
import subprocess
import sys
from pathlib import Path

import splinex

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import double_inputs, judged_row, verify_into, verify_result, write_results  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def main():
    if len(sys.argv) not in (2, 3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    cases = int(sys.argv[2]) if len(sys.argv) >= 3 else 200
    peer = Path(sys.argv[3]) if len(sys.argv) == 4 else ROOT / "build" / "bin" / "occt_peer"
    if not peer.exists():
        print(f"judge_occt: {peer} does not exist (build with OpenCASCADE installed: scripts/run.sh peers)", file=sys.stderr)
        return 2
    inputs, rows = double_inputs(cases, 20261204)
    ops = ("insert", "elevate", "eval")
    lines = []
    for seed, suite, S, tags, u, xs in inputs:
        base = {"degree": S["degrees"][0], "knots": [f"{float(k):.17g}" for k in S["knots"][0]],
                "points": [[f"{float(x):.17g}" for x in pt] for pt in S["points"]]}
        if "weights" in S:
            base["weights"] = [f"{float(w):.17g}" for w in S["weights"]]
        for op in ops:
            lines.append(json.dumps(dict(base, op=op, u=f"{u:.17g}", xs=[f"{x:.17g}" for x in xs])))
    run = subprocess.run([str(peer)], input="\n".join(lines) + "\n", capture_output=True, text=True, timeout=3600)
    if run.returncode != 0:
        print(run.stderr[-2000:], file=sys.stderr)
        return 1
    answers = [json.loads(a) for a in run.stdout.splitlines()]
    if len(answers) != len(lines):
        print(f"judge_occt: {len(answers)} answers for {len(lines)} requests", file=sys.stderr)
        return 1
    k = 0
    for seed, suite, S, tags, u, xs in inputs:
        p = S["degrees"][0]
        for op in ops:
            a = answers[k]
            k += 1
            row = judged_row(seed, suite, op, S, tags)
            try:
                if "failure" in a:
                    raise RuntimeError("OCCT: " + a["failure"][:100])
                # The peer printed doubles: read them as the doubles they are (a str would be exact).
                if op == "eval":
                    result = [[float(v) for v in r] for r in a["values"]]
                else:
                    result = {"degrees": [a["degree"]], "knots": [[float(v) for v in a["knots"]]],
                              "points": [[float(v) for v in r] for r in a["points"]]}
                    if "weights" in a:
                        result["weights"] = [float(w) for w in a["weights"]]
                rep = verify_result(S, op, u, xs, result)
                verify_into(row, rep)
            except Exception as e:
                row["failure"] = f"{type(e).__name__}: {str(e)[:120]}"
            rows.append(row)
    rows.sort(key=lambda r: r["seed"])
    version = "OpenCASCADE " + occt_version()
    (out / "occt.json").write_text(json.dumps({"occt": version, "cases": cases, "rows": rows}, indent=1) + "\n")
    md = write_results(out, "occt", f"{version} judged exactly by splinex (Geom_BSplineCurve)",
                       f"{cases} curves of splinex's structured generator (C^-1 knots, unclamped ends, degree 0, single "
                       f"spans, knots 2^-60 apart, shifted domains), {cases} ordinary clamped curves of degree 1..7, {cases} "
                       "rational structured curves (poles and weights) and the report's adversarial curves, rounded to "
                       "double; `InsertKnot` (one knot, default tolerance), `IncreaseDegree` (degree + 1) and "
                       "`D0` (9 points), each judged by `splinex.verify` against the exact result on the same input. "
                       "Bits lost: the worst of the coefficient (or value) error and the certified function-level bound, "
                       "relative to the largest reference coefficient (or value), of 53.",
                       rows, ops, cases, version)
    print("\n".join(md[:10]))
    return 0


def occt_version():
    """The installed OpenCASCADE version, from its header."""
    for inc in (Path("/usr/include/opencascade/Standard_Version.hxx"),):
        if inc.exists():
            for line in inc.read_text().splitlines():
                if line.startswith("#define OCC_VERSION_COMPLETE"):
                    return line.split('"')[1]
    return "(version unknown)"


if __name__ == "__main__":
    sys.exit(main())
