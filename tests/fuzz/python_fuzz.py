#!/usr/bin/env python3
"""Mutation fuzzer for the Python module splinex (issue 47).

Every case calls one function of the module (validate, evaluate, insert_knots, elevate,
extract_bezier, split, reverse, verify, verify_compose, structured_case) on mutated splines and
mutated arguments, in a child interpreter of its own under a CPU-time budget (RLIMIT_CPU) and an
address-space cap (RLIMIT_AS), and is classified:

  ok-value   the call returned
  ok-error   a Python exception a caller can catch and understand: ValueError (splinex's one-line
             text: "<where>: <what> ... (fix: ...)"), or TypeError (an argument of the wrong type,
             or a keyword the function does not take)
  FAIL-*     anything else: the interpreter killed by a signal (crash, abort), the CPU budget
             exhausted (a hang), MemoryError, RuntimeError or any other exception type, a
             ValueError without splinex's text, or a child that printed no outcome

An oracle checks what returned, exactly (Fractions): a validated spline is the same spline read
back; insert_knots, elevate, split and reverse keep the function (evaluate before and after at
the domain's ends and midpoints, exactly); extract_bezier's pieces equal the spline at their
midpoints; verify of the exact result itself gives structure "equal". A mismatch is FAIL-oracle.

Failures are written to OUT/failures/<n>/case.py, a script that replays the case by hand. The exit
status is 1 if any case failed.

  PYTHONPATH=build/python python3 tests/fuzz/python_fuzz.py --cases 300 --seed 1 --out fuzz-py
"""
import argparse
import copy
import json
import os
import random
import resource
import shutil
import subprocess
import sys
import time

# The oracle reads exact values as Python integers; a knot like -1e100000 has 100001 digits, past
# CPython's default limit on int <-> str conversion (3.11+), which would fail the oracle, not splinex.
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)

EXTREME = ["0", "-0", "1", "-1", "1e100000", "-1e100000", "1e-100000", "1e-400", "1e400", "1/3", "-7/3", "1/0",
           "0/0", "2^3", "0x10", "1e", ".", "", "nan", "inf", "9" * 400, "1/" + "3" * 100, "4.9e-324",
           float("nan"), float("inf"), -float("inf"), 1e308, 5e-324, -0.0, 0.5, True, False, None, [], {},
           10 ** 30, -(10 ** 30), 2 ** 63, 10 ** 1300]
INTS = [-(2 ** 63) - 1, -(2 ** 31) - 1, -100000, -1, 0, 1, 2, 3, 7, 30, 100, 2 ** 31 - 1, 2 ** 31, 2 ** 63, 10 ** 30,
        "0", 0.5, None, True, [0]]
SPLINES = [
    {"degrees": [3], "knots": [[0, 0, 0, 0, "1/3", 0.5, 1, 1, 1, 1]],
     "points": [[0, 0], [1, 2], ["22/7", "1e-3"], [3, 0.784], [4, 1], [5, "-1/2"]]},
    {"degrees": [1], "knots": [[0, 0, 1, 1]], "points": [[0], [1]]},
    {"degrees": [0], "knots": [[0, 1]], "points": [[2, 3]]},
    {"degrees": [2], "knots": [[0, 0, 0, 1, 1, 1]], "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, "1/2", 1]},
    {"degrees": [2, 1], "knots": [[0, 0, 0, 1, 1, 1], [-1, -1, 2, 2]],
     "points": [[0, 0, 0], [1, 0, 1], [2, 0, 0], [0, 1, 1], [1, 1, 2], [2, 1, "1/7"]]},
    {"degrees": [2], "knots": [[0, 0, 0, "1/2", "1/2", "1/2", 1, 1, 1]], "points": [[0], [1], [2], [5], [3], [1]]},
]
FUNCTIONS = ["validate", "evaluate", "insert_knots", "elevate", "extract_bezier", "split", "reverse", "verify",
             "verify_compose", "structured_case"]
VERIFY_OPS = ["insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse", "derivative", "eval",
              "compose", "nope", ""]
ALLOWED = ("ValueError", "TypeError")


# ---------------------------------------------------------------------------------------------
# Case generation (deterministic from the seed and the case number; runs in parent and child).

def paths(value, path=()):
    yield path, value
    if len(path) > 40:  # deep nests are mutated as a whole
        return
    if isinstance(value, dict):
        for k, v in list(value.items()):
            yield from paths(v, path + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from paths(v, path + (i,))


def mutate(rng, doc):
    """A copy of doc with 0-3 structural or value mutations; may make it contain itself."""
    doc = json.loads(json.dumps(doc))
    for _ in range(rng.choice([0, 1, 1, 1, 2, 3])):
        ps = list(paths(doc))
        path, value = rng.choice(ps)
        r = rng.random()
        if isinstance(value, list) and value and r < 0.3:
            op = rng.choice(["drop", "dup", "swap", "empty", "grow", "nest"])
            if op == "drop":
                value.pop(rng.randrange(len(value)))
            elif op == "dup":
                i = rng.randrange(len(value))
                value.insert(i, json.loads(json.dumps(value[i])))
            elif op == "swap" and len(value) > 1:
                i, j = rng.randrange(len(value)), rng.randrange(len(value))
                value[i], value[j] = value[j], value[i]
            elif op == "empty":
                value.clear()
            elif op == "grow":
                value.extend(json.loads(json.dumps(value)) * rng.choice([1, 3, 40]))
            elif op == "nest":
                v = json.loads(json.dumps(value))
                for _ in range(rng.choice([2, 70, 300])):
                    v = [v]
                value[:] = [v]
        elif isinstance(value, dict) and value and r < 0.35:
            k = rng.choice(list(value))
            op = rng.choice(["drop", "rename", "extra", "type"])
            if op == "drop":
                del value[k]
            elif op == "rename":
                value[k + "x"] = value.pop(k)
            elif op == "extra":
                value["extra"] = 1
            else:
                value["type"] = rng.choice(["bspline", "nurbs", "bezier", 3])
        elif path:
            cur = doc
            for p in path[:-1]:
                cur = cur[p]
            cur[path[-1]] = copy.deepcopy(rng.choice(EXTREME) if rng.random() < 0.8 else rng.choice(INTS))
    return doc


def number(rng):
    return rng.choice([rng.choice(EXTREME), rng.choice(INTS), "1/2", 0.25, 0, 1, "3/4", rng.uniform(-2, 2)])


def case_for(seed, k):
    """(function, args, kwargs, self_reference) of case k."""
    rng = random.Random(seed * 1000003 + k)
    f = rng.choice(FUNCTIONS)
    S = mutate(rng, rng.choice(SPLINES)) if rng.random() < 0.6 else json.loads(json.dumps(rng.choice(SPLINES)))
    self_ref = rng.random() < 0.03
    kw = {}
    if f == "validate":
        args = [S]
    elif f == "evaluate":
        args = [S, rng.choice([number(rng), [number(rng)], [number(rng), number(rng)], [0.5], [0.5, 0.5], "1/2"])]
    elif f == "insert_knots":
        args = [S, rng.choice([[number(rng)], [0.5, 0.5, 0.5], [], number(rng), ["1/3"] * rng.choice([1, 5, 200])])]
        if rng.random() < 0.5:
            kw["dir"] = rng.choice(INTS)
    elif f == "elevate":
        args = [S]
        if rng.random() < 0.8:
            kw["by"] = rng.choice(INTS)
        if rng.random() < 0.4:
            kw["dir"] = rng.choice(INTS)
    elif f == "extract_bezier":
        args = [S]
    elif f == "split":
        args = [S, rng.choice([number(rng), "1/2", 0.25])]
        if rng.random() < 0.4:
            kw["dir"] = rng.choice(INTS)
    elif f == "reverse":
        args = [S]
        if rng.random() < 0.4:
            kw["dir"] = rng.choice(INTS)
    elif f == "verify":
        op = rng.choice(VERIFY_OPS)
        cand = rng.choice([mutate(rng, rng.choice(SPLINES)), [S], {"pieces": [S]}, {"splines": [S]},
                           {"at": [[0.5]], "values": [[1]]}, {"at": [number(rng)], "values": [number(rng)]}, 3, None,
                           "x", [S, S]])
        args = [op, S, cand]
        for name, choices in (("knots", [["1/2"], [number(rng)], 3]), ("by", INTS), ("at", ["1/2", number(rng)]),
                              ("interval", [["0", "1"], [1, 0], [number(rng), number(rng)], 5]),
                              ("order", INTS), ("dir", INTS), ("precision", INTS), ("factor", INTS + [1.5, "2"]),
                              ("bogus", [1])):
            if rng.random() < 0.25:
                kw[name] = rng.choice(choices)
    elif f == "verify_compose":
        T = mutate(rng, rng.choice(SPLINES))
        args = [T, S, rng.choice([S, {"regions": []}, {"tiles": []}, mutate(rng, S), None, 3])]
        if rng.random() < 0.7:
            kw["method"] = rng.choice(["symbolic", "interpolation", "trimmed", "tensor", "nope"])
        if rng.random() < 0.3:
            kw["expand"] = rng.choice([True, False, 3, None])
        if rng.random() < 0.3:
            kw["precision"] = rng.choice(INTS)
    else:  # structured_case
        args = [rng.choice([0, 1, 7, 2 ** 64 - 1, -1, 2 ** 64, "1", None])]
        for name, choices in (("max_dim", INTS), ("rational", [True, False, 1, "x"]),
                              ("discontinuous", [True, False]), ("extreme_values", [True, False, None])):
            if rng.random() < 0.4:
                kw[name] = rng.choice(choices)
    return f, args, kw, self_ref


# ---------------------------------------------------------------------------------------------
# The child: one case, one line of outcome on stdout.

def same_function(splinex, A, B, Fraction):
    """A and B evaluated exactly at the ends and midpoints of A's knot spans (direction 0; other
    directions at their domain's midpoint)."""
    ka = [[Fraction(x) for x in k] for k in A["knots"]]
    pa = A["degrees"]
    lo = [k[p] for k, p in zip(ka, pa)]
    hi = [k[len(k) - p - 1] for k, p in zip(ka, pa)]
    xs = sorted(set(x for x in ka[0] if lo[0] <= x <= hi[0]))
    ts = set(xs)
    for a, b in zip(xs, xs[1:]):
        ts.add((a + b) / 2)
        ts.add((2 * a + b) / 3)
    for t in sorted(ts)[:40]:
        at = [t] + [(l + h) / 2 for l, h in zip(lo[1:], hi[1:])]
        if t == hi[0]:
            continue  # right end: one-sided values may legitimately differ at C^-1 knots, skip
        va, vb = splinex.evaluate(A, at), splinex.evaluate(B, at)
        if va != vb:
            return "at %s: %s != %s" % (at, va, vb)
    return None


def oracle(splinex, f, args, kw, result, Fraction):
    S = args[0] if f not in ("verify", "structured_case") else None
    d = kw.get("dir", 0)
    if f == "validate":
        again = splinex.validate(result)
        if again != result:
            return "validate is not idempotent"
    elif f in ("insert_knots", "elevate", "reverse") and isinstance(d, int) and d == 0:
        R = result
        if f == "reverse":
            R2 = splinex.reverse(R)
            if splinex.validate(R2) != splinex.validate(S):
                return "reverse(reverse(S)) != S"
            return None
        return same_function(splinex, splinex.validate(S), R, Fraction)
    elif f == "split" and isinstance(d, int) and d == 0:
        L, R = result
        V = splinex.validate(S)
        for piece in (L, R):
            k, p = piece["knots"][0], piece["degrees"][0]
            a, b = k[p], k[len(k) - p - 1]
            for t in (a, (a + b) / 2):
                at = [t] + [(Fraction(x[q]) + Fraction(x[len(x) - q - 1])) / 2
                            for x, q in zip(V["knots"][1:], V["degrees"][1:])]
                if splinex.evaluate(piece, at) != splinex.evaluate(V, at):
                    return "split piece differs from S at %s" % at
    elif f == "extract_bezier":
        V = splinex.validate(S)
        for pc in result[:30]:
            mid = [(a + b) / 2 for a, b in pc["box"]]
            if splinex.evaluate(pc["spline"], mid) != splinex.evaluate(V, mid):
                return "Bezier piece differs from S at %s" % mid
    elif f == "verify" and args[0] in ("elevate", "reverse", "insert-knots") and hasattr(result, "structure"):
        pass  # a candidate's structure depends on the candidate; the CLI tests judge verify's verdicts
    return None


def plant(f, result, Fraction):
    """The planted bug of --plant: one coordinate of a returned spline moved by 10^-9, so that a
    test can show the oracle refutes it."""
    R = result[0] if f == "split" else result[0]["spline"] if f == "extract_bezier" and result else result
    if f in ("insert_knots", "elevate", "split", "extract_bezier") and isinstance(R, dict) and R.get("points"):
        R["points"][len(R["points"]) // 2][0] += Fraction(1, 10 ** 9)
    return result


def child(seed, k, planted=False):
    import fractions
    import splinex
    f, args, kw, self_ref = case_for(seed, k)
    if self_ref and isinstance(args[0] if f != "verify" else args[1], dict):
        target = args[0] if f != "verify" else args[1]
        if isinstance(target.get("points", []), list):
            target.setdefault("points", []).append(target)
        else:
            target["points"] = [target]
    try:
        result = getattr(splinex, f)(*args, **kw)
    except Exception as e:  # noqa: BLE001 - classified by the parent
        print(json.dumps({"exception": type(e).__name__, "message": str(e)[:2000]}))
        return
    if planted:
        result = plant(f, result, fractions.Fraction)
    try:
        bad = oracle(splinex, f, args, kw, result, fractions.Fraction)
    except Exception as e:  # noqa: BLE001
        bad = "the oracle's own calls failed on the result: %s: %s" % (type(e).__name__, str(e)[:500])
    print(json.dumps({"returned": True, "oracle": bad}))


# ---------------------------------------------------------------------------------------------
# The parent.

def classify(rc, out, err):
    if rc < 0:
        return "FAIL-signal-%d" % -rc
    lines = [l for l in out.decode(errors="replace").splitlines() if l.startswith("{")]
    if rc != 0 or not lines:
        return "FAIL-no-outcome"
    o = json.loads(lines[-1])
    if o.get("returned"):
        return "FAIL-oracle" if o.get("oracle") else "ok-value"
    e, msg = o["exception"], o["message"]
    if e not in ALLOWED:
        return "FAIL-" + e
    if e == "ValueError" and ("\n" in msg.strip() or ": " not in msg):
        return "FAIL-untyped-ValueError"
    return "ok-error"


def main():
    if len(sys.argv) in (4, 5) and sys.argv[1] == "--child":
        child(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:] == ["--plant"])
        return 0
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cpu", type=int, default=20, help="CPU seconds per case (RLIMIT_CPU)")
    ap.add_argument("--memory", default="4G", help="address-space cap per case (RLIMIT_AS)")
    ap.add_argument("--out", default="fuzz-py")
    ap.add_argument("--plant", action="store_true",
                    help="move one coordinate of every returned spline by 10^-9: the oracle must refute it "
                         "(exit 0 only if some case ended FAIL-oracle and no case failed otherwise)")
    a = ap.parse_args()
    units = {"M": 20, "G": 30}
    cap = int(a.memory[:-1]) << units[a.memory[-1]]

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
        resource.setrlimit(resource.RLIMIT_CPU, (a.cpu, a.cpu + 5))

    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    counts, failures, t0 = {}, 0, time.time()
    for k in range(a.cases):
        cmd = [sys.executable, os.path.abspath(__file__), "--child", str(a.seed), str(k)] + (["--plant"] if a.plant else [])
        try:
            p = subprocess.run(cmd, capture_output=True, timeout=10 * a.cpu, preexec_fn=limit)
            rc, out, err = p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired as e:
            rc, out, err = -999, e.stdout or b"", e.stderr or b""
        verdict = "FAIL-wall-timeout" if rc == -999 else classify(rc, out, err)
        if verdict in ("FAIL-signal-24", "FAIL-signal-9"):
            verdict = "FAIL-cpu-budget"
        counts[verdict] = counts.get(verdict, 0) + 1
        if verdict.startswith("FAIL"):
            failures += 1
            d = os.path.join(a.out, "failures", "%05d" % k)
            os.makedirs(d)
            f, args, kw, self_ref = case_for(a.seed, k)
            with open(os.path.join(d, "case.py"), "w") as fh:
                fh.write("# %s (seed %d, case %d); replay: python3 %s --child %d %d\n" %
                         (verdict, a.seed, k, os.path.abspath(__file__), a.seed, k))
                fh.write("import splinex\nf, args, kw, self_ref = %r, %r, %r, %r\n" % (f, args, kw, self_ref))
                fh.write("print(getattr(splinex, f)(*args, **kw))\n")
            with open(os.path.join(d, "output"), "wb") as fh:
                fh.write(out[-20000:] + b"\n--- stderr ---\n" + err[-20000:])
            print("case %d: %s: %s" % (k, verdict, f), file=sys.stderr)
        if (k + 1) % 100 == 0:
            print("%d/%d cases, %d failures, %.0f s" % (k + 1, a.cases, failures, time.time() - t0), file=sys.stderr)
    summary = {"cases": a.cases, "seed": a.seed, "cpu_s": a.cpu, "memory": a.memory,
               "seconds": round(time.time() - t0, 1), "outcomes": dict(sorted(counts.items())), "failures": failures}
    with open(os.path.join(a.out, "summary.json"), "w") as fh:
        json.dump(summary, fh, indent=2)
    print(json.dumps(summary, indent=2))
    if a.plant:
        refuted = counts.get("FAIL-oracle", 0)
        print("planted bug refuted by the oracle in %d cases" % refuted)
        return 0 if refuted > 0 and refuted == failures else 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
