#!/usr/bin/env python3
"""Ratio table of one bench_kernel run (Google Benchmark JSON), as markdown and JSON.

    scripts/bench_table.py KERNEL.json OUT_DIR [PYTHON.json]

Every ratio is taken between timings of the same run (CPU time per iteration): each arithmetic
against double for the same operation, degree p and size n, and the geometric mean per operation.
The table names the machine, its load when the run started, the library versions and the date, so a
number can be traced to where it was measured. The README's speed section links the file this
writes; nothing in it is typed by hand.
"""
import json
import math
import os
import platform
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

# extract: the Bezier form in one object (SISL's s1730 returns the same); pieces: one BSpline per piece.
ORDER = ["insert", "refine", "elevate", "extract", "pieces", "eval"]


def version(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=10).stdout.strip().splitlines()[0]
    except Exception:
        return "unknown"


def pkg(name):
    out = version(["dpkg-query", "-W", "-f=${Version}", name])
    return out or "not installed"


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    doc = json.load(open(sys.argv[1]))
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    t = {}
    for b in doc["benchmarks"]:
        if b.get("error_occurred") or b.get("run_type", "iteration") != "iteration":
            continue
        op, arith, p, n = b["name"].split("/")[:4]
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
        t[(op, arith, int(p[1:]), int(n[1:]))] = b["cpu_time"] * scale
    python = None
    if len(sys.argv) == 4:
        python = json.load(open(sys.argv[3]))
        for c in python["cases"]:
            t[(c["op"], "fraction", c["p"], c["n"])] = c["seconds"]
    present = {k[1] for k in t}
    ariths = [a for a in ("exact", "flint", "mpfr128") if a in present]
    peers = [a for a in ("sisl", "occt") if a in present]
    ops = sorted({k[0] for k in t}, key=ORDER.index)
    # Columns: double against each peer, each exact/float arithmetic against double, the exact ones
    # against SISL (the fastest double peer).
    cols = [("double", pr) for pr in peers] + [(a, "double") for a in ariths]
    if "sisl" in peers:
        cols += [(a, "sisl") for a in ("exact", "flint") if a in ariths]
    if "fraction" in present:
        cols += [(a, "fraction") for a in ("exact", "flint") if a in ariths]
    names = {"exact": "GMP", "flint": "flint", "mpfr128": "mpfr128", "double": "double", "sisl": "SISL", "occt": "OCCT",
             "fraction": "Fraction"}
    rows, geo = [], defaultdict(list)
    for (op, arith, p, n), sec in sorted(t.items(), key=lambda kv: (ORDER.index(kv[0][0]), kv[0][2], kv[0][3])):
        if arith != "double":
            continue
        row = {"op": op, "p": p, "n": n, "double_us": sec * 1e6}
        for a, b_ in cols:
            num, den = t.get((op, a, p, n)), t.get((op, b_, p, n))
            if num is not None and den is not None:
                row[f"{a}/{b_}"] = num / den
                geo[(op, f"{a}/{b_}")].append(num / den)
        rows.append(row)
    ctx = doc.get("context", {})
    meta = {
        "date": ctx.get("date"),
        "host": platform.node(),
        "cpu": ctx.get("host_name", "") and platform.processor() or platform.processor(),
        "num_cpus": ctx.get("num_cpus"),
        "mhz_per_cpu": ctx.get("mhz_per_cpu"),
        "load_avg": ctx.get("load_avg"),
        "build_type": ctx.get("library_build_type"),
        "versions": {"gmp": pkg("libgmp-dev"), "mpfr": pkg("libmpfr-dev"), "flint": pkg("libflint-dev"),
                     "boost": pkg("libboost-dev"), "benchmark": pkg("libbenchmark-dev"), "g++": version(["g++", "--version"])},
        "peers": (("peers: " + ", ".join(names[p] for p in peers)) if peers else
                  "no peer installed (scripts/run.sh bench installs SISL and OpenCASCADE)") +
                 (f"; Python {python['python']} fractions.Fraction for insert and eval (scripts/bench_python.py, "
                  "results checked equal to splinex's exact ones; timed right after the C++ run)" if python else ""),
    }
    try:
        meta["cpu"] = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name"))
    except Exception:
        pass
    summary = {f"{op} {c}": math.exp(sum(map(math.log, v)) / len(v)) for (op, c), v in sorted(geo.items())}
    head = [f"{names[a]}/{names[b_]}" for a, b_ in cols]
    md = ["# Kernel speed: splinex's arithmetics and its peers, one run", "",
          f"{meta['date']} on {meta['cpu']} ({meta['num_cpus']} CPUs, load {meta['load_avg']}), "
          f"splinex Release build; GMP {meta['versions']['gmp']}, MPFR {meta['versions']['mpfr']}, "
          f"FLINT {meta['versions']['flint']}, {meta['versions']['g++']}; {meta['peers']}. "
          "CPU time per operation; every ratio is between timings of this run (below 1: the first is faster). "
          "Data: random clamped curves in R^3 with dyadic knots and coordinates (k/1024), `bench/bench_kernel.cpp`; "
          "OCCT modifies in place, so its insert/refine/elevate include a copy of the curve; SISL's extraction "
          "returns one curve in Bezier form, splinex's a list of Bezier pieces.", "",
          "## Geometric mean over p and n", "",
          "| operation | " + " | ".join(head) + " |", "|---|" + "---|" * len(cols)]
    for op in ops:
        md.append(f"| {op} | " + " | ".join(f"{summary[f'{op} {a}/{b_}']:.3g}" if f"{op} {a}/{b_}" in summary else "-" for a, b_ in cols) + " |")
    md += ["", "## Every case", "", "| operation | p | n | double (us) | " + " | ".join(head) + " |",
           "|---|---|---|---|" + "---|" * len(cols)]
    for r in rows:
        md.append(f"| {r['op']} | {r['p']} | {r['n']} | {r['double_us']:.3g} | " +
                  " | ".join(f"{r[f'{a}/{b_}']:.3g}" if f"{a}/{b_}" in r else "-" for a, b_ in cols) + " |")
    json.dump({"meta": meta, "geometric_means": summary, "rows": rows}, open(out / "kernel.json", "w"), indent=1)
    (out / "kernel.md").write_text("\n".join(md) + "\n")
    # The generated block of docs/speed.md: the summary table and where it was measured.
    speed = Path(__file__).resolve().parent.parent / "docs" / "speed.md"
    if speed.exists():
        text = speed.read_text()
        begin, end = "<!-- bench:kernel:begin -->", "<!-- bench:kernel:end -->"
        if begin in text and end in text:
            block = "\n".join([begin, md[2], ""] + md[4:8 + len(ops)] +
                               ["", "Every case: [bench/results/kernel.md](../bench/results/kernel.md).", end])
            text = text[:text.index(begin)] + block + text[text.index(end) + len(end):]
            speed.write_text(text)
    print("\n".join(md[:8 + len(ops)]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
