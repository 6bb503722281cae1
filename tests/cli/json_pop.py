#!/usr/bin/env python3
"""json_pop.py KEY: a JSON document on stdin with the last element of its list KEY removed (a planted
defect for the verify tests: a composition with a tile or piece missing)."""
import json
import sys

doc = json.load(sys.stdin)
doc[sys.argv[1]].pop()
print(json.dumps(doc))
