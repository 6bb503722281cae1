#!/usr/bin/env python3
"""scripts/bench_table.py on planted timings (tests/data/bench: CPU times whose ratios are known by
construction), then `splinex report --sections exactness --bench` on its output:

    test_bench_table.py SPLINEX WORKDIR

Checks the ratios of the "what exactness costs" tables, the geometric means, the bytes per value,
the higher level's ratios and targets, that an errored benchmark is left out, that the report
includes the section with its headings one level down, and that a table written outside the
repository's bench/results leaves docs/speed.md alone."""
import hashlib
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "bench"


def expect(text, line, where):
    if line not in text.splitlines():
        sys.exit(f"{where}: missing line\n  {line}\n--- got:\n{text}")


def main():
    splinex, work = sys.argv[1], Path(sys.argv[2])
    out, report = work / "bench", work / "report"
    speed = ROOT / "docs" / "speed.md"
    before = hashlib.sha256(speed.read_bytes()).hexdigest()
    subprocess.run([sys.executable, str(ROOT / "scripts" / "bench_table.py"), str(DATA / "kernel.json"), str(out),
                    str(DATA / "python.json"), "--compose", str(DATA / "compose.json")], check=True, capture_output=True)
    if hashlib.sha256(speed.read_bytes()).hexdigest() != before:
        sys.exit("bench_table.py rewrote docs/speed.md for a table written outside bench/results")
    md = (out / "exactness.md").read_text()
    # insert at p = 3, n = 1000: double 1 us; exact 2.5, GMP 300, FLINT 17, SISL 0.85 and Python 64 us.
    expect(md, "| insert | 1 | 2.5 | 300 | 17 | 0.85 | 64 |", "exactness.md")
    expect(md, "| eval | 2 | 3 | 50 | - | - | 700 |", "exactness.md")
    # geometric mean of exact/double over (p3 n1000, p3 n10000, p7 n1000) = (2.5 * 2 * 4)^(1/3) = 2.71
    expect(md, "| insert | 2.71 (worst 4) | 316 (worst 333) | 17 (worst 17) | 0.85 (worst 0.85) | 64 (worst 64) |", "exactness.md")
    expect(md, "| insert | 3 | 8 | 12.5 | 48 |", "exactness.md")
    expect(md, "| stars/body | 4 | 30 | 150 |", "exactness.md")
    expect(md, "| untrim_star/body | 40 | 16 | - |", "exactness.md")
    expect(md, "| insert: worst Python Fraction / exact over p, n >= 1000 (how many times faster) | 25.6 | >= 20 | met |", "exactness.md")
    expect(md, "| insert: best exact arithmetic / double at p = 3, n = 1000 | 2.5 | <= 2 | 1.25x the bound |", "exactness.md")
    if "errored" in md or "errored" in (out / "kernel.md").read_text():
        sys.exit("an errored benchmark reached the tables")
    subprocess.run([splinex, "report", "--sections", "exactness", "--bench", str(out), "--out", str(report)], check=True,
                   capture_output=True)
    rep = (report / "report.md").read_text()
    expect(rep, "## What exactness costs", "report.md")
    expect(rep, "### Degree 3, n = 1000: time / double", "report.md")
    expect(rep, "| insert | 1 | 2.5 | 300 | 17 | 0.85 | 64 |", "report.md")
    if "\n# What exactness costs" in rep:
        sys.exit("report.md kept the table file's own title")
    # Without --bench the section says how to make it.
    subprocess.run([splinex, "report", "--sections", "exactness", "--out", str(work / "plain")], check=True, capture_output=True)
    plain = (work / "plain" / "report.md").read_text()
    if "Not included in this run. `scripts/run.sh bench`" not in plain:
        sys.exit("without --bench the section does not say how to include it:\n" + plain)
    print("bench_table and the exactness section: ok")


if __name__ == "__main__":
    main()
