#!/usr/bin/env python3
"""check_report_files.py DIR...: the files a report run wrote are well formed (issue 48): every CSV
has as many fields in each row as in its header (a text with a comma must be quoted), and
report.md starts with its title and the "Run: " line and ends with what ran."""
import csv
import sys
from pathlib import Path

bad = []
for d in map(Path, sys.argv[1:]):
    for f in sorted(d.glob("*.csv")):
        rows = list(csv.reader(f.open(newline="")))
        for i, r in enumerate(rows[1:], 2):
            if len(r) != len(rows[0]):
                bad.append(f"{f}:{i}: {len(r)} fields, the header has {len(rows[0])}")
    md = (d / "report.md").read_text().splitlines()
    if md[:1] != ["# splinex report"] or not any(l.startswith("Run: splinex ") for l in md[:4]):
        bad.append(f"{d}/report.md: does not start with '# splinex report' and a 'Run: splinex ...' line")
    if not md or not md[-1].startswith("This report ran "):
        bad.append(f"{d}/report.md: does not end with 'This report ran ...'")
for b in bad:
    print(b)
print(f"report files: {len(sys.argv) - 1} folder(s), " + ("well formed" if not bad else f"{len(bad)} problem(s)"))
sys.exit(1 if bad else 0)
