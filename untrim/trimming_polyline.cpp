#include "untrim/trimming_polyline.hpp"

#include <algorithm>
#include <cmath>

#include "spline/evaluate.hpp"

namespace splinex {

namespace {

struct Level {
  const BSpline<double>& S;
  int coord;
  double level;
  double operator()(const Point2<double>& p) const { return evaluate(S, {p[0], p[1]})[coord] - level; }
};

// Bisection between a and b (f(a), f(b) of opposite signs) until |b - a| < eps.
Point2<double> bisect(const Level& f, Point2<double> a, Point2<double> b, double eps) {
  double fa = f(a);
  for (int it = 0; it < 200 && std::hypot(b[0] - a[0], b[1] - a[1]) >= eps; ++it) {
    const Point2<double> m{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    const double fm = f(m);
    if ((fm < 0) == (fa < 0)) { a = m; fa = fm; }
    else b = m;
  }
  return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
}

void refine(const Level& f, const Point2<double>& a, const Point2<double>& b, const TrimmingTolerance& tol, int depth,
            std::vector<Segment2<double>>& out) {
  const Point2<double> m{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
  const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
  if (depth >= tol.max_depth || len <= tol.eps) { out.push_back({a, b}); return; }
  const Point2<double> nrm{-dy / len, dx / len};
  const Point2<double> lo{m[0] - len * nrm[0], m[1] - len * nrm[1]}, hi{m[0] + len * nrm[0], m[1] + len * nrm[1]};
  const bool inside = lo[0] >= f.S.domain_lo(0) && hi[0] >= f.S.domain_lo(0) && lo[0] <= f.S.domain_hi(0) &&
                      hi[0] <= f.S.domain_hi(0) && lo[1] >= f.S.domain_lo(1) && hi[1] >= f.S.domain_lo(1) &&
                      lo[1] <= f.S.domain_hi(1) && hi[1] <= f.S.domain_hi(1);
  if (!inside || (f(lo) < 0) == (f(hi) < 0)) { out.push_back({a, b}); return; }
  const Point2<double> p = bisect(f, lo, hi, tol.eps / 4);
  if (std::hypot(p[0] - m[0], p[1] - m[1]) <= tol.eps / 2) { out.push_back({a, b}); return; }
  refine(f, a, p, tol, depth + 1, out);
  refine(f, p, b, tol, depth + 1, out);
}

}  // namespace

std::vector<Segment2<double>> trace_level_set(const BSpline<double>& S, int coord, double level, const TrimmingTolerance& tol) {
  const Level f{S, coord, level};
  const int G = tol.grid;
  const double r0 = S.domain_lo(0), r1 = S.domain_hi(0), t0 = S.domain_lo(1), t1 = S.domain_hi(1);
  auto node = [&](int i, int j) { return Point2<double>{r0 + (r1 - r0) * i / G, t0 + (t1 - t0) * j / G}; };
  std::vector<double> F((G + 1) * (G + 1));
  for (int j = 0; j <= G; ++j)
    for (int i = 0; i <= G; ++i) F[j * (G + 1) + i] = f(node(i, j));
  auto val = [&](int i, int j) { return F[j * (G + 1) + i]; };
  std::vector<Segment2<double>> out;
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      const Point2<double> c[4] = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
      const double v[4] = {val(i, j), val(i + 1, j), val(i + 1, j + 1), val(i, j + 1)};
      Point2<double> x[4];
      bool has[4];
      int n = 0;
      for (int e = 0; e < 4; ++e) {
        has[e] = (v[e] < 0) != (v[(e + 1) % 4] < 0);
        if (has[e]) { x[e] = bisect(f, c[e], c[(e + 1) % 4], tol.eps); ++n; }
      }
      if (n == 2) {
        int a = -1, b = -1;
        for (int e = 0; e < 4; ++e)
          if (has[e]) (a < 0 ? a : b) = e;
        refine(f, x[a], x[b], tol, 0, out);
      } else if (n == 4) {  // saddle: the centre's sign decides which corners are cut off
        const Point2<double> ctr{0.5 * (c[0][0] + c[2][0]), 0.5 * (c[0][1] + c[2][1])};
        if ((f(ctr) < 0) == (v[0] < 0)) {
          refine(f, x[0], x[1], tol, 0, out);
          refine(f, x[2], x[3], tol, 0, out);
        } else {
          refine(f, x[3], x[0], tol, 0, out);
          refine(f, x[1], x[2], tol, 0, out);
        }
      }
    }
  return out;
}

bool polyline_side(const BSpline<double>& S, int coord, double level, const std::vector<Segment2<double>>& poly, const Point2<double>& r) {
  const Level f{S, coord, level};
  Point2<double> ref{S.domain_lo(0), S.domain_lo(1)};
  double fref = f(ref);
  for (const Point2<double>& c : {Point2<double>{S.domain_hi(0), S.domain_lo(1)}, Point2<double>{S.domain_lo(0), S.domain_hi(1)},
                          Point2<double>{S.domain_hi(0), S.domain_hi(1)}}) {
    const double v = f(c);
    if (std::fabs(v) > std::fabs(fref)) { ref = c; fref = v; }
  }
  auto orient = [](const Point2<double>& a, const Point2<double>& b, const Point2<double>& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  };
  bool side = fref >= 0;
  for (const auto& sg : poly) {
    // Proper crossing of [ref, r] with [a, b]; a vertex shared by two segments is counted once by
    // the half-open test on the second segment's orientation.
    const double o1 = orient(ref, r, sg.a), o2 = orient(ref, r, sg.b);
    if ((o1 < 0) == (o2 < 0)) continue;
    const double o3 = orient(sg.a, sg.b, ref), o4 = orient(sg.a, sg.b, r);
    if ((o3 < 0) != (o4 < 0)) side = !side;
  }
  return side;
}

std::vector<double> crossings_at(const std::vector<Segment2<double>>& poly, double t) {
  std::vector<double> xs;
  for (const auto& s : poly) {
    const double ya = s.a[1] - t, yb = s.b[1] - t;
    if ((ya < 0) == (yb < 0) || ya == yb) continue;  // half-open in t: a vertex on the line counts once
    xs.push_back(s.a[0] + (s.b[0] - s.a[0]) * (ya / (ya - yb)));
  }
  std::sort(xs.begin(), xs.end());
  return xs;
}

}  // namespace splinex
