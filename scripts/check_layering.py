#!/usr/bin/env python3
"""Checks that every #include "folder/..." in a library folder names a folder it may depend on
(docs/ARCHITECTURE.md): the dependency direction of the targets, enforced on the sources."""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DIRECT = {
    "spline": [],
    "exact": ["spline"],
    "float": ["exact"],
    "compose": ["float"],
    "solve": ["compose"],
    "untrim": ["compose"],
    "cut": ["compose"],
    "vrep": ["compose", "solve"],
    "hybrid": ["float"],
    "io": ["untrim", "hybrid", "vrep", "cut"],
    "fixtures": ["io"],
    "crosscheck": ["io"],
    "proofs": ["fixtures"],
    "experiments": ["proofs", "crosscheck", "vrep", "solve", "cut"],
    "apps": ["experiments"],
    "python": ["crosscheck", "fixtures"],
}


def closure(folder):
    seen, todo = {folder}, [folder]
    while todo:
        for d in DIRECT[todo.pop()]:
            if d not in seen:
                seen.add(d)
                todo.append(d)
    return seen


def main():
    bad = []
    for folder in DIRECT:
        allowed = closure(folder)
        for f in sorted((ROOT / folder).rglob("*.[ch]pp")):
            for n, line in enumerate(f.read_text().splitlines(), 1):
                m = re.match(r'\s*#\s*include\s+"([^/"]+)/', line)
                if m and m.group(1) in DIRECT and m.group(1) not in allowed:
                    bad.append(f"{f.relative_to(ROOT)}:{n}: includes {m.group(1)}/, but {folder}/ may depend only on "
                               + ", ".join(sorted(allowed - {folder})))
    for b in bad:
        print(b)
    if not bad:
        print(f"layering: {len(DIRECT)} folders, every include points down")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
