#!/usr/bin/env python3
"""Snapshot everything splinex prints, so that a change meant to keep behaviour can be checked.

    scripts/behaviour_snapshot.py BUILD_DIR OUT_DIR [--no-report]
    scripts/behaviour_snapshot.py --diff A B
    scripts/behaviour_snapshot.py --remask BUILD_DIR OUT_DIR
    scripts/behaviour_snapshot.py --diff-reports A B

A snapshot holds, one file per item, the exit status, standard output and standard error of
  - every command-line test registered with CTest (except the `long` label and the report),
    run as the command after `--` of tests/cli/cli_expect.sh, so the whole output is kept, not just
    the match the test asks for;
  - the help text of every subcommand, `prove --list` and all proofs (`prove --json`);
  - `splinex report` (every file it writes).
Wall-clock times are the only thing allowed to differ: CSV columns whose header names seconds are
blanked, and in text "<number> s", "seconds": <number>, the report's Time section and its "Run: "
line (version, date, command) are masked.
The SVGs that plot times (untrim_tolerance_cost.svg) keep their axes but not their polylines'
coordinates. Absolute paths of the source and build trees become $SRC and $BUILD.

--diff compares two snapshots and lists every file that differs (exit 1) or prints "identical".
--remask BUILD_DIR OUT_DIR applies the masks again to the raw outputs a snapshot keeps in raw/.
--diff-reports A B compares two report folders (e.g. `splinex report` and the merge of
`splinex sweep plan report`) file by file with the same masks, and prints the differing lines.
"""
import csv
import difflib
import io
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parent.parent
TIMEOUT = 3600


def normalise_text(text: str, build: Path) -> str:
    text = text.replace(str(build.resolve()), "$BUILD").replace(str(build), "$BUILD")
    text = text.replace(str(SRC), "$SRC")
    return text


NUMBER = r"\b\d+(\.\d+)?(e[-+]?\d+)?\b"


def mask_times(text: str) -> str:
    # "0.025 s", "1.15 s;", "(3.2e-05 s)"; JSON "seconds...": number; progress "[report 1.2s]"; "ratio 24.3"
    text = re.sub(r"\b\d+(\.\d+)?(e[-+]?\d+)? s\b", "<t> s", text)
    text = re.sub(r"\[report [0-9.]+s\]", "[report <t>s]", text)
    text = re.sub(r"\bratio " + NUMBER, "ratio <t>", text)
    text = re.sub(r'("[a-z_]*seconds[a-z_]*"\s*:\s*)[-+0-9.eE]+', r"\1<t>", text)
    text = re.sub(r"\b\d+(\.\d+)?(e[-+]?\d+)? ms\b", "<t> ms", text)
    return text


def mask_csv(text: str) -> str:
    if not text:
        return text
    rows = list(csv.reader(io.StringIO(text)))
    header = rows[0]
    timed = [i for i, h in enumerate(header)
             if "seconds" in h or h.endswith("_time") or h == "time" or h.endswith("_s") or h.startswith("ms_")]
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(header)
    for row in rows[1:]:
        writer.writerow(["<t>" if i in timed and i < len(row) and row[i] else v for i, v in enumerate(row)])
    return out.getvalue()


def timed_column(header: str) -> bool:
    h = header.strip()
    return (h.endswith(" s") or h in ("s", "ms") or "(s)" in h or " s " in h or h == "exact / double" or h == "time" or "seconds" in h or "/float" in h or "/double" in h
            or "ratio" in h)


def mask_report_md(text: str) -> str:
    # The section "## Time ..." lists wall-clock times only: its numbers are masked. In every
    # Markdown table, the cells of columns whose header names a time ("exact s", "time", ratios
    # of times) are masked.
    out, in_time, in_table, timed = [], False, False, set()
    for line in text.splitlines(keepends=True):
        if line.startswith("Run: "):  # version, date and command of the run
            out.append("Run: <masked>\n")
            continue
        if line.startswith("## "):
            in_time = line.startswith("## Time")
        if line.startswith("|"):
            cells = line.rstrip("\n").split("|")
            if not in_table:  # the header row
                timed = {i for i, c in enumerate(cells) if timed_column(c)}
                in_table = True
            elif timed and not re.match(r"^\|[-| :]+\|$", line.strip()):
                line = "|".join("<t>" if i in timed and c.strip() else c for i, c in enumerate(cells)) + "\n"
        else:
            in_table, timed = False, set()
        if in_time and not line.startswith("## "):
            line = re.sub(NUMBER, "<n>", line)
        out.append(line)
    return mask_times("".join(out))


def mask_svg_with_times(text: str) -> str:
    return re.sub(r'(points|d|x|y|cx|cy|x1|x2|y1|y2)="[^"]*"', r'\1="<t>"', text)


TIMED_SVGS = {"untrim_tolerance_cost.svg"}


def run(cmd, cwd, out: Path, name: str, build: Path, env=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, timeout=TIMEOUT, env=env)
        rc, so, se = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        rc, so, se = "timeout", b"", b""
    text = (f"exit: {rc}\n--- stdout\n" + normalise_text(so.decode("utf-8", "replace"), build)
            + "--- stderr\n" + normalise_text(se.decode("utf-8", "replace"), build))
    text = text.replace(str(out), "$SNAP")
    (out / "raw" / "cli").mkdir(parents=True, exist_ok=True)
    (out / "raw" / "cli" / (name + ".txt")).write_text(text)
    (out / "cli" / (name + ".txt")).write_text(mask_times(text))


def ctest_commands(build: Path):
    js = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"], check=True,
                        capture_output=True, text=True).stdout
    for t in json.loads(js)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        labels = props.get("LABELS", [])
        cmd = t.get("command", [])
        if not cmd or "long" in labels or Path(cmd[0]).name == "splinex_tests":
            continue
        if t["name"] in ("cli.report", "cli.report_manifest", "cli.install_find_package", "layering") or \
                t["name"].startswith("cli.report_part"):
            continue
        if Path(cmd[0]).name == "cli_expect.sh" and "--" in cmd:
            cmd = cmd[cmd.index("--") + 1:]
        yield t["name"], cmd, props.get("WORKING_DIRECTORY", str(build))


def snapshot(build: Path, out: Path, with_report: bool):
    if out.exists():
        shutil.rmtree(out)
    (out / "cli").mkdir(parents=True)
    cli = str(build / "bin" / "splinex")
    items = list(ctest_commands(build))
    helps = [[], ["eval"], ["insert-knots"], ["elevate"], ["extract-bezier"], ["split"], ["reparametrize"],
             ["reverse"], ["compose"], ["crosscheck"], ["prove"], ["report"], ["untrim"], ["hybrid"],
             ["hybrid", "eval"], ["hybrid", "example"], ["hybrid", "experiment"]]
    for h in helps:
        items.append(("help." + (".".join(h) or "main"), [cli, *h, "--help"], str(build)))
    items.append(("prove.list", [cli, "prove", "--list"], str(build)))
    items.append(("prove.all_json", [cli, "prove", "--json"], str(build)))
    items.append(("prove.all_text", [cli, "prove", "--cases", "3"], str(build)))
    for i, (name, cmd, cwd) in enumerate(items):
        print(f"[{i + 1}/{len(items)}] {name}", file=sys.stderr, flush=True)
        run(cmd, cwd, out, name, build)
    if with_report:
        print("report (a few minutes)", file=sys.stderr, flush=True)
        rep = out / "raw" / "report"
        run([cli, "report", "--out", str(rep)], str(build), out, "report.command", build)
        remask_report(out, build)


def remask_report(out: Path, build: Path):
    rep = out / "raw" / "report"
    if (out / "report").exists():
        shutil.rmtree(out / "report")
    (out / "report").mkdir()
    for f in sorted(rep.iterdir()):
        text = normalise_text(f.read_text(errors="replace"), build).replace(str(rep), "$OUT")
        if f.suffix == ".csv":
            text = mask_csv(text)
        elif f.name == "report.md":
            text = mask_report_md(text)
        elif f.name in TIMED_SVGS:
            text = mask_svg_with_times(text)
        else:
            text = mask_times(text)
        (out / "report" / f.name).write_text(text)
    raw_cli = out / "raw" / "cli"
    for f in sorted(raw_cli.iterdir()):
        (out / "cli" / f.name).write_text(mask_times(f.read_text()))


def diff(a: Path, b: Path) -> int:
    fa = {p.relative_to(a) for p in a.rglob("*") if p.is_file() and p.relative_to(a).parts[0] != "raw"}
    fb = {p.relative_to(b) for p in b.rglob("*") if p.is_file() and p.relative_to(b).parts[0] != "raw"}
    bad = sorted(str(p) + " (only in " + str(a) + ")" for p in fa - fb)
    bad += sorted(str(p) + " (only in " + str(b) + ")" for p in fb - fa)
    bad += sorted(str(p) for p in fa & fb if (a / p).read_bytes() != (b / p).read_bytes())
    for line in bad:
        print("differs:", line)
    if not bad:
        print(f"identical: {len(fa)} files")
    return 1 if bad else 0


def masked_report_file(f: Path, folder: Path) -> str:
    text = f.read_text(errors="replace").replace(str(folder.resolve()), "$OUT").replace(str(folder), "$OUT")
    if f.suffix == ".csv":
        return mask_csv(text)
    if f.name == "report.md":
        return mask_report_md(text)
    if f.name in TIMED_SVGS:
        return mask_svg_with_times(text)
    return mask_times(text)


def diff_reports(a: Path, b: Path) -> int:
    fa = {f.name for f in a.iterdir() if f.is_file()}
    fb = {f.name for f in b.iterdir() if f.is_file()}
    bad = [f"{n} (only in {a})" for n in sorted(fa - fb)] + [f"{n} (only in {b})" for n in sorted(fb - fa)]
    for n in sorted(fa & fb):
        ta, tb = masked_report_file(a / n, a), masked_report_file(b / n, b)
        if ta != tb:
            bad.append(n)
            lines = [l for l in difflib.unified_diff(ta.splitlines(), tb.splitlines(), lineterm="") if l[:1] in "+-"]
            for l in lines[:6]:
                print("  " + l[:200])
    for line in bad:
        print("differs:", line)
    if not bad:
        print(f"identical, times aside: {len(fa)} files")
    return 1 if bad else 0


def main():
    args = sys.argv[1:]
    if len(args) == 3 and args[0] == "--diff-reports":
        sys.exit(diff_reports(Path(args[1]), Path(args[2])))
    if len(args) == 3 and args[0] == "--diff":
        sys.exit(diff(Path(args[1]), Path(args[2])))
    if len(args) == 3 and args[0] == "--remask":  # re-apply the masks to a snapshot's raw outputs
        remask_report(Path(args[2]).resolve(), Path(args[1]).resolve())
        return
    if len(args) in (2, 3) and args[0] != "--diff":
        snapshot(Path(args[0]).resolve(), Path(args[1]).resolve(), "--no-report" not in args)
        return
    print(__doc__, file=sys.stderr)
    sys.exit(2)


if __name__ == "__main__":
    main()
