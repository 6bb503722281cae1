#include "untrim/polygon.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <CGAL/Simple_cartesian.h>

namespace splinex {

namespace {
using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
CGAL::Gmpq gq(const Rational& x) { return CGAL::Gmpq(x.backend().data()); }
Rational rq(const CGAL::Gmpq& x) { return Rational(x.mpq()); }
CGAL::Polygon_2<K> to_cgal(const Polygon& p) {
  CGAL::Polygon_2<K> P;
  for (const auto& v : p) P.push_back(K::Point_2(gq(v[0]), gq(v[1])));
  return P;
}
}  // namespace

Rational polygon_area(const Polygon& p) {
  if (p.size() < 3) return Rational(0);
  return rq(to_cgal(p).area());
}

bool polygon_is_simple(const Polygon& p) { return p.size() >= 3 && to_cgal(p).is_simple(); }

Rational polygon_union_area(const std::vector<Polygon>& polygons) {
  CGAL::Polygon_set_2<K> set;
  std::vector<CGAL::Polygon_2<K>> ps;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (polygons[i].size() < 3) continue;
    auto P = to_cgal(polygons[i]);
    if (!P.is_simple())
      throw std::invalid_argument("polygon_union_area: polygon " + std::to_string(i) + " is not simple");
    const auto o = P.orientation();
    if (o == CGAL::COLLINEAR) continue;
    if (o == CGAL::CLOCKWISE) P.reverse_orientation();
    ps.push_back(std::move(P));
  }
  if (ps.empty()) return Rational(0);
  set.join(ps.begin(), ps.end());
  std::vector<CGAL::Polygon_with_holes_2<K>> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  CGAL::Gmpq a(0);
  for (const auto& pw : parts) {
    a += pw.outer_boundary().area();
    for (auto h = pw.holes_begin(); h != pw.holes_end(); ++h) a += h->area();  // holes are clockwise
  }
  return rq(a);
}

namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Segments = CGAL::Arr_segment_traits_2<EK>;

EK::FT ek(const Rational& x) { return EK::FT(mpq_class(x.backend().data())); }

/// Do any two of the given loops (each simple) meet? A vertex of two loops, or CGAL's sweep finding
/// an interior intersection of two edges (a crossing, an overlap, or a vertex inside an edge: the
/// edges of one simple loop share only the vertices of adjacent edges). The sweep stops at the first
/// one: O(n log n).
bool loops_meet(const std::vector<Polygon>& loops, const std::vector<std::size_t>& which) {
  std::vector<std::pair<const Point2<Rational>*, std::size_t>> vertices;
  for (const std::size_t l : which)
    for (const auto& v : loops[l]) vertices.emplace_back(&v, l);
  std::sort(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) { return *a.first < *b.first; });
  for (std::size_t k = 1; k < vertices.size(); ++k)
    if (*vertices[k].first == *vertices[k - 1].first && vertices[k].second != vertices[k - 1].second) return true;
  std::vector<Segments::Curve_2> curves;
  for (const std::size_t l : which)
    for (std::size_t i = 0; i < loops[l].size(); ++i) {
      const auto &a = loops[l][i], &b = loops[l][(i + 1) % loops[l].size()];
      curves.emplace_back(EK::Point_2(ek(a[0]), ek(a[1])), EK::Point_2(ek(b[0]), ek(b[1])));
    }
  return CGAL::do_curves_intersect(curves.begin(), curves.end());
}

}  // namespace

std::optional<std::array<std::size_t, 2>> first_meeting_loops(const std::vector<Polygon>& loops) {
  const std::size_t n = loops.size();
  std::vector<std::size_t> which(n);
  std::iota(which.begin(), which.end(), 0);
  if (n < 2 || !loops_meet(loops, which)) return std::nullopt;
  // The least m such that loops 0..m meet (monotone in m: bisection), then the least l < m such that
  // loops 0..l and m meet (monotone in l).
  std::size_t lo = 1, hi = n - 1;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    which.resize(mid + 1);
    std::iota(which.begin(), which.end(), 0);
    if (loops_meet(loops, which)) hi = mid;
    else lo = mid + 1;
  }
  const std::size_t m = lo;
  std::size_t a = 0, b = m - 1;
  while (a < b) {
    const std::size_t mid = a + (b - a) / 2;
    which.resize(mid + 1);
    std::iota(which.begin(), which.end(), 0);
    which.push_back(m);
    if (loops_meet(loops, which)) b = mid;
    else a = mid + 1;
  }
  return std::array<std::size_t, 2>{a, m};
}

Polygon clip_halfplane(const Polygon& p, const Rational& a, const Rational& b, const Rational& c) {
  Polygon out;
  const std::size_t n = p.size();
  auto f = [&](const Point2<Rational>& v) { return Rational(a * v[0] + b * v[1] + c); };
  for (std::size_t i = 0; i < n; ++i) {
    const auto &P = p[i], &Q = p[(i + 1) % n];
    const Rational fp = f(P), fq = f(Q);
    if (fp >= 0) out.push_back(P);
    if ((fp > 0 && fq < 0) || (fp < 0 && fq > 0)) {
      const Rational s = fp / (fp - fq);
      out.push_back({P[0] + (Q[0] - P[0]) * s, P[1] + (Q[1] - P[1]) * s});
    }
  }
  return out;
}

Polygon affine_region_polygon(const std::vector<std::pair<Rational, Rational>>& box,
                              const std::vector<CellCondition<Rational>>& region, const Rational al[2], const Rational be[2],
                              const Rational ga[2]) {
  Polygon poly{{box[0].first, box[1].first}, {box[0].second, box[1].first}, {box[0].second, box[1].second},
               {box[0].first, box[1].second}};
  for (const auto& c : region) {
    if (c.check_lo) poly = clip_halfplane(poly, be[c.coord], ga[c.coord], Rational(al[c.coord] - c.lo));
    if (c.check_hi) poly = clip_halfplane(poly, -be[c.coord], -ga[c.coord], Rational(c.hi - al[c.coord]));
  }
  return poly;
}

}  // namespace splinex
