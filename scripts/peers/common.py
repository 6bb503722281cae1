"""What the peer judges share: the input as a double program gets it, the domain, the figure."""
from fractions import Fraction


def rounded(S):
    """The spline with every number rounded to double, as exact Fractions of those doubles."""
    out = dict(S)
    out["knots"] = [[Fraction(float(u)) for u in U] for U in S["knots"]]
    out["points"] = [[Fraction(float(x)) for x in p] for p in S["points"]]
    return out


def domain(S):
    p, U = S["degrees"][0], S["knots"][0]
    n = len(S["points"])
    return U[p], U[n]


def svg(series, title):
    """A small line plot of bits lost against degree (one series per operation)."""
    W, H, L, B = 560, 320, 50, 40
    xs = [x for pts in series.values() for x, _ in pts] or [0, 1]
    x0, x1 = min(xs), max(max(xs), min(xs) + 1)
    y1 = max([y for pts in series.values() for _, y in pts] + [53])
    sx = lambda x: L + (x - x0) / (x1 - x0) * (W - L - 20)
    sy = lambda y: H - B - y / y1 * (H - B - 30)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           f'<text x="{W/2}" y="16" text-anchor="middle" font-size="13">{title}</text>',
           f'<line x1="{L}" y1="{H-B}" x2="{W-20}" y2="{H-B}" stroke="black"/><line x1="{L}" y1="{H-B}" x2="{L}" y2="30" stroke="black"/>',
           f'<text x="{W/2}" y="{H-8}" text-anchor="middle">degree</text>',
           f'<text x="12" y="{H/2}" transform="rotate(-90 12 {H/2})" text-anchor="middle">bits lost (worst, of 53)</text>']
    for d in range(int(x0), int(x1) + 1):
        out.append(f'<text x="{sx(d)}" y="{H-B+14}" text-anchor="middle">{d}</text>')
    for y in range(0, int(y1) + 1, 10):
        out.append(f'<text x="{L-6}" y="{sy(y)+4}" text-anchor="end">{y}</text>')
    colors = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
    for i, (name, pts) in enumerate(sorted(series.items())):
        pts = sorted(pts)
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in pts)
        out.append(f'<polyline fill="none" stroke="{colors[i % 4]}" stroke-width="2" points="{path}"/>')
        out.append(f'<text x="{W-150}" y="{40+14*i}" fill="{colors[i % 4]}">{name}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def ordinary_curve(rng, p):
    """A clamped curve in R^2 of degree p with simple interior knots at distinct dyadic positions
    k/1024 and coordinates k/1024: ordinary input, exact in double."""
    m = rng.randint(0, 50)
    interior = sorted(rng.sample(range(1, 1024), m))
    U = [Fraction(0)] * (p + 1) + [Fraction(k, 1024) for k in interior] + [Fraction(1)] * (p + 1)
    n = len(U) - p - 1
    P = [[Fraction(rng.randint(-1024, 1024), 1024) for _ in range(2)] for _ in range(n)]
    return {"degrees": [p], "knots": [U], "points": P}


def cases(count, seed):
    """(suite, spline, structures) for the judges: the structured generator's curves (polynomial),
    then as many ordinary curves of degree 1..7."""
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
