#!/usr/bin/env python3
"""Generated blocks of the docs equal what the program that knows them prints (issue 48).

    scripts/check_generated.py SPLINEX            check (exit 1 on any difference, with a diff)
    scripts/check_generated.py SPLINEX --write    rewrite the blocks

A block sits between `<!-- NAME:begin -->` and `<!-- NAME:end -->`; each is written by one command:
  report:sections   docs/papers.md   `splinex report --list-sections` (the sections' table in
                                     experiments/report.cpp: what each reproduces, its time)
(docs/speed.md's bench:kernel and bench:exactness blocks are written by scripts/bench_table.py from a benchmark run.)
"""
import difflib
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BLOCKS = [("report:sections", "docs/papers.md", ["report", "--list-sections"])]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli, write = sys.argv[1], "--write" in sys.argv
    bad = 0
    for name, page, args in BLOCKS:
        path = ROOT / page
        text = path.read_text()
        want = subprocess.run([cli] + args, check=True, capture_output=True, text=True).stdout
        pat = re.compile(r"(<!-- " + re.escape(name) + r":begin -->\n)(.*?)(<!-- " + re.escape(name) + r":end -->)", re.S)
        m = pat.search(text)
        if not m:
            print(f"{page}: no block <!-- {name}:begin --> ... <!-- {name}:end -->")
            bad += 1
            continue
        if m.group(2) == want:
            continue
        if write:
            path.write_text(text[:m.start(2)] + want + text[m.end(2):])
            print(f"{page}: block {name} rewritten")
            continue
        print(f"{page}: block {name} differs from `splinex {' '.join(args)}` (scripts/check_generated.py SPLINEX --write):")
        sys.stdout.writelines(difflib.unified_diff(m.group(2).splitlines(True), want.splitlines(True), "committed", "generated"))
        bad += 1
    if not bad:
        print(f"generated docs: {len(BLOCKS)} block(s) equal to their programs' output")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
