#!/usr/bin/env python3
"""The house's size budget and placement rules (issue 48), checked on every C++ source.

    scripts/check_size.py            check (exit 1 on any breach)
    scripts/check_size.py --report   print every file and function over the budget, with sizes

Budget: no file over 800 lines, no function over 150 lines. What was over the budget when the rule
came in is listed in scripts/size_allowlist.txt with its size then; that list may only shrink:
  - a file or function not on the list must fit the budget;
  - one on the list may not grow past its recorded size;
  - one on the list that now fits (or is gone) must be struck from the list, so the ratchet holds.
Placement: no JSON (nlohmann) in apps/ or in the algorithm folders, outside the files that are
listed in the same file as allowed to (the same ratchet: the list may only shrink). No point type
and no point algebra outside base/point.hpp (tests aside): no alias of std::array<T, 2 or 3> (use
Point2<T>, Point3<T>), no cross product written out (use cross, dot, triple). Verdicts only
through base/verdict.hpp (Verdict, Uncertain<E>): no enum with an `undecided` member outside base/, and
no verdict spelled as text ("undecided" in an algorithm folder's code); those there when the rule
came in are listed (`verdict PATH::ENUM`, `verdict-text PATH`) and the list may only shrink.
Instantiation (one rule, docs/ARCHITECTURE.md): a header never instantiates a template explicitly,
and an `_impl.hpp` (template definitions) is included only by its own folder's .cpp files, other
`_impl.hpp` files of the folder and its `instantiate.hpp`, where its templates are instantiated for
the arithmetics the folder names; other folders compile against declarations. The includes across
folders there when the rule came in are listed (`impl FILE INCLUDED`); the list may only shrink.
Prose (issue 48 item 9): report.md's words live in experiments/report/*.md templates
(experiments/report_template.hpp), not in C++ string literals: no literal in experiments/ (adjacent
literals joined, raw strings skipped) that holds Markdown prose (a `##` heading, a table rule `|---`,
a link or image `](`, a paragraph break followed by text) or a sentence of 25 words or more outside
an SVG element; files that still hold some are listed (`prose PATH COUNT`), and the list may only shrink.
SVG (issue 48 item 9): written only by experiments/svg.cpp (svg::Canvas: a viewBox, titles and
captions wrapped to their width); no other C++ source opens an svg element, in code or in a string
(no allowance).

Functions are found by a brace scanner, not a compiler: comments, strings and character literals
are blanked, and a `{` at namespace or class scope that follows `)` (with qualifiers, an arrow
return type or a constructor's initialiser list between) opens a function body; its length is the
number of lines from the line of its name to the closing brace. Lambdas and local classes count
towards the function that holds them.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ALLOW = ROOT / "scripts" / "size_allowlist.txt"
FILE_BUDGET = 800
FUNCTION_BUDGET = 150
FOLDERS = ["base", "spline", "bernstein", "exact", "float", "compose", "solve", "untrim", "cut", "vrep", "hybrid", "io",
           "fixtures", "crosscheck", "proofs", "experiments", "apps", "python", "bench", "fuzz", "tests",
           "examples"]
# Folders whose code is algorithm, not documents: no JSON there (a package's io/ sub-folder, such as
# vrep/io/, is where its documents live).
NO_JSON = ["base", "spline", "bernstein", "exact", "float", "compose", "solve", "untrim", "cut", "vrep", "hybrid", "apps"]


def sources():
    for folder in FOLDERS:
        base = ROOT / folder
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in (".cpp", ".hpp", ".h", ".cc"))


def blank(text):
    """Comments, strings and character literals replaced by spaces; newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == '_')):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append(re.sub(r"[^\n]", " ", text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")  # digit separator 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(re.sub(r"[^\n]", " ", text[i:j + 1]))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else|try)\s*$")
SCOPE = re.compile(r"\b(namespace|class|struct|union|enum)\b[^;(){}]*$")


def skip_braces(text, i):
    """The index after the brace group that opens at text[i] == '{'."""
    depth = 0
    while i < len(text):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return i


INIT_LIST = re.compile(r"\)\s*(noexcept\b)?\s*:(?!:)")


def functions(path):
    """(name, first line, last line) of each function body at namespace or class scope."""
    text = blank(path.read_text(errors="replace"))
    stack = []  # kinds of the open braces: 'scope', 'function', 'other'
    found = []
    last = 0  # end of the previous statement at this level
    i = 0
    while i < len(text):
        c = text[i]
        if c in ";}":
            if c == "}" and stack:
                kind, start, name = stack.pop()
                if kind == "function" and not any(k == "function" for k, _, _ in stack):
                    found.append((name, start, text.count("\n", 0, i) + 1))
            last = i + 1
        elif c == "{":
            head = text[last:i]
            inside_function = any(k == "function" for k, _, _ in stack)
            before = head.rstrip()[-1:] if head.strip() else ""
            if not inside_function and head.count("(") > head.count(")"):
                i = skip_braces(text, i)  # a braced default argument inside a parameter list: f(const L& l = {})
                continue
            if not inside_function and INIT_LIST.search(head) and (before.isalnum() or before in "_>"):
                i = skip_braces(text, i)  # a constructor's braced member initialiser: X() : a_{a} {
                continue
            if inside_function:
                stack.append(("other", 0, ""))
            elif SCOPE.search(head) or re.search(r"\bextern\s*$", head.strip() + " ") or head.strip().endswith("="):
                stack.append(("scope" if SCOPE.search(head) else "other", 0, ""))
            else:
                name = function_name(head)
                if name and not CONTROL.search(head.split(")")[0]):
                    start_offset = last + head.find(name) if name in head else last
                    stack.append(("function", text.count("\n", 0, start_offset) + 1, name))
                else:
                    stack.append(("other", 0, ""))
            last = i + 1
        i += 1
    return found


def function_name(head):
    """The name of the function whose body the brace after `head` opens, or None."""
    h = " ".join(head.split())
    h = re.sub(r"^\s*(public|private|protected)\s*:", "", h)
    while re.search(r"\{[^{}]*\}", h):  # braced initialisers in the head (defaults, member inits)
        h = re.sub(r"\{[^{}]*\}", "", h)
    h = re.sub(r"\bnoexcept\s*\([^()]*(\([^()]*\)[^()]*)*\)", "noexcept", h)  # noexcept(expr)
    h = re.sub(r"\brequires\b.*$", "", h) if re.search(r"\)\s*(const\s*)?requires\b", h) else h  # a trailing requires-clause
    if ")" not in h:
        return None
    # strip a constructor's initialiser list: ") : a(x), b{y}" -> ")"
    m = re.search(r"\)\s*(const|noexcept|override|final|mutable|&|&&|\s)*(->[^{]*)?(\s*:\s*[^{]*)?$", h)
    if not m:
        return None
    paren = h.rfind(")", 0, m.start() + 1)
    depth, j = 0, paren
    while j >= 0:
        if h[j] == ")":
            depth += 1
        elif h[j] == "(":
            depth -= 1
            if depth == 0:
                break
        j -= 1
    if j < 0:
        return None
    before = h[:j].rstrip()
    op = re.search(r"([A-Za-z_][A-Za-z0-9_:]*::)?operator\s*\(\s*\)$", before)
    if op:
        return op.group(0).replace(" ", "")
    nm = re.search(r"([A-Za-z_~][A-Za-z0-9_:~<>,\s]*?(operator\s*[^\s(]+)?)$", before)
    if not nm:
        return None
    name = nm.group(1).strip().split()[-1] if nm.group(1).strip() else None
    if not name or name in ("if", "for", "while", "switch", "catch", "return", "sizeof", "decltype",
                            "alignof", "static_assert", "defined"):
        return None
    if re.search(r"\b(if|for|while|switch|catch)\s*$", before):
        return None
    return name


POINT_ALIAS = re.compile(r"\busing\s+\w+\s*=\s*std::array<[^<>,]+,\s*[23]\s*>")
CROSS_WRITTEN = re.compile(r"(\w+)\[1\]\s*\*\s*(\w+)\[2\]\s*-\s*\1\[2\]\s*\*\s*\2\[1\]")


def point_breaches(rel, code):
    """Lines of `code` (comments and strings blanked) that define a point type or write out a cross
    product, outside base/ and tests/."""
    if rel.startswith(("base/", "tests/")):
        return []
    out = []
    for n, line in enumerate(code.splitlines(), 1):
        if POINT_ALIAS.search(line):
            out.append(f"{rel}:{n}: a local point type: use Point2<T> or Point3<T> (base/point.hpp)")
        if CROSS_WRITTEN.search(line):
            out.append(f"{rel}:{n}: a cross product written out: use cross (base/point.hpp)")
    return out


THREE_VALUED = re.compile(r"\benum(?:\s+class)?\s+(\w+)\s*(?::\s*\w+\s*)?\{[^}]*\bundecided\b")
ALGORITHM = ["spline", "bernstein", "exact", "float", "compose", "solve", "untrim", "cut", "vrep", "hybrid"]


def verdict_breaches(rel, text, code):
    """Three-valued enums (by name) and whether the file spells a verdict as text."""
    if rel.startswith(("base/", "tests/")):
        return set(), False
    enums = {f"{rel}::{m.group(1)}" for m in THREE_VALUED.finditer(code)}
    uncommented = re.sub(r"/\*.*?\*/", "", re.sub(r"//[^\n]*", "", text), flags=re.S)
    as_text = rel.split("/")[0] in ALGORITHM and "/io/" not in rel and '"undecided"' in uncommented
    return enums, as_text


def impl_breaches(rel, text, code):
    """(file, included _impl.hpp) pairs breaking the instantiation rule, and explicit instantiations in a header."""
    if rel.startswith(("tests/", "bench/", "fuzz/", "examples/")):
        return set(), []
    pairs = set()
    own = rel.split("/")[0]
    may_include = rel.endswith((".cpp", "_impl.hpp", "instantiate.hpp"))
    for m in re.finditer(r'#\s*include\s*"([\w/]+_impl\.hpp)"', text):
        if not may_include or m.group(1).split("/")[0] != own:
            pairs.add((rel, m.group(1)))
    in_header = []
    if rel.endswith(".hpp") and not rel.endswith("instantiate.hpp"):
        for n, line in enumerate(code.splitlines(), 1):
            if re.match(r"template\s+(?!<)[^;{]*;\s*$", line):
                in_header.append(f"{rel}:{n}: an explicit instantiation in a header: instantiate in a .cpp (docs/ARCHITECTURE.md)")
    return pairs, in_header


def string_literals(text):
    """The C++ string literals of `text` as (line, value), adjacent ones joined as the compiler joins
    them; comments, character literals and raw strings (data: embedded documents) skipped."""
    out, i, n, line, open_at = [], 0, len(text), 1, None
    while i < n:
        c = text[i]
        if c == "\n":
            line, i = line + 1, i + 1
            continue
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            line, i = line + text.count("\n", i, j), j
            continue
        if c == "R" and text.startswith('"', i + 1) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i + 2)
            end = text.find(")" + text[i + 2:k] + '"', k)
            j = n if k < 0 or end < 0 else end + k - i
            line, i, open_at = line + text.count("\n", i, j), j, None
            continue
        if c == "'" and not (i and text[i - 1].isalnum()):  # (a digit separator is not a literal)
            j = i + 1
            while j < n and text[j] not in "'\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            continue
        if c == '"':
            j, value = i + 1, []
            while j < n and text[j] != '"':
                if text[j] == "\\" and j + 1 < n:
                    value.append({"n": "\n", "t": "\t"}.get(text[j + 1], text[j + 1]))
                    j += 2
                else:
                    value.append(text[j])
                    j += 1
            if open_at is not None and text[open_at:i].strip() == "":
                out[-1] = (out[-1][0], out[-1][1] + "".join(value))
            else:
                out.append((line, "".join(value)))
            line, i = line + text.count("\n", i, j), j + 1
            open_at = i
            continue
        if not c.isspace():
            open_at = None
        i += 1
    return out


MARKDOWN = re.compile(r"(^|\n)#{2,4} \w|\|---|\]\(|\n\n[*\w(`!-]")


SVG_WRITER = "experiments/svg.cpp"
SVG_OPEN = re.compile(r"<svg\b")


def svg_breaches(rel, text):
    """Lines of a C++ source other than the one SVG writer that open an svg element."""
    if rel == SVG_WRITER:
        return []
    return [f"{rel}:{n}: writes SVG by hand: draw on svg::Canvas (experiments/svg.hpp), the one SVG writer"
            for n, line in enumerate(text.splitlines(), 1) if SVG_OPEN.search(line)]


def prose_count(rel, text):
    """How many string literals of an experiments/ source hold report prose (the docstring's rule)."""
    if not rel.startswith("experiments/"):
        return 0
    return sum(1 for _, v in string_literals(text)
               if MARKDOWN.search(v) or (len(v.split()) >= 25 and not v.lstrip().startswith("<")))


def measure():
    files, funcs, json_files = {}, {}, set()
    global PROSE
    PROSE = {}
    points = []
    global SVG
    SVG = []
    verdicts, verdict_texts = set(), set()
    global IMPL, IMPL_IN_HEADER
    IMPL, IMPL_IN_HEADER = set(), []
    for p in sources():
        rel = str(p.relative_to(ROOT))
        text = p.read_text(errors="replace")
        files[rel] = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        for name, a, b in functions(p):
            key = f"{rel}::{name}"
            size = b - a + 1
            if size > funcs.get(key, 0):
                funcs[key] = size
        code = blank(text)
        prose = prose_count(rel, text)
        if prose:
            PROSE[rel] = prose
        points += point_breaches(rel, code)
        SVG += svg_breaches(rel, text)
        enums, as_text = verdict_breaches(rel, text, code)
        verdicts |= enums
        if as_text:
            verdict_texts.add(rel)
        pairs, in_header = impl_breaches(rel, text, code)
        IMPL |= pairs
        IMPL_IN_HEADER += in_header
        if rel.split("/")[0] in NO_JSON and "/io/" not in rel and (re.search(r"(?i)json", code) or
                                             re.search(r'#\s*include\s*[<"](nlohmann/|io/(json_io|result_json))', text)):
            json_files.add(rel)
    return files, funcs, json_files, points, verdicts, verdict_texts


def read_allow():
    allow = {"file": {}, "function": {}, "json": set(), "verdict": set(), "verdict-text": set(), "impl": set(), "prose": {}}
    if not ALLOW.exists():
        return allow
    for n, line in enumerate(ALLOW.read_text().splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = line.split()
        if parts[0] in ("json", "verdict", "verdict-text") and len(parts) == 2:
            allow[parts[0]].add(parts[1])
        elif parts[0] == "impl" and len(parts) == 3:
            allow["impl"].add((parts[1], parts[2]))
        elif parts[0] in ("file", "function", "prose") and len(parts) == 3:
            allow[parts[0]][parts[1]] = int(parts[2])
        else:
            sys.exit(f"{ALLOW.relative_to(ROOT)}:{n}: expected 'file PATH LINES', 'function PATH::NAME LINES', 'json PATH', "
                     "'verdict PATH::ENUM', 'verdict-text PATH', 'impl FILE INCLUDED' or 'prose PATH COUNT'")
    return allow


def self_test():
    """The scanner on a planted text: a long function, a class's method, a lambda, a control block."""
    import tempfile
    body = "\n".join(f"  x += {i};" for i in range(160))
    text = ("namespace a {\nstruct S {\n  int m() const { return 1; }\n};\n"
            "// void commented_out() {\n"
            "int long_one(int x)\n{\n  auto f = [&](int y) { return y; };\n  if (x) {\n" + body + "\n  }\n"
            "  const char* s = \"{ not a brace\";\n  return f(x);\n}\n"
            "Point::Point(int a) : a_(a), b_{a} {}\n"
            "int with_default(const L& l = {}, int k = L{}.k)\n{\n" + body + "\n}\n"
            "Long::Long(int a)\n    : a_{a}, b_{a} {\n" + body + "\n}\n"
            "struct Call {\n  int operator()(int x) const noexcept(true) {\n" + body + "\n  }\n};\n"
            "}  // namespace a\n")
    with tempfile.NamedTemporaryFile("w", suffix=".cpp", delete=False) as f:
        f.write(text)
    got = {name: b - a + 1 for name, a, b in functions(Path(f.name))}
    Path(f.name).unlink()
    want = {"m": 1, "long_one": 168, "Point::Point": 1, "with_default": 163, "Long::Long": 163, "operator()": 162}
    if got != want:
        print(f"self-test failed: found {got}, expected {want}")
        return 1
    planted = ("using P3 = std::array<Rational, 3>;\n"
               "  n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};\n"
               "  // n = {u[1] * v[2] - u[2] * v[1]} in a comment\n"
               "using Row = std::array<Rational, 4>;\n")
    enums, as_text = verdict_breaches("cut/x.cpp", 'enum class Fate { yes, no, undecided };\nr = "undecided";\n',
                                      blank('enum class Fate { yes, no, undecided };\nr = "undecided";\n'))
    if enums != {"cut/x.cpp::Fate"} or not as_text:
        print(f"self-test failed: verdict placement found {enums}, {as_text}")
        return 1
    planted_impl = '#include "compose/compose_impl.hpp"\n#include "vrep/model/vmodel_impl.hpp"\ntemplate int f<int>(int);\n'
    pairs, in_header = impl_breaches("vrep/x.hpp", planted_impl, blank(planted_impl))
    ok_pairs, _ = impl_breaches("vrep/y.cpp", planted_impl, blank(planted_impl))
    if pairs != {("vrep/x.hpp", "compose/compose_impl.hpp"), ("vrep/x.hpp", "vrep/model/vmodel_impl.hpp")} or len(in_header) != 1 or \
            ok_pairs != {("vrep/y.cpp", "compose/compose_impl.hpp")}:
        print(f"self-test failed: instantiation rule found {pairs}, {in_header}, {ok_pairs}")
        return 1
    planted_prose = ('// "## not a literal"\nmd << "\\n## Heading\\n\\n" "Text";\nconst char* d = R"(## data)";\n'
                     'o << "<text>" "a b c d e f g h i j k l m n o p q r s t u v w x y</text>";\n'
                     'w << "a b c d e f g h i j k l m n o p q r s t u v w x y z";\nchar q = \'"\';\n')
    lits = string_literals(planted_prose)
    if prose_count("experiments/x.cpp", planted_prose) != 2 or [l for l, _ in lits] != [2, 4, 5] or lits[0][1] != "\n## Heading\n\nText" \
            or prose_count("vrep/x.cpp", planted_prose):
        print(f"self-test failed: the prose rule found {lits}")
        return 1
    planted_svg = 'o << "<svg xmlns=\\"http://www.w3.org/2000/svg\\" width=\\"" << W << "\\">";\no << "</svg>\\n";\n'
    got_svg = [b.split(":")[1] for b in svg_breaches("experiments/x.cpp", planted_svg)]
    if got_svg != ["1"] or svg_breaches(SVG_WRITER, planted_svg):
        print(f"self-test failed: the SVG rule found lines {got_svg} of a planted hand-written svg element")
        return 1
    found = point_breaches("vrep/x.cpp", blank(planted))
    if [b.split(":")[1] for b in found] != ["1", "2"] or point_breaches("base/point.hpp", planted):
        print(f"self-test failed: point placement found {found}, expected lines 1 and 2 only")
        return 1
    print("self-test: the scanner measures planted long functions (plain, braced default arguments, braced member "
          "initialisers, operator()) and skips comments, strings, lambdas and blocks; the placement rule finds a "
          "planted point alias, a written-out cross product, a three-valued enum, a verdict as text, template definitions "
          "included across folders and from a header, an explicit instantiation in a header, report prose in joined "
          "string literals (not in comments, raw strings or SVG text) and a hand-written svg element")
    return 0


def main():
    if "--self-test" in sys.argv:
        return self_test()
    files, funcs, json_files, points, verdicts, verdict_texts = measure()
    if "--report" in sys.argv:
        for f, n in sorted(files.items()):
            if n > FILE_BUDGET:
                print(f"file {f} {n}")
        for f, n in sorted(funcs.items()):
            if n > FUNCTION_BUDGET:
                print(f"function {f} {n}")
        for f in sorted(json_files):
            print(f"json {f}")
        for e in sorted(verdicts):
            print(f"verdict {e}")
        for f in sorted(verdict_texts):
            print(f"verdict-text {f}")
        for f, i in sorted(IMPL):
            print(f"impl {f} {i}")
        for f, k in sorted(PROSE.items()):
            print(f"prose {f} {k}")
        return 0
    allow = read_allow()
    bad = []
    for kind, sizes, budget in (("file", files, FILE_BUDGET), ("function", funcs, FUNCTION_BUDGET)):
        for key, n in sorted(sizes.items()):
            if n <= budget:
                continue
            if key not in allow[kind]:
                bad.append(f"{key}: {n} lines, over the budget of {budget}: split it (or, only when the rule came in, list it)")
            elif n > allow[kind][key]:
                bad.append(f"{key}: {n} lines, grew past its allowance of {allow[kind][key]}: the list may only shrink")
        for key, was in sorted(allow[kind].items()):
            if sizes.get(key, 0) <= budget:
                bad.append(f"{ALLOW.name}: {kind} {key} now fits the budget ({sizes.get(key, 0)} lines, was {was}): strike it from the list")
            elif sizes[key] < was:
                bad.append(f"{ALLOW.name}: {kind} {key} shrank to {sizes[key]} lines: lower its allowance from {was}")
    for f in sorted(json_files - allow["json"]):
        bad.append(f"{f}: builds or reads JSON, but {f.split('/')[0]}/ may not (documents belong in io/)")
    for f in sorted(allow["json"] - json_files):
        bad.append(f"{ALLOW.name}: json {f} no longer uses JSON: strike it from the list")
    bad += points
    for e in sorted(verdicts - allow["verdict"]):
        bad.append(f"{e}: an enum with an undecided member: use Verdict or Uncertain<E> (base/verdict.hpp)")
    for e in sorted(allow["verdict"] - verdicts):
        bad.append(f"{ALLOW.name}: verdict {e} is gone: strike it from the list")
    for f in sorted(verdict_texts - allow["verdict-text"]):
        bad.append(f"{f}: spells a verdict as text (\"undecided\"): use Verdict (base/verdict.hpp); text belongs in io/")
    for f in sorted(allow["verdict-text"] - verdict_texts):
        bad.append(f"{ALLOW.name}: verdict-text {f} no longer spells verdicts as text: strike it from the list")
    for f, i in sorted(IMPL - allow["impl"]):
        bad.append(f"{f}: includes {i}, another folder's template definitions (or from a header): instantiate them in "
                   f"{i.split('/')[0]}/ and use the declarations (docs/ARCHITECTURE.md)")
    for f, i in sorted(allow["impl"] - IMPL):
        bad.append(f"{ALLOW.name}: impl {f} {i} is gone: strike it from the list")
    bad += IMPL_IN_HEADER
    bad += SVG
    for f, k in sorted(PROSE.items()):
        if f not in allow["prose"]:
            bad.append(f"{f}: {k} string literal(s) of report prose: move the words into a template, experiments/report/*.md "
                       "(experiments/report_template.hpp)")
        elif k > allow["prose"][f]:
            bad.append(f"{f}: {k} string literals of report prose, more than its allowance of {allow['prose'][f]}: the list may only shrink")
    for f, was in sorted(allow["prose"].items()):
        if PROSE.get(f, 0) < was:
            bad.append(f"{ALLOW.name}: prose {f} holds {PROSE.get(f, 0)} literal(s) of prose now: lower its allowance from {was} "
                       "(strike it at 0)")
    for b in bad:
        print(b)
    if not bad:
        nf = sum(1 for n in files.values() if n > FILE_BUDGET)
        nfn = sum(1 for n in funcs.values() if n > FUNCTION_BUDGET)
        print(f"size: {len(files)} files, {len(funcs)} functions; over the budget and allowed: "
              f"{nf} files, {nfn} functions, {len(allow['json'])} files with JSON outside io/, "
              f"{len(allow['verdict'])} three-valued enums, {len(allow['verdict-text'])} files with verdicts as text outside base/, "
              f"{len(allow['impl'])} template definitions included across folders and {sum(allow['prose'].values())} literals of "
              "report prose outside the templates; SVG only from " + SVG_WRITER)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
