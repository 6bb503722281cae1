#!/usr/bin/env python3
"""Ratio table of one bench_kernel run (Google Benchmark JSON), as markdown and JSON.

    scripts/bench_table.py KERNEL.json OUT_DIR

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


def version(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=10).stdout.strip().splitlines()[0]
    except Exception:
        return "unknown"


def pkg(name):
    out = version(["dpkg-query", "-W", "-f=${Version}", name])
    return out or "not installed"


def main():
    if len(sys.argv) != 3:
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
    ariths = [a for a in ("exact", "flint", "mpfr128") if any(k[1] == a for k in t)]
    ops = sorted({k[0] for k in t}, key=["insert", "refine", "elevate", "extract", "eval"].index)
    rows, geo = [], defaultdict(list)
    for (op, arith, p, n), sec in sorted(t.items()):
        if arith != "double":
            continue
        row = {"op": op, "p": p, "n": n, "double_us": sec * 1e6}
        for a in ariths:
            other = t.get((op, a, p, n))
            if other is not None:
                row[a + "_over_double"] = other / sec
                geo[(op, a)].append(other / sec)
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
        "peers": "OpenCASCADE and SISL peers are not built yet (issue 15); only splinex's own arithmetics are compared",
    }
    try:
        meta["cpu"] = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name"))
    except Exception:
        pass
    summary = {f"{op}/{a}": math.exp(sum(map(math.log, v)) / len(v)) for (op, a), v in sorted(geo.items())}
    json.dump({"meta": meta, "geometric_means": summary, "rows": rows}, open(out / "kernel.json", "w"), indent=1)
    md = [f"# Kernel speed: each arithmetic against double, one run", "",
          f"{meta['date']} on {meta['cpu']} ({meta['num_cpus']} CPUs, load {meta['load_avg']}), "
          f"build {meta['build_type']}; GMP {meta['versions']['gmp']}, MPFR {meta['versions']['mpfr']}, "
          f"FLINT {meta['versions']['flint']}, {meta['versions']['g++']}. CPU time per operation, ratios within this run. "
          "Data: random clamped curves in R^3 with dyadic knots and coordinates (k/1024), `bench/bench_kernel.cpp`. "
          + meta["peers"] + ".", "",
          "## Geometric mean over p and n", "",
          "| operation | " + " | ".join(f"{a}/double" for a in ariths) + " |",
          "|---|" + "---|" * len(ariths)]
    for op in ops:
        md.append(f"| {op} | " + " | ".join(f"{summary[f'{op}/{a}']:.1f}" if f"{op}/{a}" in summary else "-" for a in ariths) + " |")
    md += ["", "## Every case", "", "| operation | p | n | double (us) | " + " | ".join(f"{a}/double" for a in ariths) + " |",
           "|---|---|---|---|" + "---|" * len(ariths)]
    for r in rows:
        md.append(f"| {r['op']} | {r['p']} | {r['n']} | {r['double_us']:.3g} | " +
                  " | ".join(f"{r[a + '_over_double']:.1f}" if a + "_over_double" in r else "-" for a in ariths) + " |")
    (out / "kernel.md").write_text("\n".join(md) + "\n")
    print("\n".join(md[:8 + len(ops)]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
