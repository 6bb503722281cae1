#include "untrim/loops.hpp"

#include <string>

#include "float/mpfr.hpp"
#include "untrim/curved.hpp"
#include "untrim/interval_join.hpp"
#include "untrim/poly.hpp"

namespace splinex {

namespace {

using poly::Poly;
using poly::bernstein_monomial;

// Closed segments [a, b] and [c, d] share a point (exact orientation tests).
bool segments_meet(const Point2<Rational>& a, const Point2<Rational>& b, const Point2<Rational>& c, const Point2<Rational>& d) {
  using detail::orient2;
  using detail::sgn;
  const int o1 = sgn(orient2(a, b, c)), o2 = sgn(orient2(a, b, d)), o3 = sgn(orient2(c, d, a)), o4 = sgn(orient2(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && detail::within(a, b, c)) return true;
  if (o2 == 0 && detail::within(a, b, d)) return true;
  if (o3 == 0 && detail::within(c, d, a)) return true;
  if (o4 == 0 && detail::within(c, d, b)) return true;
  return false;
}

// Does the ray from p to +x cross the edge a-b? Half-open in y, so a ray through a vertex counts
// the two edges meeting there once; p must not lie on the edge. The parity over a loop's edges
// tells whether p is strictly inside it (crossing number).
template <class T>
bool ray_crosses(const Point2<T>& a, const Point2<T>& b, const Point2<T>& p) {
  // x of the edge at height p[1] compared with p[0], without division: sign-corrected orientation.
  return (p[1] < a[1]) != (p[1] < b[1]) && (a[1] < b[1]) == (T(0) < detail::orient2(a, b, p));
}

}  // namespace

Polygon TrimmedDomain::edge(std::size_t l, std::size_t i) const {
  const auto& L = loops.at(l);
  Polygon P{L.at(i)};
  if (l < controls.size() && i < controls[l].size()) P.insert(P.end(), controls[l][i].begin(), controls[l][i].end());
  P.push_back(L[(i + 1) % L.size()]);
  return P;
}

void validate_loop_vertices(const TrimmedDomain& D, std::size_t l) {
  const auto& L = D.loops[l];
  const auto qs = [](const Rational& v) { return ArithTraits<Rational>::to_string(v); };
  for (std::size_t i = 0; i < L.size(); ++i) {
    if (L[i] == L[(i + 1) % L.size()])
      throw ValidationError(vertex_field(l, i), "is degenerate: repeats the next vertex (zero-length edge)", "remove the repeated vertex");
    for (int d = 0; d < 2; ++d)
      if (L[i][d] < D.lo[d] || D.hi[d] < L[i][d])
        throw DomainError(vertex_field(l, i), "leaves the domain: coordinate " + std::to_string(d) + " is " + qs(L[i][d]) + ", outside [" +
                                           qs(D.lo[d]) + ", " + qs(D.hi[d]) + "]",
                          "keep trimming loops inside the parameter box");
  }
}

void validate_domain(const TrimmedDomain& D) {
  for (int d = 0; d < 2; ++d)
    if (!(D.lo[d] < D.hi[d]))
      throw ValidationError("domain[" + std::to_string(d) + "]", "is empty (lo >= hi)", "give [lo, hi] with lo < hi");
  if (D.curved()) {
    validate_curved_domain(D);
    return;
  }
  for (std::size_t l = 0; l < D.loops.size(); ++l) {
    const auto& L = D.loops[l];
    const std::string f = loop_field(l);
    if (L.size() < 3)
      throw ValidationError(f, "is degenerate: " + std::to_string(L.size()) + " vertices", "give at least 3 vertices");
    validate_loop_vertices(D, l);
    bool collinear = true;
    for (std::size_t i = 2; i < L.size(); ++i)
      if (detail::orient2(L[0], L[1], L[i]) != 0) collinear = false;
    if (collinear)
      throw ValidationError(f, "is degenerate: all vertices on one line (zero area)", "give a loop that encloses a region");
    if (!polygon_is_simple(L))
      throw ValidationError(f, "is self-intersecting", "split it into simple loops (no edge may cross or touch another)");
  }
  // Loops meeting: edges of different loops paired by an interval join on x (each loop's own
  // edges were checked by CGAL's simplicity test, a sweep).
  std::vector<std::pair<Rational, Rational>> ex;
  std::vector<std::pair<std::size_t, std::size_t>> id;
  for (std::size_t l = 0; l < D.loops.size(); ++l)
    for (std::size_t i = 0; i < D.loops[l].size(); ++i) {
      const auto &a = D.loops[l][i], &b = D.loops[l][(i + 1) % D.loops[l].size()];
      ex.emplace_back(std::min(a[0], b[0]), std::max(a[0], b[0]));
      id.emplace_back(l, i);
    }
  // The join is output-sensitive in the pairs whose x-ranges meet; many equal or nested loops make
  // those quadratic in number (16,000 copies of two loops: minutes), so above a budget the same
  // first pair is found by CGAL's arrangement of the edges instead (O((n + k) log n)).
  const auto meets = [&](std::size_t l, std::size_t i, std::size_t m, std::size_t j) {
    const auto &A = D.loops[l], &B = D.loops[m];
    return l != m && segments_meet(A[i], A[(i + 1) % A.size()], B[j], B[(j + 1) % B.size()]);
  };
  const std::size_t budget = std::max<std::size_t>(1000000, 16 * ex.size());
  if (count_overlapping_pairs(ex, budget + 1) <= budget) {
    if (const auto first = first_meeting_edges(ex, id, meets)) throw_meeting_edges(*first);
    return;
  }
  // Over the budget: the two loops by CGAL's sweep, then their first meeting edges by the join.
  const auto pair = first_meeting_loops(D.loops);
  if (!pair) return;
  std::vector<std::pair<Rational, Rational>> ex2;
  std::vector<std::pair<std::size_t, std::size_t>> id2;
  for (std::size_t k = 0; k < id.size(); ++k)
    if (id[k].first == (*pair)[0] || id[k].first == (*pair)[1]) {
      ex2.push_back(ex[k]);
      id2.push_back(id[k]);
    }
  const auto first = first_meeting_edges(ex2, id2, meets);
  if (!first) throw DomainError("loops", "the sweep found loops that meet and the edge test did not", "please report this input");
  throw_meeting_edges(*first);
}

template <class T>
std::vector<Tile<T>> untrim_domain(const TrimmedDomain& D, const std::array<std::vector<Rational>, 2>& knot_lines) {
  const auto cv = [](const Rational& x) { return ArithTraits<T>::from_rational(x); };
  if (D.curved()) {
    std::vector<Tile<T>> out;
    // Float arithmetics: irrational crossings with knot lines approximated well below the rounding.
    const int bits = ArithTraits<T>::exact ? 0 : ArithTraits<T>::precision_bits() + 16;
    for (const auto& t : untrim_curved(D, knot_lines, bits)) out.push_back(convert_tile<T>(t, cv));
    return out;
  }
  const T x0 = cv(D.lo[0]), x1 = cv(D.hi[0]), y0 = cv(D.lo[1]), y1 = cv(D.hi[1]);
  std::vector<Segment2<T>> segs{{{x0, y0}, {x1, y0}}, {{x1, y0}, {x1, y1}}, {{x0, y1}, {x1, y1}}, {{x0, y0}, {x0, y1}}};
  std::vector<T> barriers;
  for (const auto& k : knot_lines[0])
    if (D.lo[0] < k && k < D.hi[0]) {
      segs.push_back({{cv(k), y0}, {cv(k), y1}});
      barriers.push_back(cv(k));
    }
  for (const auto& k : knot_lines[1])
    if (D.lo[1] < k && k < D.hi[1]) segs.push_back({{x0, cv(k)}, {x1, cv(k)}});
  std::vector<std::vector<Point2<T>>> loops;
  for (const auto& L : D.loops) {
    std::vector<Point2<T>> P;
    for (const auto& v : L) P.push_back({cv(v[0]), cv(v[1])});
    for (std::size_t i = 0; i < P.size(); ++i) segs.push_back({P[i], P[(i + 1) % P.size()]});
    loops.push_back(std::move(P));
  }
  const auto traps = vertical_decomposition(planar_subdivision(segs));
  // Each trapezoid is in the region when its centre is inside an odd number of loops: the parity of
  // the loop edges a horizontal ray from the centre crosses (ray_crosses, summed over the
  // disjoint loops). Edges and centres are paired by an interval join on y, so the work grows with
  // the crossings, not with trapezoids times edges.
  std::vector<Point2<T>> centres;
  std::vector<std::pair<T, T>> centre_y, edge_y;
  for (const auto& tz : traps) {
    centres.push_back({(tz.x0 + tz.x1) / T(2), (tz.yb0 + tz.yb1 + tz.yt0 + tz.yt1) / T(4)});
    centre_y.emplace_back(centres.back()[1], centres.back()[1]);
  }
  std::vector<std::pair<const Point2<T>*, const Point2<T>*>> edges;
  for (const auto& P : loops)
    for (std::size_t i = 0; i < P.size(); ++i) {
      const auto &a = P[i], &b = P[(i + 1) % P.size()];
      edges.emplace_back(&a, &b);
      edge_y.emplace_back(a[1] < b[1] ? a[1] : b[1], a[1] < b[1] ? b[1] : a[1]);
    }
  std::vector<char> odd(traps.size(), 0);
  for_overlapping_pairs(edge_y, centre_y, [&](std::size_t e, std::size_t z) {
    const auto &a = *edges[e].first, &b = *edges[e].second;
    if (ray_crosses(a, b, centres[z])) odd[z] ^= 1;
  });
  std::vector<int> labels(traps.size(), -1);
  for (std::size_t z = 0; z < traps.size(); ++z) labels[z] = odd[z] ? 0 : -1;
  return merge_trapezoids(traps, labels, barriers);
}

std::vector<int> loop_signs(const TrimmedDomain& D) {
  std::vector<int> s;
  for (std::size_t l = 0; l < D.loops.size(); ++l) {
    int depth = 0;
    for (std::size_t m = 0; m < D.loops.size(); ++m)
      if (m != l && inside_loop(D, m, D.loops[l][0])) ++depth;  // straight or curved edges
    s.push_back(depth % 2 == 0 ? 1 : -1);
  }
  return s;
}

Rational region_area(const TrimmedDomain& D) {
  const auto s = loop_signs(D);
  Rational a(0);
  for (std::size_t l = 0; l < D.loops.size(); ++l)
    a += s[l] * abs(D.curved() ? loop_signed_area(D, l) : polygon_area(D.loops[l]));
  return a;
}

Rational green_integral(const TrimmedDomain& D, const BSpline<Rational>& f) {
  if (f.dim() != 2 || f.q != 1 || f.is_rational())
    throw ValidationError("density", "must be a scalar polynomial in (x, y)", "give q = 1 and no weights");
  // f in monomials: m[a][b] x^a y^b.
  const int n0 = f.degrees[0], n1 = f.degrees[1];
  std::vector<std::vector<Rational>> mono(n0 + 1, std::vector<Rational>(n1 + 1, Rational(0)));
  for (int j = 0; j <= n1; ++j) {
    const Poly by = bernstein_monomial(n1, j, f.domain_lo(1), f.domain_hi(1));
    for (int i = 0; i <= n0; ++i) {
      const Poly bx = bernstein_monomial(n0, i, f.domain_lo(0), f.domain_hi(0));
      const Rational& c = f.points[static_cast<std::size_t>(j) * (n0 + 1) + i];
      for (int a = 0; a <= n0; ++a)
        for (int b = 0; b <= n1; ++b) mono[a][b] += c * bx[a] * by[b];
    }
  }
  // int_region x^a y^b dA = sum_loops sign * orientation * oint x^(a+1)/(a+1) y^b dy, each edge a
  // Bezier curve (x(t), y(t)) on [0, 1] (straight edges: degree 1).
  const auto sg = loop_signs(D);
  Rational total(0);
  for (std::size_t l = 0; l < D.loops.size(); ++l) {
    const auto& L = D.loops[l];
    const Rational area = D.curved() ? loop_signed_area(D, l) : polygon_area(L);
    const int orient = area > 0 ? 1 : -1;  // counter-clockwise loops give +area
    Rational loop_sum(0);
    for (std::size_t e = 0; e < L.size(); ++e) {
      const Polygon P = D.edge(l, e);
      std::vector<Rational> bx, by;
      for (const auto& p : P) {
        bx.push_back(p[0]);
        by.push_back(p[1]);
      }
      const Poly xs = poly::from_bernstein(bx, 0, 1), ys = poly::from_bernstein(by, 0, 1), dys = poly::derivative(ys);
      if (poly::is_zero(dys)) continue;
      for (int a = 0; a <= n0; ++a)
        for (int b = 0; b <= n1; ++b) {
          if (mono[a][b] == 0) continue;
          const Poly g = poly::mul(poly::mul(poly::pow(xs, a + 1), poly::pow(ys, b)), dys);
          loop_sum += mono[a][b] * poly::integral01(g) / (a + 1);
        }
    }
    total += sg[l] * orient * loop_sum;
  }
  return total;
}

BSpline<Rational> monomial_density(int a, int b, const TrimmedDomain& D) {
  BSpline<Rational> f;
  f.degrees = {a, b};
  f.q = 1;
  for (int d = 0; d < 2; ++d) {
    const int n = d == 0 ? a : b;
    std::vector<Rational> U(n + 1, D.lo[d]);
    U.insert(U.end(), n + 1, D.hi[d]);
    f.knots.push_back(U);
  }
  for (int j = 0; j <= b; ++j)
    for (int i = 0; i <= a; ++i) {
      Rational c(1);
      for (int k = 0; k < a; ++k) c *= k < a - i ? D.lo[0] : D.hi[0];
      for (int k = 0; k < b; ++k) c *= k < b - j ? D.lo[1] : D.hi[1];
      f.points.push_back(c);
    }
  return f;
}

template std::vector<Tile<Rational>> untrim_domain(const TrimmedDomain&, const std::array<std::vector<Rational>, 2>&);
template std::vector<Tile<double>> untrim_domain(const TrimmedDomain&, const std::array<std::vector<Rational>, 2>&);
template std::vector<Tile<Mpfr>> untrim_domain(const TrimmedDomain&, const std::array<std::vector<Rational>, 2>&);

}  // namespace splinex
