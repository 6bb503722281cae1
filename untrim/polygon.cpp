#include "untrim/polygon.hpp"

#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>

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
