#!/usr/bin/env python3
"""json_check.py EXPR...: reads one JSON document on stdin and requires every Python expression
EXPR (with the document bound to `j`) to be true; prints "ok" or names the first failing one.
Used by the command-line tests to assert fields of a command's JSON output, e.g.
  splinex verify ... | python3 json_check.py 'j["function"]["certified"]' '"null" not in raw'"""
import json
import sys

raw = sys.stdin.read()
try:
    j = json.loads(raw)
except ValueError as e:
    print("not JSON (%s): %s" % (e, raw[:2000]))
    sys.exit(1)
for expr in sys.argv[1:]:
    try:
        ok = eval(expr, {"j": j, "raw": raw})
    except Exception as e:  # a missing key is a failed check, named
        ok = False
        expr += "  (%s: %s)" % (type(e).__name__, e)
    if not ok:
        print("failed: %s\n%s" % (expr, raw[:4000]))
        sys.exit(1)
print("ok")
