#!/usr/bin/env python3
"""A summary of an unfinished untrimming tolerance sweep (issue 21).

`splinex sweep merge` refuses an incomplete sweep (it names the missing jobs). While a long sweep
runs, this script lists what has finished: one CSV row per finished job in the plan's order, the
exact numbers as doubles (the job files keep them as exact fractions), and the ids still missing.

    python3 scripts/sweep_partial.py JOBS.jsonl DIR > partial.csv   (missing ids on stderr)
"""
import json
import os
import sys
from fractions import Fraction


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: sweep_partial.py JOBS.jsonl DIR")
    jobs = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
    print("multiplicity,arith,eps,tiles,control_points,cpu_seconds,max_abs_deviation,gap_area,overlap_area,skipped")
    missing = []
    for job in jobs:
        path = os.path.join(sys.argv[2], job["output"])
        if not os.path.exists(path):
            missing.append(job["id"])
            continue
        doc = json.load(open(path))
        if doc.get("id") != job["id"] or doc.get("plan") != job["plan"]:
            sys.exit(f"{path}: not the result of job {job['id']} under this plan")
        r = doc["result"]
        exact = [float(Fraction(r[k])) for k in ("deviation", "gap", "overlap")]
        print(f"{r['m']},{r['arith']},{r['eps']!r},{r['tiles']},{r['control_points']},{r['cpu_seconds']!r},"
              f"{exact[0]!r},{exact[1]!r},{exact[2]!r},{json.dumps(r['why']) if r['skipped'] else ''}")
    print(f"{len(jobs) - len(missing)} of {len(jobs)} jobs finished; missing: {', '.join(missing) or 'none'}", file=sys.stderr)


if __name__ == "__main__":
    main()
