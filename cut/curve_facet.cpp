#include "cut/curve_facet.hpp"

#include <cmath>
#include <cstdio>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "bernstein/subdivide.hpp"
#include "exact/root_isolation.hpp"
#include "float/rounding.hpp"
#include "spline/basis.hpp"
#include "spline/bernstein.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

using P2 = Point2<Rational>;

P2 at(const BSpline<Rational>& C, const Rational& s) {
  const auto v = evaluate(C, std::vector<Rational>{s});
  return {v[0], v[1]};
}
P2 d_at(const BSpline<Rational>& C, const Rational& s) {
  const auto v = derivative(C, std::vector<Rational>{s}, {1});
  return {v[0], v[1]};
}

// A Bezier piece's control points and its hodograph's (exact).
struct Piece {
  Rational lo, hi;
  std::vector<P2> P, H;
};

Piece make_piece(const BSpline<Rational>& bz) {
  Piece p;
  p.lo = bz.domain_lo(0);
  p.hi = bz.domain_hi(0);
  const int deg = bz.degrees[0];
  for (int i = 0; i <= deg; ++i) p.P.push_back({bz.points[2 * i], bz.points[2 * i + 1]});
  const Rational scale = Rational(deg) / (p.hi - p.lo);
  for (int i = 0; i < deg; ++i) p.H.push_back({(p.P[i + 1][0] - p.P[i][0]) * scale, (p.P[i + 1][1] - p.P[i][1]) * scale});
  return p;
}

std::pair<Piece, Piece> halve(const Piece& p) {
  // de Casteljau at 1/2 of the piece's own parameter
  std::vector<P2> a, b;
  std::vector<P2> w = p.P;
  const std::size_t n = w.size();
  a.push_back(w[0]);
  b.push_back(w[n - 1]);
  for (std::size_t r = 1; r < n; ++r) {
    for (std::size_t i = 0; i + r < n; ++i) w[i] = {(w[i][0] + w[i + 1][0]) / 2, (w[i][1] + w[i + 1][1]) / 2};
    a.push_back(w[0]);
    b.push_back(w[n - 1 - r]);
  }
  std::reverse(b.begin(), b.end());
  const Rational mid = (p.lo + p.hi) / 2;
  auto build = [](const Rational& lo, const Rational& hi, std::vector<P2> pts) {
    Piece q;
    q.lo = lo;
    q.hi = hi;
    q.P = std::move(pts);
    const int deg = static_cast<int>(q.P.size()) - 1;
    const Rational scale = Rational(deg) / (hi - lo);
    for (int i = 0; i < deg; ++i) q.H.push_back({(q.P[i + 1][0] - q.P[i][0]) * scale, (q.P[i + 1][1] - q.P[i][1]) * scale});
    return q;
  };
  return {build(p.lo, mid, a), build(mid, p.hi, b)};
}

std::array<Rational, 4> box(const Piece& p) {
  std::array<Rational, 4> b{p.P[0][0], p.P[0][1], p.P[0][0], p.P[0][1]};
  for (const auto& x : p.P) {
    if (x[0] < b[0]) b[0] = x[0];
    if (x[1] < b[1]) b[1] = x[1];
    if (b[2] < x[0]) b[2] = x[0];
    if (b[3] < x[1]) b[3] = x[1];
  }
  return b;
}

bool boxes_disjoint(const Piece& a, const Piece& b) {
  const auto A = box(a), B = box(b);
  return A[2] < B[0] || B[2] < A[0] || A[3] < B[1] || B[3] < A[1];
}

// d . C' > 0 on the piece (all hodograph coefficients).
bool monotone_along(const Piece& p, const P2& d) {
  for (const auto& h : p.H)
    if (!(dot(d, h) > 0)) return false;
  return true;
}

std::vector<Piece> pieces_of(const BSpline<Rational>& S) {
  std::vector<Piece> out;
  for (const auto& bz : extract_bezier(S)) out.push_back(make_piece(bz.spline));
  return out;
}

// Exact linear solve (Gauss-Jordan with pivot search for non-zero).
std::vector<std::vector<Rational>> solve_exact(std::vector<std::vector<Rational>> A, std::vector<std::vector<Rational>> B) {
  const std::size_t n = A.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t piv = k;
    while (piv < n && A[piv][k] == 0) ++piv;
    if (piv == n) throw DomainError("control-points", "the least-squares system is singular", "give fewer control points or a finer march");
    std::swap(A[k], A[piv]);
    std::swap(B[k], B[piv]);
    for (std::size_t i = 0; i < n; ++i) {
      if (i == k || A[i][k] == 0) continue;
      const Rational f = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= f * A[k][j];
      for (std::size_t c = 0; c < B[i].size(); ++c) B[i][c] -= f * B[k][c];
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (auto& v : B[i]) v /= A[i][i];
  return B;
}

}  // namespace

CuttingCurve fit_cutting_curve(const Solid2<Rational>& S, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                               const CurveFitOptions& o) {
  if (o.control_points < 4 || o.control_points > 1000) throw ValidationError("control-points", "is " + std::to_string(o.control_points), "give 4 .. 1000");
  if (!(o.step > 0) || o.step > 0.5) throw ValidationError("step", "is not in (0, 1/2]", "give a marching step such as 1/256");
  const auto fd = round_spline<double>(f, "guide");
  const P2 pq = at(S.facets[cut.ends[0].facet], cut.ends[0].param), qq = at(S.facets[cut.ends[1].facet], cut.ends[1].param);
  const double p[2] = {to_double(pq[0]), to_double(pq[1])}, q[2] = {to_double(qq[0]), to_double(qq[1])};
  auto F = [&](double x, double y, double* g) {
    const double cx = std::min(1.0, std::max(0.0, x)), cy = std::min(1.0, std::max(0.0, y));
    g[0] = derivative(fd, std::vector<double>{cx, cy}, {1, 0})[0];
    g[1] = derivative(fd, std::vector<double>{cx, cy}, {0, 1})[0];
    return evaluate(fd, std::vector<double>{cx, cy})[0];
  };
  auto project = [&](double& x, double& y) {
    for (int it = 0; it < 30; ++it) {
      double g[2];
      const double v = F(x, y, g), gg = g[0] * g[0] + g[1] * g[1];
      if (!(gg > 0)) throw DomainError("guide", "has a vanishing gradient on its zero set near the march", "change the guide's weights or knots");
      x -= v * g[0] / gg;
      y -= v * g[1] / gg;
      if (std::abs(v) < 1e-15) break;
    }
  };
  // The zero set passes the second cut point at about |f(q)| / |grad f(q)|; the march stops when it
  // comes that close (plus a step), and q closes the polygon.
  double gq[2];
  const double fq = F(q[0], q[1], gq);
  const double reach = 1.5 * o.step + 2 * std::abs(fq) / std::max(1e-300, std::hypot(gq[0], gq[1]));
  double gp[2];
  const double fp = F(p[0], p[1], gp);
  const double start_offset = std::max(o.step, 2 * std::abs(fp) / std::max(1e-300, std::hypot(gp[0], gp[1])));
  CuttingCurve out;
  out.polygon.push_back({p[0], p[1]});
  // Start a little inside along the tangent (f*(p) is only about 0), then project onto f* = 0.
  double dir[2] = {to_double(cut.ends[0].tangent[0]), to_double(cut.ends[0].tangent[1])};
  const double dn = std::hypot(dir[0], dir[1]);
  double x = p[0] + start_offset * dir[0] / dn, y = p[1] + start_offset * dir[1] / dn;
  project(x, y);
  const double x0 = x, y0 = y;
  bool reached = false, closed = false;
  for (int k = 0; k < o.max_steps; ++k) {
    double g[2];
    F(x, y, g);
    double t[2] = {-g[1], g[0]};
    if (t[0] * dir[0] + t[1] * dir[1] < 0) t[0] = -t[0], t[1] = -t[1];
    const double tn = std::hypot(t[0], t[1]);
    dir[0] = t[0] / tn;
    dir[1] = t[1] / tn;
    double nx = x + o.step * dir[0], ny = y + o.step * dir[1];
    project(nx, ny);
    x = nx;
    y = ny;
    if (x < -o.step || x > 1 + o.step || y < -o.step || y > 1 + o.step) break;
    if (std::hypot(x - q[0], y - q[1]) < reach) {
      reached = true;
      break;
    }
    if (k > 8 && std::hypot(x - x0, y - y0) < 1.5 * o.step) {
      closed = true;
      break;
    }
    out.polygon.push_back({x, y});
  }
  if (!reached) {
    char where[160];
    std::snprintf(where, sizeof where, " (the march %s at (%.4g, %.4g) after %zu steps, %.3g from it; normalized units)",
                  closed ? "closed a loop" : "ended", x, y, out.polygon.size(), std::hypot(x - q[0], y - q[1]));
    throw DomainError("guide", std::string("its zero set traced from the first cut point does not reach the second") + where,
                      "certify the guide first (cut guide), refine it (--inner-knots), or shorten --step");
  }
  out.polygon.push_back({q[0], q[1]});
  // Chord-length parameters, exact from the doubles.
  std::vector<double> len{0};
  for (std::size_t i = 1; i < out.polygon.size(); ++i)
    len.push_back(len.back() + std::hypot(out.polygon[i][0] - out.polygon[i - 1][0], out.polygon[i][1] - out.polygon[i - 1][1]));
  const double L = len.back();
  const int m = o.control_points;
  std::vector<Rational> inner;
  for (int i = 1; i <= m - 4; ++i) inner.push_back(Rational(i, m - 3));
  const auto U = clamped_knots<Rational>(3, Rational(0), Rational(1), inner);
  // Fixed: P0 = p, P_{m-1} = q, P1 = p + a t_p h1/3, P_{m-2} = q + b t_q h/3 with C'(0) = 3 (P1 - P0) / U[4].
  // The end derivatives' lengths: the polygon's length over |t|, as doubles (dyadic, exact).
  auto factor = [&](const P2& t) { return exact_from_double(L / std::hypot(to_double(t[0]), to_double(t[1])), "tangent"); };
  const Rational a = factor(cut.ends[0].tangent), b = factor(cut.ends[1].tangent);
  std::vector<P2> Pc(m);
  Pc[0] = pq;
  Pc[m - 1] = qq;
  const Rational h0 = U[4] - U[1], h1 = U[m + 2] - U[m - 1];
  Pc[1] = {pq[0] + a * cut.ends[0].tangent[0] * h0 / 3, pq[1] + a * cut.ends[0].tangent[1] * h0 / 3};
  Pc[m - 2] = {qq[0] + b * cut.ends[1].tangent[0] * h1 / 3, qq[1] + b * cut.ends[1].tangent[1] * h1 / 3};
  const int free_n = m - 4;
  if (free_n > 0) {
    std::vector<std::vector<Rational>> A(free_n, std::vector<Rational>(free_n, Rational(0)));
    std::vector<std::vector<Rational>> B(free_n, std::vector<Rational>(2, Rational(0)));
    const std::size_t nb = static_cast<std::size_t>(m);
    for (std::size_t k = 1; k + 1 < out.polygon.size(); ++k) {
      const Rational s = exact_from_double(len[k] / L, "parameter");
      const std::size_t span = find_span(U, 3, nb, s);
      const auto N = basis_funs(span, s, 3, U);
      // residual target: x_k - sum over fixed control points
      P2 r{exact_from_double(out.polygon[k][0], "point"), exact_from_double(out.polygon[k][1], "point")};
      std::vector<std::pair<int, Rational>> freev;
      for (int j = 0; j <= 3; ++j) {
        const int idx = static_cast<int>(span) - 3 + j;
        if (idx <= 1 || idx >= m - 2) {
          r[0] -= N[j] * Pc[idx][0];
          r[1] -= N[j] * Pc[idx][1];
        } else {
          freev.emplace_back(idx - 2, N[j]);
        }
      }
      for (const auto& [i, vi] : freev) {
        for (const auto& [j, vj] : freev) A[i][j] += vi * vj;
        B[i][0] += vi * r[0];
        B[i][1] += vi * r[1];
      }
    }
    for (int i = 0; i < free_n; ++i)
      if (A[i][i] == 0) A[i][i] = Rational(1);  // a control point no sample sees: keep it at 0 influence (solved as 0 target)
    const auto X = solve_exact(A, B);
    // The least-squares solution's denominators grow with the data; its control points are rounded
    // to doubles (dyadic rationals, relative change <= 2^-53, far below the fit's own error). The
    // curve decided valid or not is this exactly represented curve.
    for (int i = 0; i < free_n; ++i) Pc[i + 2] = {exact_from_double(to_double(X[i][0])), exact_from_double(to_double(X[i][1]))};
  }
  std::vector<Rational> pts;
  for (const auto& c : Pc) pts.push_back(c[0]), pts.push_back(c[1]);
  out.curve = make_spline<Rational>({3}, {U}, 2, pts);
  const auto cd = round_spline<double>(out.curve, "curve");
  for (std::size_t k = 0; k < out.polygon.size(); ++k) {
    const auto v = evaluate(cd, std::vector<double>{len[k] / L});
    out.fit_max_deviation = std::max(out.fit_max_deviation, std::hypot(v[0] - out.polygon[k][0], v[1] - out.polygon[k][1]));
  }
  return out;
}

std::optional<int> classify_point(const Solid2<Rational>& S, const P2& x) {
  // Ray x + (r, 0), r > 0: crossings of facet pieces whose y(t) - x_y has a root of odd multiplicity
  // strictly inside the piece, with x(t) > x_x there.
  int crossings = 0;
  for (const auto& F : S.facets)
    for (const auto& bz : extract_bezier(F)) {
      const auto& B = bz.spline;
      const int deg = B.degrees[0];
      std::vector<Rational> yb(deg + 1), xb(deg + 1);
      for (int i = 0; i <= deg; ++i) xb[i] = B.points[2 * i], yb[i] = B.points[2 * i + 1] - x[1];
      bool all_zero = true;
      for (const auto& v : yb) all_zero = all_zero && v == 0;
      if (all_zero) {  // a horizontal piece on the ray's line
        Rational lo = xb[0], hi = xb[0];
        for (const auto& v : xb) lo = v < lo ? v : lo, hi = hi < v ? v : hi;
        if (lo <= x[0] && x[0] <= hi) {
          // on the piece's hull: exact check of the point being on it is not needed for a witness
          return std::nullopt;
        }
        if (x[0] < lo) return std::nullopt;  // the ray runs along a facet
        continue;
      }
      const auto power = bernstein_to_power(yb);
      const auto roots = isolate_real_roots(power, Rational(0), Rational(1), 64);
      for (const auto& r : roots) {
        // x(t) on the root's interval, bounded by Horner's scheme in exact interval arithmetic;
        // the interval shrinks by bisection on the sign of y until the bound decides.
        if (r.lo <= 0 || r.hi >= 1) return std::nullopt;  // at (or near) a piece end: a vertex on the ray
        Rational lo = r.lo, hi = r.hi;
        const auto xp = bernstein_to_power(xb);
        for (int refine = 0;; ++refine) {
          Rational vlo = 0, vhi = 0;
          for (std::size_t k = xp.size(); k-- > 0;) {  // Horner in intervals, t in [lo, hi] (lo > 0)
            const Rational a1 = vlo * lo, a2 = vlo * hi, a3 = vhi * lo, a4 = vhi * hi;
            Rational mn = a1, mx = a1;
            for (const Rational& v : {a2, a3, a4}) mn = v < mn ? v : mn, mx = mx < v ? v : mx;
            vlo = mn + xp[k];
            vhi = mx + xp[k];
          }
          if (x[0] < vlo) {
            if (r.multiplicity % 2 == 1) ++crossings;
            else return std::nullopt;  // a touch: try another point
            break;
          }
          if (vhi < x[0]) break;
          if (lo == hi) return 0;  // x(t) = x_x at an exact root: the point is on the boundary
          if (refine > 200) return std::nullopt;
          // refine the root's interval by bisection on the sign of y
          const Rational mid = (lo + hi) / 2;
          Rational ym(0), ylo(0);
          for (std::size_t k = power.size(); k-- > 0;) ym = ym * mid + power[k], ylo = ylo * lo + power[k];
          if (ym == 0) lo = hi = mid;
          else if ((ym > 0) == (ylo > 0)) lo = mid;
          else hi = mid;
        }
      }
    }
  return crossings % 2 == 1 ? 1 : -1;
}

namespace {

// A witness of a collision: among the suspect parameters strictly inside C's domain, the first
// whose point is outside the solid or on its boundary (exact ray casting) refutes "no collision".
void find_outside_witness(const Solid2<Rational>& S, const BSpline<Rational>& C, const std::vector<Rational>& suspects, ValidityResult& R) {
  const Rational s0 = C.domain_lo(0), s1 = C.domain_hi(0);
  for (const auto& s : suspects) {
    if (!(s0 < s && s < s1)) continue;
    const P2 x = at(C, s);
    const auto cls = classify_point(S, x);
    if (cls && *cls <= 0) {
      R.witness_s = s;
      R.witness = x;
      R.witness_meaning = *cls == 0 ? "C(s) lies on the boundary, exactly" : "C(s) lies outside the solid (exact ray casting)";
      R.inside = Verdict::refuted(R.witness_meaning);
      return;
    }
  }
}

// Section 2's conditions together: valid when every one is certified, invalid when one is violated.
Verdict overall_verdict(const ValidityResult& R) {
  const bool valid = R.interpolates && R.tangents && R.regular.is_proved() && R.injective.is_proved() && R.inside.is_proved();
  const bool invalid = !R.interpolates || !R.tangents || R.regular.is_refuted() || R.inside.is_refuted();
  return valid     ? Verdict::proved("Section 2's conditions hold: interpolation, tangents, regularity, injectivity, no collision")
         : invalid ? Verdict::refuted("a condition is violated (see the conditions)")
                   : Verdict::undecided("a condition is undecided (see the conditions)");
}

}  // namespace

ValidityResult certify_cutting_curve(const Solid2<Rational>& S, const CutData2<Rational>& cut, const BSpline<Rational>& C,
                                     const ValidityOptions& o) {
  ValidityResult R;
  const P2 p = at(S.facets[cut.ends[0].facet], cut.ends[0].param), q = at(S.facets[cut.ends[1].facet], cut.ends[1].param);
  const Rational s0 = C.domain_lo(0), s1 = C.domain_hi(0);
  R.interpolates = at(C, s0) == p && at(C, s1) == q;
  const P2 d0 = d_at(C, s0), d1 = d_at(C, s1);
  R.tangents = cross(d0, cut.ends[0].tangent) == 0 && dot(d0, cut.ends[0].tangent) > 0 && cross(d1, cut.ends[1].tangent) == 0 &&
               dot(d1, cut.ends[1].tangent) < 0;
  const auto cp = pieces_of(C);
  // One budget for the three subdivisions, spent in turn; once spent, what is left is undecided.
  auto budget = [&] {
    Budget b;
    b.max_boxes = o.max_pairs - R.pairs;
    b.max_depth = o.max_depth;
    return b;
  };
  const Walk dfs{Order::depth_first, 4, false};

  // Regularity: on each piece, x' or y' of one strict sign; else halve.
  auto regular = [&](const Piece& pc, int) {
    for (int a = 0; a < 2; ++a) {
      bool pos = true, neg = true;
      for (const auto& h : pc.H) pos = pos && h[a] > 0, neg = neg && h[a] < 0;
      if (pos || neg) return Examined::settled;
    }
    const Rational mid = (pc.lo + pc.hi) / 2;
    const P2 dm = d_at(C, mid);
    if (dm[0] == 0 && dm[1] == 0) {
      R.singular_s = mid;
      return Examined::refuted;
    }
    return Examined::split;
  };
  auto halve_piece = [](Piece&& pc, int, auto&& emit) {
    auto [a, b] = halve(pc);
    emit(std::move(a));
    emit(std::move(b));
  };
  const Subdivision reg = subdivide(cp, dfs, budget(), regular, halve_piece, [](Piece&&, Left) {});
  R.pairs += reg.examined;
  const std::string spent = "the subdivision budget (ValidityOptions: max_pairs, max_depth) ran out";
  R.regular = reg.stop == Subdivision::Stop::refuted ? Verdict::refuted("C' = 0 at singular_at, exactly")
              : reg.decided()                        ? Verdict::proved("x' or y' of one strict sign on every piece")
                                                     : Verdict::undecided(spent);

  // Injectivity: pairs of intervals.
  struct Pair {
    Piece a, b;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < cp.size(); ++i)
    for (std::size_t j = i; j < cp.size(); ++j) pairs.push_back({cp[i], cp[j]});
  auto injective = [&](const Pair& pr, int) {
    const bool same = pr.a.lo == pr.b.lo && pr.a.hi == pr.b.hi;
    const bool adjacent = pr.a.hi == pr.b.lo || pr.b.hi == pr.a.lo;
    if (!same && !adjacent && boxes_disjoint(pr.a, pr.b)) return Examined::settled;
    if (same || adjacent) {
      // one direction d with d . C' > 0 on both: C is monotone along d on the union
      const Rational lo = same ? pr.a.lo : std::min(pr.a.lo, pr.b.lo), hi = same ? pr.a.hi : std::max(pr.a.hi, pr.b.hi);
      const P2 chord = sub(at(C, hi), at(C, lo));
      const P2 dm = d_at(C, (lo + hi) / 2);
      for (const P2& d : {dm, chord})
        if (monotone_along(pr.a, d) && monotone_along(pr.b, d)) return Examined::settled;
    }
    return Examined::split;
  };
  auto split_pair = [](Pair&& pr, int, auto&& emit) {
    if (pr.a.lo == pr.b.lo && pr.a.hi == pr.b.hi) {  // a piece against itself: its halves and the two apart
      auto [a, b] = halve(pr.a);
      emit(Pair{a, a});
      emit(Pair{b, b});
      emit(Pair{a, b});
      return;
    }
    auto [a1, a2] = halve(pr.a);
    auto [b1, b2] = halve(pr.b);
    for (const auto& x : {a1, a2})
      for (const auto& y : {b1, b2}) emit(Pair{x, y});
  };
  const Subdivision inj = subdivide(std::move(pairs), dfs, budget(), injective, split_pair, [](Pair&&, Left) {});
  R.pairs += inj.examined;
  R.injective = inj.decided() ? Verdict::proved("every two pieces apart (disjoint boxes) or monotone along one direction together")
                               : Verdict::undecided(spent);

  // No collision: curve intervals against facet pieces (split at the cut points).
  std::vector<std::pair<Piece, std::size_t>> fp;
  for (const auto& P : split_at_cut_points(S, cut))
    for (const auto& bz : extract_bezier(P.curve)) fp.push_back({make_piece(bz.spline), P.facet});
  // n . (F - c) <= 0 on the facet piece
  auto behind = [](const Piece& f, const P2& n, const P2& c) {
    for (const auto& x : f.P)
      if (dot(n, sub(x, c)) > 0) return false;
    return true;
  };
  auto touches = [](const Piece& f, const P2& c) { return f.P.front() == c || f.P.back() == c; };
  struct CPair {
    Piece c, f;
  };
  std::vector<CPair> cpairs;
  std::vector<Rational> suspects;
  for (const auto& c : cp)
    for (const auto& f : fp) cpairs.push_back({c, f.first});
  auto inside = [&](const CPair& pr, int) {
    if (boxes_disjoint(pr.c, pr.f)) return Examined::settled;
    const bool at_start = pr.c.lo == s0 && touches(pr.f, p) && pr.c.hi < s1;
    const bool at_end = pr.c.hi == s1 && touches(pr.f, q) && s0 < pr.c.lo;
    if (at_start || at_end) {
      const P2 c = at_start ? p : q;
      const P2 t = cut.ends[at_start ? 0 : 1].tangent;
      const P2 e = pr.f.P.front() == c ? sub(pr.f.P[1], pr.f.P[0]) : sub(pr.f.P[pr.f.P.size() - 2], pr.f.P.back());
      std::vector<P2> cands{t, {-e[1], e[0]}, {e[1], -e[0]}};
      bool ok = false;
      for (const P2& n : cands) {
        if (!(dot(n, t) > 0)) continue;
        // near p: n . C' > 0; near q: C runs into q, n . C' < 0
        const P2 nn = at_start ? n : P2{-n[0], -n[1]};
        if (monotone_along(pr.c, nn) && behind(pr.f, n, c)) ok = true;
      }
      if (ok) return Examined::settled;
    }
    return Examined::split;
  };
  auto split_cpair = [&](CPair&& pr, int depth, auto&& emit) {
    auto [c1, c2] = halve(pr.c);
    auto [f1, f2] = halve(pr.f);
    for (const auto& x : {c1, c2})
      for (const auto& y : {f1, f2}) emit(CPair{x, y});
    // Look for a witness early: the middle of this curve interval.
    if (depth == 6 || depth == 12) suspects.push_back((pr.c.lo + pr.c.hi) / 2);
  };
  auto suspect = [&](CPair&& pr, Left why) {
    if (why == Left::depth) suspects.push_back((pr.c.lo + pr.c.hi) / 2);
  };
  const Subdivision col = subdivide(std::move(cpairs), dfs, budget(), inside, split_cpair, suspect);
  R.pairs += col.examined;
  R.inside = col.decided() ? Verdict::proved("no piece meets the boundary, except at the cut points, where C enters the solid")
                            : Verdict::undecided(spent + "; no point outside the solid was found");
  if (!R.inside.is_proved()) find_outside_witness(S, C, suspects, R);
  R.verdict = overall_verdict(R);
  return R;
}

BSpline<Rational> from_frame(const BSpline<Rational>& C, const Frame2& f) {
  BSpline<Rational> out = C;
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int a = 0; a < 2; ++a) out.points[2 * i + a] = f.lo[a] + f.scale * out.points[2 * i + a];
  return out;
}

std::pair<Solid2<Rational>, Solid2<Rational>> split_solid(const Solid2<Rational>& S, const CutData2<Rational>& cut, const BSpline<Rational>& C) {
  // The boundary as a cyclic list of pieces split at the cut points.
  const auto parts = split_at_cut_points(S, cut);
  auto starts_at = [&](const BoundaryPiece& p, const CutPoint2<Rational>& e) { return p.facet == e.facet && p.curve.domain_lo(0) == e.param; };
  std::size_t ip = parts.size(), iq = parts.size();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (starts_at(parts[k], cut.ends[0])) ip = k;
    if (starts_at(parts[k], cut.ends[1])) iq = k;
  }
  if (ip == parts.size() || iq == parts.size()) throw DomainError("cut", "the cut points are not on the split boundary", "report this with the input");
  Solid2<Rational> S1, S2;
  for (std::size_t k = ip; k != iq; k = (k + 1) % parts.size()) S1.facets.push_back(parts[k].curve);
  S1.facets.push_back(reverse(C, 0));
  for (std::size_t k = iq; k != ip; k = (k + 1) % parts.size()) S2.facets.push_back(parts[k].curve);
  S2.facets.push_back(C);
  validate_solid(S1);
  validate_solid(S2);
  if (signed_area(S1) + signed_area(S2) != signed_area(S))
    throw DomainError("cut", "the two parts' areas do not add up to the solid's", "report this with the input");
  return {S1, S2};
}

}  // namespace splinex
