#!/usr/bin/env python3
"""Checks that every #include "folder/..." in a library folder names a folder it may depend on
(docs/ARCHITECTURE.md): the dependency direction of the targets, enforced on the sources. The
placement rules (JSON, points, verdicts, instantiation, report prose, SVG) are scripts/check_size.py's."""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DIRECT = {
    "base": [],
    "spline": ["base"],
    "exact": ["spline"],
    "float": ["exact"],
    "bernstein": ["spline"],  # the tensor Bernstein type and the subdivision engine
    "compose": ["float", "bernstein"],
    "solve": ["compose"],
    "untrim": ["compose"],
    "cut": ["compose"],
    "vrep": ["compose", "solve"],
    "hybrid": ["float"],
    "io": ["untrim", "hybrid", "vrep", "cut"],
    "vrep/io": ["io"],  # the V-rep facade over its documents: a sub-folder above io/
    "cut/io": ["io"],   # the cutting results as documents
    "fixtures": ["io"],
    "crosscheck": ["io"],
    "proofs": ["fixtures"],
    "experiments": ["proofs", "crosscheck", "vrep", "solve", "cut", "vrep/io"],
    "apps": ["experiments", "vrep/io", "cut/io"],
    "python": ["crosscheck", "fixtures"],
}


def layer_of(path):
    """The layer a path belongs to: its sub-folder when that is a layer (vrep/io), else its folder."""
    parts = path.split("/")
    if len(parts) > 2 and "/".join(parts[:2]) in DIRECT:
        return "/".join(parts[:2])
    return parts[0] if len(parts) > 1 else None


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
            if layer_of(str(f.relative_to(ROOT))) != folder:
                continue  # a sub-folder that is a layer of its own (vrep/io/)
            for n, line in enumerate(f.read_text().splitlines(), 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                target = layer_of(m.group(1)) if m else None
                if target in DIRECT and target not in allowed:
                    bad.append(f"{f.relative_to(ROOT)}:{n}: includes {target}/, but {folder}/ may depend only on "
                               + ", ".join(sorted(allowed - {folder})))
    for b in bad:
        print(b)
    if not bad:
        print(f"layering: {len(DIRECT)} folders, every include points down")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
