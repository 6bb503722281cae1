#!/usr/bin/env python3
"""Checks the front page and the links of the docs (issue 48): the README has at most 1,000
words and its status table one short line per capability (at most 200 characters a row), and
every relative link in README.md and docs/**/*.md (every Markdown file under docs/, sub-folders
such as docs/vrep/ included) names a file of the checkout."""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MAX_WORDS = 1000
MAX_ROW = 200
LINK = re.compile(r"\]\(([^)\s]+)\)")


def main():
    bad = []
    readme = ROOT / "README.md"
    text = readme.read_text(encoding="utf-8")
    words = len(text.split())
    if words > MAX_WORDS:
        bad.append(f"README.md: {words} words, above {MAX_WORDS}: move the detail to a docs page")
    in_status = False
    for n, line in enumerate(text.splitlines(), 1):
        if line.startswith("## "):
            in_status = line.strip() == "## Status"
        if in_status and line.startswith("|") and len(line) > MAX_ROW:
            bad.append(f"README.md:{n}: a status row of {len(line)} characters, above {MAX_ROW}: one short line, the detail on its page")
    pages = [readme] + sorted((ROOT / "docs").rglob("*.md"))
    for page in pages:
        body = page.read_text(encoding="utf-8")
        body = re.sub(r"```.*?```", "", body, flags=re.S)  # links in code blocks are not links
        for n, line in enumerate(body.splitlines(), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue
                path = target.split("#", 1)[0]
                if not (page.parent / path).exists():
                    bad.append(f"{page.relative_to(ROOT)}: the link {target} names no file")
    for b in bad:
        print(b)
    if bad:
        return 1
    print(f"README.md: {words} words; links of {len(pages)} pages resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main())
