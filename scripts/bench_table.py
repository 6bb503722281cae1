#!/usr/bin/env python3
"""Ratio table of one bench_kernel run (Google Benchmark JSON), as markdown and JSON.

    scripts/bench_table.py KERNEL.json OUT_DIR [PYTHON.json] [--compose COMPOSE.json] [--hybrid HYBRID.json]
                           [--vrep VREP.json] [--solve SOLVE.json] [--cut CUT.json]

Writes OUT_DIR/kernel.md and kernel.json (every case, the targets of issues 15 and 49) and
OUT_DIR/exactness.md, the report's section "what exactness costs" (`splinex report --bench OUT_DIR`):
the naive exact kernels (GMP mpq, FLINT fmpq), the fraction-free one (`exact`), double, MPFR and the
peers (SISL, OpenCASCADE, Python's Fraction) side by side as ratios to double, the bytes per stored
exact value, and the higher levels' exact/double.

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


def seconds(b):
    return b["cpu_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]


def load_runs(path):
    """name without the /iterations:N suffix -> CPU seconds, of one Google Benchmark JSON file."""
    out = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("error_occurred") or b.get("run_type", "iteration") != "iteration":
            continue
        out[b["name"].split("/iterations:")[0]] = seconds(b)
    return out


def fmt(x):
    return "-" if x is None else f"{x:.3g}"


def targets(t, compose, hybrid, vrep=None, mem=None):
    """Issues 15's and 49's targets against this run: each one's measured value, the bound, met or how far."""
    rows = []

    def add(what, value, bound, better="<="):
        if bound is None:  # a measurement without a target of issue 15
            rows.append((what, "-" if value is None else f"{value:.3g}", "no target", "measured"))
            return
        if value is None:
            rows.append((what, "-", f"{better} {bound:g}", "not measured in this run"))
            return
        met = value <= bound if better == "<=" else value >= bound
        rows.append((what, f"{value:.3g}", f"{better} {bound:g}",
                     "met" if met else f"{value / bound:.3g}x the bound" if better == "<=" else f"{bound / value:.3g}x short"))

    cases = sorted({(k[0], k[2], k[3]) for k in t if k[1] == "double"})
    for op in ("insert", "refine", "elevate", "extract", "eval"):
        for peer in ("sisl", "occt"):
            r = [t[(o, "double", p, n)] / t[(o, peer, p, n)] for (o, p, n) in cases if o == op and (o, peer, p, n) in t]
            if r:
                add(f"{op}: worst double/{peer.upper()} over p, n ({sum(x > 1 for x in r)} of {len(r)} cases above 1)",
                    max(r), 1.0)
    # Issue 49: the bounds on the best exact arithmetic (exact = fraction-free, gmp, flint).
    exacts = ("exact", "gmp", "flint")
    for op, bound in (("insert", 2), ("refine", 5), ("eval", 3), ("elevate", 4), ("extract", 10)):
        d = t.get((op, "double", 3, 1000))
        best = min((t[(op, a, 3, 1000)] for a in exacts if (op, a, 3, 1000) in t), default=None)
        add(f"{op}: best exact arithmetic / double at p = 3, n = 1000", best / d if best and d else None, bound)
    for op in ORDER:
        r = [min(t[(op, a, 7, n)] for a in exacts if (op, a, 7, n) in t) / t[(op, "double", 7, n)]
             for (o, p, n) in cases if o == op and p == 7 and any((op, a, 7, n) in t for a in exacts)]
        add(f"{op}: worst best-exact / double at p = 7 over n", max(r) if r else None, 25)
    r = [t[("insert", "fraction", p, n)] / t[("insert", "exact", p, n)] for (o, p, n) in cases
         if o == "insert" and n >= 1000 and ("insert", "fraction", p, n) in t and ("insert", "exact", p, n) in t]
    add("insert: worst Python Fraction / exact over p, n >= 1000 (how many times faster)", min(r) if r else None, 20, ">=")
    for op, bound in (("insert", 1.0), ("eval", 0.1)):
        r = [t[(op, "gmp", p, n)] / t[(op, "fraction", p, n)] for (o, p, n) in cases
             if o == op and (op, "fraction", p, n) in t and (op, "gmp", p, n) in t]
        add(f"{op}: worst GMP / Python Fraction over p, n", max(r) if r else None, bound)
    if mem:
        b = [v["bytes_per_coef"] for (op, a, p, n), v in mem.items() if a == "exact" and n == 10000 and "bytes_per_coef" in v]
        add("exact: worst bytes per coefficient of a result, n = 10^4", max(b) if b else None, 16)
    if compose:
        for a in ("exact", "flint"):
            tot = [v for k, v in compose.items() if k.startswith(f"stars/{a}/")]
            add(f"Algorithm 1, teapot star pattern, all four surfaces, {a} (s)", sum(tot) if len(tot) == 4 else None, 1.0)
        for k, v in sorted(compose.items()):
            if k.startswith("untrim_star/exact/"):
                surf = k.split("/")[2]
                d = compose.get(f"untrim_star/double/{surf}")
                add(f"Algorithm 2, one star, {surf}: exact / double", v / d if d else None, 20)
    if hybrid:
        for k, v in sorted(hybrid.items()):
            parts = k.split("/")
            if len(parts) == 4 and parts[2] == "exact":
                d = hybrid.get(f"{parts[0]}/{parts[1]}/double/{parts[3]}")
                add(f"hybrid patch {parts[1]}, {parts[3][1:]} sides: exact / double per point", v / d if d else None, 30)
    if vrep:
        for k, v in sorted(vrep.items()):
            parts = k.split("/")
            if len(parts) == 4 and parts[2] == "exact":
                d = vrep.get(f"{parts[0]}/{parts[1]}/double/{parts[3]}")
                add(f"V-rep {parts[1]}, {parts[3]}: exact / double", v / d if d else None, None)
    return rows


# The arithmetics of the higher benchmarks, as the third-from-last or middle part of a name.
HIGHER_ARITHS = ("double", "exact", "gmp", "flint", "mpfr53", "mpfr200", "newton16", "judge")
HIGHER_NAMES = {"compose": "composition (bench_compose)", "hybrid": "hybrid patch (bench_hybrid)",
                "vrep": "V-rep (bench_vrep)", "solve": "solver (bench_solve)", "cut": "cutting (bench_cut)"}


def higher_rows(runs):
    """{name: seconds} of one higher benchmark -> rows (case, double seconds, {arith: ratio to double})."""
    groups = defaultdict(dict)
    for name, sec in runs.items():
        parts = name.split("/")
        idx = [i for i, x in enumerate(parts) if x in HIGHER_ARITHS]
        if not idx:
            continue
        arith = parts[idx[0]]
        case = "/".join(parts[:idx[0]] + parts[idx[0] + 1:])
        groups[case][arith] = sec
    rows = []
    for case, by in sorted(groups.items()):
        d = by.get("double")
        if d and any(a != "double" for a in by):
            rows.append((case, d, {a: v / d for a, v in by.items() if a != "double"}))
    return rows


# What a reader of a higher level's table needs to know to read its ratios.
HIGHER_NOTES = {
    "cut": "The guide's double run solves the rounded program with CGAL's exact solver on Gmpzf (no float QP method "
           "yet, docs/cut.md), while the exact run solves by a float active set certified exactly: that is why its "
           "exact / double is below 1.",
    "vrep": "`judge`: the exact judgement of the float surface-surface intersection's points (Krawczyk certificates), "
            "against the float intersection itself.",
    "solve": "`mpfr53`, `mpfr200`: the certified solver in MPFR at 53 and 200 bits; `newton16`: an uncertified projection "
             "in double (Newton from a 16 x 16 grid of starts, what a CAD kernel does), against the certified double solver.",
}


def exactness(t, mem, higher, meta, provenance, target_rows=()):
    """The report's section "what exactness costs", from the same run as kernel.md."""
    names = {"exact": "exact", "gmp": "GMP", "flint": "FLINT", "mpfr128": "MPFR 128", "sisl": "SISL", "occt": "OCCT",
             "fraction": "Python Fraction"}
    cols = [a for a in names if any(k[1] == a for k in t)]
    md = ["# What exactness costs", "",
          "From one `scripts/run.sh bench` run: " + provenance, "",
          "Three exact arithmetics compute the same values (every result equal, tests/exact/test_ffnet.cpp and "
          "`splinex prove ff-agreement`): `exact`, the fraction-free kernel (integer homogeneous coordinates over one "
          "denominator per point, integer knots over one denominator per knot vector, FLINT words that are plain "
          "64-bit integers while they fit), and the two naive kernels, `GMP` (one mpq per coefficient) and `FLINT` "
          "(one fmpq per coefficient), each field operation reduced on the spot. `MPFR 128` is a 128-bit float; SISL "
          "and OpenCASCADE are double libraries; Python's `fractions.Fraction` runs the same insertion and evaluation "
          "(scripts/bench_python.py). Each entry is that column's CPU time over splinex's double time for the same "
          "operation and curve (below 1: faster than splinex in double).", ""]
    for p in (3, 7):
        cases = [op for op in ORDER if (op, "double", p, 1000) in t]
        if not cases:
            continue
        md += [f"## Degree {p}, n = 1000: time / double", "",
               "| operation | double (us) | " + " | ".join(names[a] for a in cols) + " |", "|---|---|" + "---|" * len(cols)]
        for op in cases:
            d = t[(op, "double", p, 1000)]
            md.append(f"| {op} | {d * 1e6:.3g} | " + " | ".join(fmt(t[(op, a, p, 1000)] / d) if (op, a, p, 1000) in t else "-"
                                                             for a in cols) + " |")
        md.append("")
    geo = defaultdict(list)
    for (op, a, p, n), v in t.items():
        d = t.get((op, "double", p, n))
        if a != "double" and d:
            geo[(op, a)].append(v / d)
    span = sorted({(k[2], k[3]) for k in t if k[1] == "double"})
    if span:
        md += [f"## Every degree ({', '.join(map(str, sorted({p for p, _ in span})))}) and size "
               f"({', '.join(map(str, sorted({n for _, n in span})))}): geometric mean of time / double, and the worst case",
               "", "| operation | " + " | ".join(names[a] for a in cols) + " |", "|---|" + "---|" * len(cols)]
        for op in [o for o in ORDER if any(k[0] == o for k in geo)]:
            md.append(f"| {op} | " + " | ".join(
                f"{math.exp(sum(map(math.log, geo[(op, a)])) / len(geo[(op, a)])):.3g} (worst {max(geo[(op, a)]):.3g})"
                if geo.get((op, a)) else "-" for a in cols) + " |")
        md.append("")
    store = [a for a in ("double", "exact", "gmp", "flint") if any(k[1] == a and "bytes_per_coef" in v for k, v in mem.items())]
    if store:
        md += ["## Storage: bytes per stored value of the result, n = 10^4", "",
               "The value itself and what it holds on the heap (allocator overhead not counted), over every coordinate, "
               "weight and knot of the result; a double is 8.", "",
               "| operation | p | " + " | ".join(names.get(a, a) for a in store) + " |", "|---|---|" + "---|" * len(store)]
        for (op, p) in sorted({(k[0], k[2]) for k in mem if k[3] == 10000}, key=lambda k: (ORDER.index(k[0]), k[1])):
            cells = [mem.get((op, a, p, 10000), {}).get("bytes_per_coef") for a in store]
            if any(c is not None for c in cells):
                md.append(f"| {op} | {p} | " + " | ".join(fmt(c) for c in cells) + " |")
        md.append("")
    for key, runs in higher.items():
        rows = higher_rows(runs)
        if not rows:
            continue
        others = sorted({a for _, _, r in rows for a in r}, key=HIGHER_ARITHS.index)
        md += [f"## Above the kernel: {HIGHER_NAMES[key]}, time / double", "",
               "| case | double (ms) | " + " | ".join(others) + " |", "|---|---|" + "---|" * len(others)]
        for case, d, r in rows:
            md.append(f"| {case} | {d * 1e3:.3g} | " + " | ".join(fmt(r.get(a)) for a in others) + " |")
        md.append("")
        if key in HIGHER_NOTES:
            md += [HIGHER_NOTES[key], ""]
    if not higher:
        md += ["The higher levels (composition, the hybrid patch, the V-rep, the solver, cutting) were not part of this "
               "run.", ""]
    exact_targets = [r for r in target_rows if "/SISL" not in r[0] and "/OCCT" not in r[0] and r[2] != "no target"]
    if exact_targets:
        md += ["## Issue 49's targets in this run", "", "| target | measured | bound | verdict |", "|---|---|---|---|"] + \
              [f"| {w} | {v} | {b} | {m} |" for w, v, b, m in exact_targets] + [""]
    md.append("Every kernel case and the memory counters: bench/results/kernel.md.")
    return md


def main():
    args = sys.argv[1:]
    extra = {}
    for flag in ("--compose", "--hybrid", "--vrep", "--solve", "--cut"):
        if flag in args:
            i = args.index(flag)
            extra[flag] = load_runs(args[i + 1])
            del args[i:i + 2]
    if len(args) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    sys.argv = [sys.argv[0]] + args
    doc = json.load(open(sys.argv[1]))
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    t = {}
    mem = {}  # (op, arith, p, n) -> the memory counters of bench/memory_probe.hpp
    for b in doc["benchmarks"]:
        if b.get("error_occurred") or b.get("run_type", "iteration") != "iteration":
            continue
        op, arith, p, n = b["name"].split("/")[:4]
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
        t[(op, arith, int(p[1:]), int(n[1:]))] = b["cpu_time"] * scale
        counters = {k: b[k] for k in ("allocs", "allocs_per_item", "heap_peak_kib", "rss_peak_mib", "bytes_per_coef") if k in b}
        if counters:
            mem[(op, arith, int(p[1:]), int(n[1:]))] = counters
    # Runs before issue 49 named GMP "exact" and had no fraction-free kernel: read them so.
    if not any(k[1] == "gmp" for k in t):
        t = {(o, "gmp" if a == "exact" else a, p, n): v for (o, a, p, n), v in t.items()}
        mem = {(o, "gmp" if a == "exact" else a, p, n): v for (o, a, p, n), v in mem.items()}
    python = None
    if len(sys.argv) == 4:
        python = json.load(open(sys.argv[3]))
        for c in python["cases"]:
            t[(c["op"], "fraction", c["p"], c["n"])] = c["seconds"]
    present = {k[1] for k in t}
    ariths = [a for a in ("exact", "gmp", "flint", "mpfr128") if a in present]
    peers = [a for a in ("sisl", "occt") if a in present]
    ops = sorted({k[0] for k in t}, key=ORDER.index)
    # Columns: double against each peer, each exact/float arithmetic against double, the exact ones
    # against SISL (the fastest double peer).
    cols = [("double", pr) for pr in peers] + [(a, "double") for a in ariths]
    if "sisl" in peers:
        cols += [(a, "sisl") for a in ("exact", "gmp", "flint") if a in ariths]
    if "fraction" in present:
        cols += [(a, "fraction") for a in ("exact", "gmp", "flint") if a in ariths]
    names = {"exact": "exact", "gmp": "GMP", "flint": "flint", "mpfr128": "mpfr128", "double": "double", "sisl": "SISL", "occt": "OCCT",
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
          "OCCT modifies in place, so its insert/refine/elevate include a copy of the curve; `extract` is the Bezier "
          "form in one object (splinex `bezier_form`, SISL s1730; OCCT's converter makes one arc object per piece), "
          "`pieces` one BSpline per piece (splinex `extract_bezier`); elevation by one is splinex's default method (GMP "
          "and flint: A5.9; exact: the blossom at p >= 3, A5.9 below; double and MPFR: the blossom). `exact` is the fraction-free kernel (exact/ffnet.hpp: "
          "integers over one denominator per point and per knot vector), `GMP` and `flint` the naive exact kernels "
          "(one mpq / fmpq per coefficient).", "",
          "## Geometric mean over p and n", "",
          "| operation | " + " | ".join(head) + " |", "|---|" + "---|" * len(cols)]
    for op in ops:
        md.append(f"| {op} | " + " | ".join(f"{summary[f'{op} {a}/{b_}']:.3g}" if f"{op} {a}/{b_}" in summary else "-" for a, b_ in cols) + " |")
    md += ["", "## Every case", "", "| operation | p | n | double (us) | " + " | ".join(head) + " |",
           "|---|---|---|---|" + "---|" * len(cols)]
    for r in rows:
        md.append(f"| {r['op']} | {r['p']} | {r['n']} | {r['double_us']:.3g} | " +
                  " | ".join(f"{r[f'{a}/{b_}']:.3g}" if f"{a}/{b_}" in r else "-" for a, b_ in cols) + " |")
    # Memory: one more run of each case with the allocator counted (bench/memory_probe.hpp).
    mem_ariths = [a for a in ("double", "exact", "gmp", "flint", "mpfr128", "sisl", "occt")
                  if any(k[1] == a and "allocs" in v for k, v in mem.items())]
    mem_md = []
    if mem_ariths:
        md += ["", "## Memory of one operation", "",
               "Heap allocations of one operation (per evaluated point for eval) and the peak of its live heap above "
               "the level before it (KiB), counted by malloc/free interposed in the benchmark executable, so every "
               "library's allocations count (libstdc++, GMP, MPFR, FLINT, SISL, OpenCASCADE); the process's peak RSS "
               "during the operation (MiB; it includes the benchmark's cached inputs).", ""]
        mem_md.append("| operation | p | n | " + " | ".join(f"{names[a]} allocs" for a in mem_ariths) + " | " +
                      " | ".join(f"{names[a]} heap KiB" for a in mem_ariths) + " | peak RSS MiB |")
        mem_md.append("|---|---|---|" + "---|" * (2 * len(mem_ariths) + 1))
        for (op, p, n) in sorted({(k[0], k[2], k[3]) for k in mem}, key=lambda k: (ORDER.index(k[0]), k[1], k[2])):
            cells = [mem.get((op, a, p, n)) if "allocs" in mem.get((op, a, p, n), {}) else None for a in mem_ariths]
            fmt_alloc = lambda c: "-" if c is None else f"{c['allocs_per_item']:.3g}"
            fmt_heap = lambda c: "-" if c is None else f"{c['heap_peak_kib']:.3g}"
            rss = max((c.get("rss_peak_mib", 0) for c in cells if c), default=0)
            mem_md.append(f"| {op} | {p} | {n} | " + " | ".join(fmt_alloc(c) for c in cells) + " | " +
                          " | ".join(fmt_heap(c) for c in cells) + f" | {rss:.3g} |")
        md += mem_md
        for r in rows:
            for a in mem_ariths:
                c = mem.get((r["op"], a, r["p"], r["n"]))
                if c:
                    r[f"{a}_memory"] = c
    target_rows = targets(t, extra.get("--compose"), extra.get("--hybrid"), extra.get("--vrep"), mem)
    target_md = ["## Targets of issues 15 and 49 in this run", "",
                 "| target | measured | bound | verdict |", "|---|---|---|---|"] + \
                [f"| {w} | {v} | {b} | {m} |" for w, v, b, m in target_rows]
    md[8 + len(ops):8 + len(ops)] = [""] + target_md
    json.dump({"meta": meta, "geometric_means": summary, "targets": [dict(zip(("target", "measured", "bound", "verdict"), r))
                                                                     for r in target_rows], "rows": rows},
              open(out / "kernel.json", "w"), indent=1)
    (out / "kernel.md").write_text("\n".join(md) + "\n")
    higher = {flag[2:]: runs for flag, runs in extra.items()}
    cost = exactness(t, mem, higher, meta, md[2], target_rows)
    (out / "exactness.md").write_text("\n".join(cost) + "\n")
    # The generated block of docs/speed.md: the summary table and where it was measured.
    # (only for a run written into the repository's bench/results: a table made elsewhere, e.g. by a
    # test, leaves the page alone)
    root = Path(__file__).resolve().parent.parent
    speed = root / "docs" / "speed.md"
    if speed.exists() and out.resolve() == (root / "bench" / "results").resolve():
        text = speed.read_text()
        begin, end = "<!-- bench:kernel:begin -->", "<!-- bench:kernel:end -->"
        if begin in text and end in text:
            block = "\n".join([begin, md[2], ""] + md[4:8 + len(ops)] + [""] + target_md +
                               ["", "Every case: [bench/results/kernel.md](../bench/results/kernel.md).", end])
            text = text[:text.index(begin)] + block + text[text.index(end) + len(end):]
        begin, end = "<!-- bench:exactness:begin -->", "<!-- bench:exactness:end -->"
        if begin in text and end in text:  # the section without its title, headings one level down
            block = "\n".join([begin] + ["#" + l if l.startswith("#") else l for l in cost[2:]] + [end])
            text = text[:text.index(begin)] + block + text[text.index(end) + len(end):]
        speed.write_text(text)
    print("\n".join(md[:8 + len(ops)] + [""] + target_md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
