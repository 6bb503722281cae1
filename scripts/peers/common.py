"""What the peer judges share: the input as a double program gets it, the domain, the figure."""
import math
from fractions import Fraction


def rounded(S):
    """The spline with every number rounded to double, as exact Fractions of those doubles."""
    out = dict(S)
    out["knots"] = [[Fraction(float(u)) for u in U] for U in S["knots"]]
    out["points"] = [[Fraction(float(x)) for x in p] for p in S["points"]]
    if "weights" in S:
        out["weights"] = [Fraction(float(w)) for w in S["weights"]]
    return out


def homogeneous_input(S):
    """For a peer that takes homogeneous coefficients (w x, w y, ..., w) as doubles: those doubles
    (w x rounded) and the exact input they are (points h / w), which the peer is judged against."""
    if "weights" not in S:
        return S, None
    W = [Fraction(w) for w in S["weights"]]
    H = [[float(Fraction(x) * w) for x in p] + [float(w)] for p, w in zip(S["points"], W)]
    exact = dict(S)
    exact["points"] = [[Fraction(h) / w for h in row[:-1]] for row, w in zip(H, W)]
    return exact, H


def domain(S):
    p, U = S["degrees"][0], S["knots"][0]
    n = len(S["points"])
    return U[p], U[n]


def svg(series, title, xlabel="degree", points=False):
    """A small plot of bits lost against x (one series per operation): lines through the worst per
    degree, or with points=True a scatter (x: log2 of the smallest knot spacing)."""
    W, H, L, B = 560, 320, 50, 40
    xs = [x for pts in series.values() for x, _ in pts] or [0, 1]
    x0, x1 = min(xs), max(max(xs), min(xs) + 1)
    y1 = max([y for pts in series.values() for _, y in pts] + [53])
    sx = lambda x: L + (x - x0) / (x1 - x0) * (W - L - 20)
    sy = lambda y: H - B - y / y1 * (H - B - 30)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           f'<text x="{W/2}" y="16" text-anchor="middle" font-size="13">{title}</text>',
           f'<line x1="{L}" y1="{H-B}" x2="{W-20}" y2="{H-B}" stroke="black"/><line x1="{L}" y1="{H-B}" x2="{L}" y2="30" stroke="black"/>',
           f'<text x="{W/2}" y="{H-8}" text-anchor="middle">{xlabel}</text>',
           f'<text x="12" y="{H/2}" transform="rotate(-90 12 {H/2})" text-anchor="middle">bits lost (of 53)</text>']
    step = max(1, int((x1 - x0) // 12))
    for d in range(int(math.floor(x0)), int(math.ceil(x1)) + 1, step):
        out.append(f'<text x="{sx(d)}" y="{H-B+14}" text-anchor="middle">{d}</text>')
    for y in range(0, int(y1) + 1, 10):
        out.append(f'<text x="{L-6}" y="{sy(y)+4}" text-anchor="end">{y}</text>')
    colors = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
    for i, (name, pts) in enumerate(sorted(series.items())):
        col = colors[i % 4]
        if points:
            out += [f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="2.5" fill="{col}" fill-opacity="0.6"/>' for x, y in pts]
        else:
            path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in sorted(pts))
            out.append(f'<polyline fill="none" stroke="{col}" stroke-width="2" points="{path}"/>')
        out.append(f'<text x="{W-150}" y="{40+14*i}" fill="{col}">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def min_gap_log2(S):
    """log2 of the smallest positive spacing of distinct knots (0 for a single span on [0, 1])."""
    U = sorted(set(S["knots"][0]))
    gaps = [b - a for a, b in zip(U, U[1:]) if b > a]
    return math.log2(min(gaps)) if gaps else 0.0


def judged_row(seed, suite, op, S, tags):
    return {"seed": seed, "suite": suite, "op": op, "degree": S["degrees"][0], "tags": tags,
            "min_gap_log2": round(min_gap_log2(S), 3)}


def verify_result(S, op, u, xs, result):
    """splinex.verify of a peer's result for op on S: result is a spline dict (insert: knot u;
    elevate: by one; derivative: the first derivative as a spline) or, for eval, the values at xs."""
    import splinex
    if op == "eval":
        return splinex.verify("eval", S, {"at": [[x] for x in xs], "values": result})
    if op == "insert":
        return splinex.verify("insert-knots", S, result, knots=[u])
    if op == "derivative":
        return splinex.verify("derivative", S, result, order=1)
    return splinex.verify("elevate", S, result, by=1)


def verify_into(row, rep):
    row.update({"structure": rep.structure, "bits_lost": rep.bits_lost, "certified": rep.certified,
                "function_upper": float(rep.function_upper)})
    notes = rep.report.get("structure_notes", [])
    if rep.structure == "different" and notes:
        row["structure_note"] = "; ".join(notes)[:160]


def write_results(out, name, title, intro, rows, ops, cases, label):
    """The peer's table (per suite and operation: judged, bits lost median and max, cases above 10
    bits, structure differences, failures), the worst cases and failures, and two figures: worst
    bits lost by degree (ordinary curves) and every judged case's bits lost against the smallest
    knot spacing. Returns the markdown lines."""
    import statistics
    md = [f"# {title}", "", intro, "",
          "| cases | operation | judged | bits lost, median | bits lost, max | cases above 10 bits | structure differs | failures |",
          "|---|---|---|---|---|---|---|---|"]
    by_degree, by_gap = {}, {}
    suites = []
    for r in rows:
        if r["op"] != "input" and r["suite"] not in suites:
            suites.append(r["suite"])
    for suite in sorted(suites, key=lambda x: SUITES.index(x)):
        for op in ops:
            ok = [r for r in rows if r["suite"] == suite and r["op"] == op and "bits_lost" in r]
            fails = [r for r in rows if r["suite"] == suite and r["op"] == op and "failure" in r]
            bits = [r["bits_lost"] for r in ok]
            md.append(f"| {suite} | {op} | {len(ok)} | {statistics.median(bits) if bits else 0:.3g} | "
                      f"{max(bits) if bits else 0:.3g} | {sum(b > 10 for b in bits)} | "
                      f"{sum(r['structure'] == 'different' for r in ok)} | {len(fails)} |")
            if suite == "ordinary":
                worst = {}
                for r in ok:
                    worst[r["degree"]] = max(worst.get(r["degree"], 0), r["bits_lost"])
                by_degree[op] = sorted(worst.items())
            by_gap.setdefault(op, []).extend((r["min_gap_log2"], r["bits_lost"]) for r in ok)
    md += ["", "Worst judged cases (first 15), then failures (first 15):", ""]
    judged = sorted([r for r in rows if "bits_lost" in r and r["bits_lost"] > 10], key=lambda r: -r["bits_lost"])
    failed = [r for r in rows if r["op"] != "input" and "failure" in r]
    for r in judged[:15] + failed[:15]:
        what = r.get("failure") or (f"{r['bits_lost']:.1f} bits lost, structure {r['structure']}"
                                    + (f" ({r['structure_note']})" if "structure_note" in r else ""))
        md.append(f"- {r['suite']} case {r['seed']}, {r['op']}, degree {r['degree']}, structures {', '.join(r['tags']) or '-'}: {what}")
    if not judged and not failed:
        md.append("- none")
    not_double = sum(r["op"] == "input" for r in rows)
    md += ["", f"{not_double} inputs were not handed over (not representable in double: knots closer than double "
               "tells apart; or more coordinates than the peer's curves have).", "",
           f"![bits lost vs degree]({name}_bits_vs_degree.svg) ![bits lost vs knot spacing]({name}_bits_vs_spacing.svg)", ""]
    (out / f"{name}.md").write_text("\n".join(md))
    (out / f"{name}_bits_vs_degree.svg").write_text(svg(by_degree, f"{label}, ordinary curves: worst bits lost by degree"))
    (out / f"{name}_bits_vs_spacing.svg").write_text(
        svg(by_gap, f"{label}: bits lost against the smallest knot spacing", "log2 of the smallest knot spacing", points=True))
    return md


def ordinary_curve(rng, p):
    """A clamped curve in R^2 of degree p with simple interior knots at distinct dyadic positions
    k/1024 and coordinates k/1024: ordinary input, exact in double."""
    m = rng.randint(0, 50)
    interior = sorted(rng.sample(range(1, 1024), m))
    U = [Fraction(0)] * (p + 1) + [Fraction(k, 1024) for k in interior] + [Fraction(1)] * (p + 1)
    n = len(U) - p - 1
    P = [[Fraction(rng.randint(-1024, 1024), 1024) for _ in range(2)] for _ in range(n)]
    return {"degrees": [p], "knots": [U], "points": P}


SUITES = ["ordinary", "structured", "rational", "adversarial"]


def adversarial_curves():
    """The report's adversarial inputs as curves: knots 1/10 and 1/10 + 2^-50, degree 15, 1000 knots
    clustered within 10^-6, knots 2^-30 apart at degree 7, 200 knots at degree 1."""
    def clamped(p, interior, n_pts_seed):
        U = [Fraction(0)] * (p + 1) + sorted(interior) + [Fraction(1)] * (p + 1)
        n = len(U) - p - 1
        P = [[Fraction((i * 37 + n_pts_seed) % 101 - 50, 64), Fraction((i * i * 13 + 7) % 97 - 48, 32)] for i in range(n)]
        return {"degrees": [p], "knots": [U], "points": P}
    tenth = Fraction(1, 10)
    return [
        (clamped(3, [tenth, tenth + Fraction(1, 2**50), Fraction(1, 2)], 1), ["knots 1/10 and 1/10 + 2^-50"]),
        (clamped(15, [Fraction(k, 21) for k in range(1, 21)], 2), ["degree 15"]),
        (clamped(3, [Fraction(1, 2) + Fraction(k, 10**9) for k in range(1000)], 3), ["1000 knots within 1e-6"]),
        (clamped(7, [Fraction(1, 3) + Fraction(k, 2**30) for k in range(8)] + [Fraction(2, 3)], 4), ["knots 2^-30 apart"]),
        (clamped(1, [Fraction(k, 201) for k in range(1, 201)], 5), ["degree 1, 200 knots"]),
    ]


def cases(count, seed):
    """(suite, spline, structures) for the judges: the structured generator's curves (polynomial),
    as many ordinary curves of degree 1..7, as many rational structured curves, then the
    adversarial curves (the later suites are appended so that the earlier cases' draws stay)."""
    import random
    import splinex
    out = []
    for s in range(count):
        S, tags = splinex.structured_case(s, max_dim=1, rational=False)
        out.append(("structured", S, tags))
    rng = random.Random(seed)
    for s in range(count):
        p = 1 + s % 7
        out.append(("ordinary", ordinary_curve(rng, p), ["degree %d, simple dyadic knots" % p]))
    found = 0
    for s in range(20 * count):  # the generator gives weights to some of its cases
        if found == count:
            break
        S, tags = splinex.structured_case(100000 + s, max_dim=1, rational=True)
        if "weights" in S:
            out.append(("rational", S, tags))
            found += 1
    for S, tags in adversarial_curves():
        out.append(("adversarial", S, tags))
    return out


def double_inputs(count, seed):
    """The judges' inputs: each case rounded to double, with one knot u to insert and 9 evaluation
    points. Returns (inputs, rows): inputs as (index, suite, S, tags, u, xs); rows hold the cases
    that are not representable in double (knots closer than double can tell apart)."""
    import random
    import splinex
    rng = random.Random(seed)
    inputs, rows = [], []
    for index, (suite, S0, tags) in enumerate(cases(count, 1202)):
        try:
            S = splinex.validate(rounded(S0))
        except ValueError as e:
            rows.append({"seed": index, "suite": suite, "op": "input", "tags": tags,
                         "failure": "not representable in double: " + str(e)[:80]})
            continue
        lo, hi = domain(S)
        u = float(lo + (hi - lo) * Fraction(rng.randint(1, 999), 1000))
        xs = [float(lo + (hi - lo) * Fraction(i, 8)) for i in range(9)]
        inputs.append((index, suite, S, tags, u, xs))
    return inputs, rows
