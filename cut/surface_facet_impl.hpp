// Internal to cut/: the helpers the cutting surface's sources share (surface_domain.cpp,
// surface_patch.cpp, surface_guided.cpp, surface_certificate.cpp, surface_injectivity.cpp). The
// public entry is cut/surface_facet.hpp.
#pragma once
#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <string>
#include <vector>

#include "base/point.hpp"
#include "bernstein/tensor.hpp"
#include "cut/surface_facet.hpp"
#include "spline/bezier.hpp"

namespace splinex {
namespace surface_detail {

using P2 = Point2<Rational>;
using P3 = Point3<Rational>;
using K = CGAL::Simple_cartesian<CGAL::Gmpq>;

inline K::Point_2 cg(const P2& p) { return K::Point_2(CGAL::Gmpq(p[0].backend().data()), CGAL::Gmpq(p[1].backend().data())); }

inline std::vector<K::Point_2> cg_polygon(const std::vector<P2>& v) {
  std::vector<K::Point_2> r;
  for (const auto& p : v) r.push_back(cg(p));
  return r;
}

inline Rational rabs(const Rational& x) { return x < 0 ? Rational(-x) : x; }

// q rounded to the nearest multiple of 2^-bits (through MPFR at 256 bits: the callers' q are at most
// 1 in magnitude). Defined in surface_domain.cpp.
Rational round_to_grid(const Rational& q, unsigned bits);

// Whether the box [lo, hi] meets the polygon (its edges or its inside).
inline bool box_meets_polygon(const P2& lo, const P2& hi, const std::vector<K::Point_2>& poly) {
  const K::Iso_rectangle_2 box(cg(lo), cg(hi));
  for (std::size_t j = 0; j < poly.size(); ++j)
    if (CGAL::do_intersect(K::Segment_2(poly[j], poly[(j + 1) % poly.size()]), box)) return true;
  return CGAL::bounded_side_2(poly.begin(), poly.end(), cg(lo), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

inline bool in_polygon(const P2& w, const std::vector<K::Point_2>& poly) {
  return CGAL::bounded_side_2(poly.begin(), poly.end(), cg(w), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

inline Bernstein<Rational> scaled(Bernstein<Rational> b, const Rational& s) {
  for (auto& c : b.c) c *= s;
  return b;
}

// Injectivity and regularity by a grid of cells (the fallback when no single projection works, as
// for surfaces that turn through 90 degrees, like the maiden's wave). At level m every Bezier piece
// is cut into 2^m x 2^m cells, numbered (I, J) over the whole patch. Then
//   (a) on every window of 3 x 3 cells that holds a cell meeting Omega, F = A p is a monotone map:
//       A (2 x 3) the left inverse of Dp at the window's centre, rounded (any fixed A keeps the
//       argument), and the symmetric part of DF = A Dp positive definite on each of its 9 cells
//       (Bernstein signs of A_0 p_u and 4 (A_0 p_u)(A_1 p_v) - (A_0 p_v + A_1 p_u)^2). The window is a
//       rectangle, so F is injective on it and DF non-singular: p is injective and regular there;
//   (b) any two cells meeting Omega whose indices differ by 3 or more in I or J have disjoint boxes
//       of Bernstein coefficients (the convex hulls of their images).
// Two parameters of Omega whose cells differ by at most 2 in I and J share a window (a); all other
// pairs are separated by (b). So p is injective on Omega and regular there. Levels are tried until
// both hold or the cells exceed max_cells. Defined in surface_injectivity.cpp.
struct GridCertificate {
  bool proved = false;
  int level = -1;
  std::size_t cells = 0, windows = 0;
  std::string why;  // the last level's failure
};

GridCertificate grid_injectivity(const std::vector<BezierPiece<Rational>>& pieces, const std::vector<K::Point_2>& poly, int max_level,
                                 std::size_t max_cells);

}  // namespace surface_detail
}  // namespace splinex
