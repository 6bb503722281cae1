#!/usr/bin/env python3
"""check_report_files.py DIR...: the files a report run wrote are well formed (issue 48): every CSV
has as many fields in each row as in its header (a text with a comma must be quoted), and
report.md starts with its title and the "Run: " line and ends with what ran, its headings and
tables follow a blank line, and no template placeholder is left."""
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
    # The parts (experiments/report/*.md templates) join with blank lines: a heading or a table
    # right after a paragraph's line means a template lost its final blank line.
    for i in range(1, len(md)):
        if md[i].startswith("#") and md[i - 1].strip():
            bad.append(f"{d}/report.md:{i + 1}: a heading without a blank line before it")
        if md[i].startswith("|") and md[i - 1].strip() and not md[i - 1].startswith("|"):
            bad.append(f"{d}/report.md:{i + 1}: a table right after a line of text (no blank line)")
    if "{{" in "\n".join(md):
        bad.append(f"{d}/report.md: an unfilled '{{{{' placeholder")
for b in bad:
    print(b)
print(f"report files: {len(sys.argv) - 1} folder(s), " + ("well formed" if not bad else f"{len(bad)} problem(s)"))
sys.exit(1 if bad else 0)
