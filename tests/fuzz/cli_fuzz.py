#!/usr/bin/env python3
"""Mutation fuzzer for the splinex command line (issue 13).

Every case runs one command on a mutated document and/or mutated options, with a wall-clock
timeout and an address-space cap, and is classified:

  ok-json    exit 0 and stdout is valid JSON (plain text for `prove`)
  ok-error   exit 2 and stderr is exactly one line "splinex: error: <where>: <what> ... (fix: ...)"
  FAIL-*     anything else: exit 1 (internal error), another status, a signal (crash, abort),
             a timeout, an error of several lines or without the prefix, exit 0 with invalid JSON,
             a JSON `null` where a number belongs

Failures are written to OUT/failures/<n>/ (the document, the command line, stdout, stderr) so that
each can be replayed by hand. The exit status is 1 if any case failed.

  cli_fuzz.py --splinex build/bin/splinex --data tests/data --cases 2000 --seed 1 --out fuzz-out
"""
import argparse
import json
import os
import random
import resource
import signal
import shutil
import subprocess
import sys
import time

EXTREME_NUMBERS = ["0", "-0", "1", "-1", "1e100000", "-1e100000", "1e-100000", "1e-400", "1e400", "1/3", "-7/3",
                   "1/0", "0/0", "2^3", "0x10", "1e", ".", "-", "+1", " 1", "1 ", "nan", "inf", "-inf", "",
                   "9" * 400, "1" + "0" * 20, "123456789012345678901234567890/7", "1e-20", "0.1", "1.5e3",
                   "4.9e-324", "1.7976931348623157e308", "2.2250738585072014e-308", "1/" + "3" * 100]
EXTREME_INTS = [-2147483649, -1, 0, 1, 2, 3, 7, 100, 101, 1000, 2147483647, 2147483648, 10 ** 19, 10 ** 30]
OPTION_VALUES = ["-1", "0", "1", "2", "3", "100", "2147483647", "2147483648", "-2147483649", "1e308", "1e-15",
                 "nan", "inf", "", "abc", "0.5", "1/3", "1e100000", "0,1", "0.5,0.5,0.5,0.5,0.5", "x,y",
                 "\n", "1,", ",", "-0", "99999999999999999999"]
ARITHS = ["exact", "gmp", "flint", "double", "mpfr:24", "mpfr:53", "mpfr:113", "mpfr:2", "mpfr:65536", "mpfr:70000",
          "mpfr:abc", "quad", ""]


def load_documents(data):
    docs = {}
    for name in sorted(os.listdir(data)):
        if name.endswith(".json"):
            with open(os.path.join(data, name), "rb") as f:
                docs[name] = f.read()
    return docs


def json_paths(value, path=()):
    """Every (path, value) in a parsed document."""
    yield path, value
    if isinstance(value, dict):
        for k, v in value.items():
            yield from json_paths(v, path + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from json_paths(v, path + (i,))


def set_path(doc, path, value):
    if not path:
        return value
    cur = doc
    for p in path[:-1]:
        cur = cur[p]
    cur[path[-1]] = value
    return doc


def mutate_structured(rng, text):
    try:
        doc = json.loads(text)
    except Exception:
        return mutate_bytes(rng, text)
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        paths = list(json_paths(doc))
        path, value = rng.choice(paths)
        r = rng.random()
        if isinstance(value, list) and value and r < 0.25:
            op = rng.choice(["drop", "dup", "swap", "empty", "reverse", "grow"])
            if op == "drop":
                value.pop(rng.randrange(len(value)))
            elif op == "dup":
                i = rng.randrange(len(value))
                value.insert(i, json.loads(json.dumps(value[i])))
            elif op == "swap" and len(value) > 1:
                i, j = rng.randrange(len(value)), rng.randrange(len(value))
                value[i], value[j] = value[j], value[i]
            elif op == "empty":
                value.clear()
            elif op == "reverse":
                value.reverse()
            elif op == "grow":
                value.extend(json.loads(json.dumps(value)) * rng.choice([1, 3, 50]))
        elif isinstance(value, dict) and value and r < 0.3:
            k = rng.choice(list(value))
            op = rng.choice(["drop", "rename", "extra"])
            if op == "drop":
                del value[k]
            elif op == "rename":
                value[k + "x"] = value.pop(k)
            else:
                value["extra"] = 1
        elif path:
            repl = rng.choice([
                lambda: rng.choice(EXTREME_NUMBERS),
                lambda: rng.choice(EXTREME_INTS),
                lambda: rng.uniform(-1e3, 1e3),
                lambda: None, lambda: True, lambda: [], lambda: {}, lambda: [value],
                lambda: "\u00e9\n\"",
            ])()
            doc = set_path(doc, path, repl)
    out = json.dumps(doc)
    if rng.random() < 0.05:  # numbers as raw tokens instead of strings
        out = out.replace('"', "")
    return out.encode()


def mutate_bytes(rng, text):
    b = bytearray(text)
    for _ in range(rng.randint(1, 8)):
        if not b:
            b += b"{"
        i = rng.randrange(len(b))
        op = rng.randrange(5)
        if op == 0:
            b[i] = rng.randrange(256)
        elif op == 1:
            del b[i]
        elif op == 2:
            b.insert(i, rng.choice(b'[]{},:"0123456789-e./ \n\xff\x00'))
        elif op == 3:
            j = rng.randrange(len(b))
            b[i:i] = b[min(i, j):max(i, j)][:200]
        else:
            b = b[:i]
    return bytes(b)


KINDS = ["eval", "insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse", "compose",
         "crosscheck", "untrim", "hybrid", "prove", "vrep-info", "vrep-volume", "vrep-classify", "vrep-topology",
         "vrep-boolean", "vrep-certify", "vrep-export", "vrep-glue", "project", "contact", "cut-guide"]


NO_OPTION_MUTATION = {"cut-guide-3d"}
# The kernel's commands, whose "exact" (fraction-free) and "gmp" runs are compared byte for byte.
KERNEL_KINDS = {"eval", "insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse"}


def command_for(rng, docs, kinds=KINDS):
    """(argv after the program, document bytes or None, kind)"""
    curves = [n for n in docs if not n.startswith(("domain", "hybrid", "bad_loops", "bad_hybrid", "vmodel", "solid2d", "cut2d", "solid3d", "cut3d", "cutting_surface"))]
    models = [n for n in docs if n.startswith("vmodel")]
    surfaces = [n for n in docs if n.startswith(("sphere", "paraboloid", "saddle", "plane", "roof", "surface"))]
    doc_name = rng.choice(curves)
    doc = docs[doc_name]
    kind = rng.choice(kinds)
    arith = rng.choice(ARITHS) if rng.random() < 0.3 else rng.choice(["exact", "exact", "gmp", "double", "flint", "mpfr:113"])
    argv = []
    extra_files = {}
    if kind == "eval":
        argv = ["eval", "--arith", arith, "--at", rng.choice(["0.5", "0.3,0.5", "0", "1", "0.5,0.5,0.5", "1e-100000"])]
        if rng.random() < 0.3:
            argv += ["--derivative", rng.choice(["1", "1,0", "0,1", "3,3", "1000"])]
        if rng.random() < 0.2:
            argv += ["--method", "deboor"]
        argv += ["DOC"]
    elif kind == "insert-knots":
        argv = ["insert-knots", "--arith", arith, "--knots", rng.choice(["0.25,1/3", "0.5", "0.5,0.5,0.5", "0.1,0.9"]),
                "--dir", rng.choice(["0", "1"])]
        if rng.random() < 0.3:
            argv += ["--method", "boehm"]
        argv += ["DOC"]
    elif kind == "elevate":
        argv = ["elevate", "--arith", arith, "--by", rng.choice(["1", "2", "5"]), "--dir", rng.choice(["0", "1"]),
                "--method", rng.choice(["auto", "a59", "blossom"]), "DOC"]
    elif kind in ("extract-bezier", "reverse"):
        argv = [kind, "--arith", arith, "DOC"]
        if kind == "reverse":
            argv[-1:-1] = ["--dir", rng.choice(["0", "1"])]
    elif kind == "split":
        argv = ["split", "--arith", arith, "--at", rng.choice(["0.5", "0.25", "1/3"]), "--dir", rng.choice(["0", "1"]), "DOC"]
    elif kind == "reparametrize":
        argv = ["reparametrize", "--arith", arith, "--interval", rng.choice(["0,1", "-1,1", "0,1e-20", "2,1"]), "DOC"]
    elif kind == "compose":
        outer = rng.choice([n for n in docs if n.startswith("outer")] or curves)
        extra_files["OUTER"] = docs[outer]
        method = rng.choice(["symbolic", "interpolation", "trimmed", "tensor"])
        argv = ["compose", "--arith", arith, "--method", method, "--outer", "OUTER", "--inner", "DOC"]
        if method == "tensor" and rng.random() < 0.5:
            argv += ["--eps", rng.choice(["1e-3", "1e-6", "1e-12"])]
        if rng.random() < 0.2:
            argv += ["--expand"]
        doc = docs[rng.choice([n for n in docs if n.startswith("inner")] or curves)]
    elif kind == "crosscheck":
        op = rng.choice(["insert-knots", "elevate", "extract-bezier", "split", "reverse", "identity"])
        argv = ["crosscheck", op, "--arith", rng.choice(["double", "mpfr:64", "flint"]), "--grid", rng.choice(["0", "2", "5"])]
        if op == "insert-knots":
            argv += ["--knots", "0.3"]
        if op == "elevate":
            argv += ["--by", "1"]
        if op == "split":
            argv += ["--at", "0.5"]
        argv += ["DOC"]
    elif kind == "untrim":
        doc = docs[rng.choice([n for n in docs if n.startswith(("domain", "bad_loops"))])]
        argv = ["untrim", "--arith", rng.choice(["exact", "double", "mpfr:64"])]
        if rng.random() < 0.3:
            argv += ["--monomial", rng.choice(["1,1", "0,0", "3,2"])]
        argv += ["DOC"]
    elif kind.startswith("vrep-"):
        # V-model documents (planar, curved, trimmed cells; tests/data/vmodel_*.json), mutated.
        sub = kind[5:]
        trimmed = [n for n in models if n.startswith("vmodel_trimmed")] or models
        trivariates = [n for n in models if n.startswith("vmodel_trivariate")] or models
        doc = docs[rng.choice(trimmed if sub == "topology" else trivariates if sub == "certify" else models)]
        if sub == "info":
            argv = ["vrep", "info", "--levels", rng.choice(["0", "2", "6"]), "DOC"]
        elif sub == "volume":
            argv = ["vrep", "volume", "--boxes", rng.choice(["1", "16", "256"])] + (["--centroid"] if rng.random() < 0.4 else []) + ["DOC"]
        elif sub == "classify":
            argv = ["vrep", "classify", "--at", rng.choice(["1/2,1/2,1/2", "0,0,0", "1,1,1", "0.1,0.2,0.3", "1e-400,0,0",
                                                           "1e400,0,0", "1/3,1/3,1/3", "0.5,0.5"]), "DOC"]
        elif sub == "topology":
            argv = ["vrep", "topology", "--boxes", rng.choice(["8", "64", "512"])] + (["--glue"] if rng.random() < 0.3 else []) + ["DOC"]
        elif sub == "boolean":
            extra_files["SECOND"] = docs[rng.choice(models)]
            argv = ["vrep", "boolean", rng.choice(["union", "intersect", "subtract"]), "DOC", "SECOND",
                    "--trim", rng.choice(["auto", "always", "never"]), "--boxes", rng.choice(["8", "64", "512"])]
            if rng.random() < 0.3:
                argv += ["--eps", rng.choice(["1e-9", "1e-3", "0"])]
        elif sub == "certify":
            argv = ["vrep", "certify", "--arith", rng.choice(["exact", "double", "mpfr:64"]), "--levels",
                    rng.choice(["0", "3"]), "DOC"]
        elif sub == "export":
            argv = ["vrep", "export", "--vtk", "OUT.vtu", "DOC"]
        else:
            extra_files["SECOND"] = docs[rng.choice(models)]
            argv = ["vrep", "glue", "DOC", "SECOND"] + (["--eps", "1e-9"] if rng.random() < 0.3 else [])
    elif kind in ("project", "contact"):
        doc = docs[rng.choice(surfaces)]
        budget = ["--max-depth", rng.choice(["4", "12", "30"]), "--max-boxes", rng.choice(["16", "2000"])]
        if kind == "project":
            argv = ["project", "--arith", rng.choice(["exact", "double"]), "--point",
                    rng.choice(["0,0,2", "1/2,1/3,1", "0,0,0", "1e300,0,0", "1,2"]), "DOC"] + budget
        else:
            extra_files["SECOND"] = docs[rng.choice(surfaces)]
            argv = ["contact", "--arith", rng.choice(["exact", "double"]), "DOC", "SECOND"] + budget
    elif kind == "cut-guide" and rng.random() < 0.3:
        # d = 3: the smallest solid (tests/data/solid3d_tower.json) and its cutting data, one of them
        # mutated, with settings that keep the exact QP to seconds (options are not mutated: a
        # larger legal program runs for minutes, which is not a fault); sometimes a program over the
        # size limit, which must be refused before any work.
        kind = "cut-guide-3d"
        solid, cut = docs["solid3d_tower.json"], docs["cut3d_tower.json"]
        opts = ["--arith", rng.choice(["exact", "double"]), "--samples", rng.choice(["1", "2"]), "--loop-samples", rng.choice(["1", "2"]),
                "--inner-knots", "0", "--max-inner-knots", "0"]
        if rng.random() < 0.1:
            opts[opts.index("--inner-knots") + 1] = rng.choice(["5", "100"])
            opts[opts.index("--max-inner-knots") + 1] = "100"
        if rng.random() < 0.5:
            doc, extra_files["SECOND"] = solid, cut
            argv = ["cut", "guide"] + opts + ["DOC", "SECOND"]
        else:
            doc, extra_files["SECOND"] = cut, solid
            argv = ["cut", "guide"] + opts + ["SECOND", "DOC"]
        r = rng.random()
        if r < 0.3:  # the cutting surface: Step 1, Step 2, the certificates (sometimes guided)
            argv[1] = "facet"
            argv = [a for i, a in enumerate(argv) if a not in ("--arith",) and not (i > 0 and argv[i - 1] == "--arith")]
            argv[2:2] = ["--arith", rng.choice(["exact", "double", "both"]), "--patch-inner-knots", rng.choice(["0", "1", "3"]),
                         "--domain", rng.choice(["auto", "projection", "qp", "circle"])]
            if rng.random() < 0.3:
                argv[2:2] = ["--guided", "--weight-guide", rng.choice(["10", "1000", "auto"])]
        elif r < 0.45:  # a given cutting surface, mutated
            extra_files = {"SECOND": solid, "THIRD": cut}
            doc = docs["cutting_surface_tower.json"]
            argv = ["cut", "certify", "SECOND", "THIRD", "DOC"]
    elif kind in ("cut-guide", "cut-guide-3d"):
        # A solid and its cutting data (tests/data/solid2d_*, cut2d_*): one of them is DOC (mutated).
        name = rng.choice([n for n in docs if n.startswith("solid2d")])
        other = docs[name.replace("solid2d", "cut2d")]
        opts = ["--arith", rng.choice(["exact", "double", "both"]), "--samples", rng.choice(["1", "2", "4"]),
                "--inner-knots", rng.choice(["0", "1", "3"]), "--max-inner-knots", "3"]
        if rng.random() < 0.5:
            doc, extra_files["SECOND"] = docs[name], other
            argv = ["cut", "guide"] + opts + ["DOC", "SECOND"]
        else:
            doc, extra_files["SECOND"] = other, docs[name]
            argv = ["cut", "guide"] + opts + ["SECOND", "DOC"]
        if rng.random() < 0.3:  # the whole pipeline: guide, march, fit, validity
            argv[1] = "facet"
            argv = [a for i, a in enumerate(argv) if not (a == "--arith" or (i > 0 and argv[i - 1] == "--arith"))]
            argv[2:2] = ["--control-points", rng.choice(["4", "8", "30"])]
    elif kind == "hybrid":
        doc = docs[rng.choice([n for n in docs if n.startswith(("hybrid", "bad_hybrid"))])]
        argv = ["hybrid", "eval", "--arith", rng.choice(["exact", "double", "mpfr:64"]), "--at",
                rng.choice(["1/2,1/2", "0.3,0.4", "0,0", "1,1"]), "DOC"]
    elif kind == "prove":
        argv = ["prove", rng.choice(["knot-insertion-boehm", "elevation-agreement", "bezier-extraction"]), "--cases", "1"]
        doc = None
    return argv, doc, extra_files, kind


def mutate_options(rng, argv):
    argv = list(argv)
    idx = [i for i, a in enumerate(argv) if a.startswith("--") and i + 1 < len(argv) and not argv[i + 1].startswith("--")
           and argv[i + 1] not in ("DOC", "OUTER")]
    r = rng.random()
    if idx and r < 0.5:
        i = rng.choice(idx)
        argv[i + 1] = rng.choice(OPTION_VALUES)
    elif r < 0.6 and idx:
        i = rng.choice(idx)
        argv.insert(i, argv[i])  # a repeated option
        argv.insert(i + 1, argv[i + 2])
    elif r < 0.7:
        argv.insert(rng.randrange(len(argv) + 1), rng.choice(["--nope", "-x", "--", "--max-control-points", "0"]))
    elif r < 0.8:
        argv = [rng.choice(["--max-control-points", "--max-degree", "--max-memory"]), rng.choice(OPTION_VALUES)] + argv
    return argv


NULL_ALLOWED = {"twin"}  # documented nulls: a boundary half-V-surface has no twin


def has_null(value, key=None):
    """A JSON null anywhere but under a key whose null is documented."""
    if value is None:
        return key not in NULL_ALLOWED
    if isinstance(value, dict):
        return any(has_null(v, k) for k, v in value.items())
    if isinstance(value, list):
        return any(has_null(v, key) for v in value)
    return False


def classify(kind, rc, out, err, timed_out):
    if timed_out:
        return "FAIL-timeout"
    if rc in (-signal.SIGXCPU, -signal.SIGKILL):
        return "FAIL-cpu-budget"
    if rc < 0:
        return "FAIL-signal-%d" % -rc
    lines = err.decode(errors="replace").rstrip("\n").split("\n") if err else []
    if rc == 2:
        if len(lines) == 1 and lines[0].startswith("splinex: error: "):
            return "ok-error"
        return "FAIL-error-format"
    if rc == 0:
        if kind == "prove":
            return "ok-json"
        if kind == "vrep-export":  # writes the file and says so on stderr
            return "ok-json" if not out and len(lines) == 1 and lines[0].startswith("splinex vrep export: wrote ") else "FAIL-export-output"
        try:
            j = json.loads(out)
        except Exception:
            return "FAIL-invalid-json"
        if kind not in ("compose",) and has_null(j):
            return "FAIL-null"
        return "ok-json"
    if rc == 1 and kind == "prove":
        return "ok-json"  # a refuted proof exits 1 by design
    return "FAIL-exit-%d" % rc


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--splinex", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--cases", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=30.0)
    ap.add_argument("--memory", default="2G", help="--max-memory given to every case (a hard cap of twice that is set too)")
    ap.add_argument("--out", default="fuzz-out")
    ap.add_argument("--kinds", default="", help="comma-separated subset of: " + ", ".join(KINDS))
    a = ap.parse_args()
    kinds = a.kinds.split(",") if a.kinds else KINDS
    for k in kinds:
        if k not in KINDS:
            ap.error("unknown kind %r" % k)

    rng = random.Random(a.seed)
    docs = load_documents(a.data)
    work = os.path.join(a.out, "work")
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(work)
    units = {"M": 20, "G": 30}
    cap = int(a.memory[:-1]) << units[a.memory[-1]]

    # The per-case budget is CPU time (RLIMIT_CPU: SIGXCPU at --timeout seconds of CPU), so a case
    # does not fail because other jobs keep the cores busy; the wall-clock timeout is only a backstop
    # (ten times the budget) for a process that waits instead of computing.
    cpu = max(1, int(a.timeout))

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (2 * cap, 2 * cap))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))

    counts, failures, t0 = {}, 0, time.time()
    for case in range(a.cases):
        argv, doc, extra, kind = command_for(rng, docs, kinds)
        r = rng.random()
        if doc is not None and r < 0.45:
            doc = mutate_structured(rng, doc)
        elif doc is not None and r < 0.6:
            doc = mutate_bytes(rng, doc)
        if r >= 0.45 and rng.random() < 0.6 and kind not in NO_OPTION_MUTATION:
            argv = mutate_options(rng, argv)
        files = {}
        if doc is not None:
            files["DOC"] = doc
        files.update(extra)
        args = []
        for x in argv:
            if x == "OUT.vtu":
                args.append(os.path.join(work, "out.vtu"))
            elif x in files:
                path = os.path.join(work, x.lower() + ".json")
                with open(path, "wb") as f:
                    f.write(files[x])
                args.append(path)
            else:
                args.append(x)
        cmd = [a.splinex, "--max-memory", a.memory] + args
        timed_out = False
        start = time.time()
        try:
            p = subprocess.run(cmd, capture_output=True, timeout=10 * a.timeout, preexec_fn=limit)
            rc, out, err = p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired as e:
            rc, out, err, timed_out = -999, e.stdout or b"", e.stderr or b"", True
        verdict = classify(kind, rc, out, err, timed_out)
        # Differential: the kernel's commands in "exact" (fraction-free) and "gmp" (GMP mpq per
        # coefficient) must print the same bytes and exit the same way, errors included.
        if (not verdict.startswith("FAIL") and kind in KERNEL_KINDS and "--arith" in args
                and args.index("--arith") + 1 < len(args) and args[args.index("--arith") + 1] == "exact"):
            gcmd = list(cmd)
            gcmd[cmd.index("--arith", 3) + 1] = "gmp"
            try:
                g = subprocess.run(gcmd, capture_output=True, timeout=10 * a.timeout, preexec_fn=limit)
                # Resources are not values: the naive engine may run out of its CPU or memory
                # budget where the fraction-free one does not.
                exhausted = g.returncode not in (0, 2) or b"out of memory" in g.stderr + err
                if not exhausted and (g.returncode, g.stdout, g.stderr) != (rc, out, err):
                    verdict = "FAIL-exact-differs-from-gmp"
            except subprocess.TimeoutExpired:
                pass  # the gmp run is the naive engine: slower is expected, not a defect
        counts[verdict] = counts.get(verdict, 0) + 1
        if verdict.startswith("FAIL"):
            failures += 1
            d = os.path.join(a.out, "failures", "%05d" % case)
            os.makedirs(d)
            for name, content in files.items():
                with open(os.path.join(d, name.lower() + ".json"), "wb") as f:
                    f.write(content)
            with open(os.path.join(d, "command"), "w") as f:
                f.write(" ".join(repr(x) for x in cmd) + "\n" + verdict + " after %.1f s\n" % (time.time() - start))
            with open(os.path.join(d, "stdout"), "wb") as f:
                f.write(out[:100000])
            with open(os.path.join(d, "stderr"), "wb") as f:
                f.write(err[:100000])
            print("case %d: %s: %s" % (case, verdict, " ".join(argv)), file=sys.stderr)
        if (case + 1) % 100 == 0:
            print("%d/%d cases, %d failures, %.0f s" % (case + 1, a.cases, failures, time.time() - t0), file=sys.stderr)
    summary = {"cases": a.cases, "seed": a.seed, "timeout_s": a.timeout, "max_memory": a.memory,
               "seconds": round(time.time() - t0, 1), "outcomes": dict(sorted(counts.items())), "failures": failures}
    with open(os.path.join(a.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    print(json.dumps(summary, indent=2))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
