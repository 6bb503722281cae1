#include "cut/examples.hpp"

#include "base/errors.hpp"
#include "base/point.hpp"
#include "spline/factories.hpp"

namespace splinex {

namespace {

using P = Point2<Rational>;
Rational q(long a, long b = 1) { return Rational(a, b); }

BSpline<Rational> segment(const P& a, const P& b) {
  return make_spline<Rational>({1}, {clamped_knots<Rational>(1, q(0), q(1))}, 2, {a[0], a[1], b[0], b[1]});
}

BSpline<Rational> cubic(const P& a, const P& b, const P& c, const P& d) {
  return make_spline<Rational>({3}, {clamped_knots<Rational>(3, q(0), q(1))}, 2, {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
}

Solid2<Rational> polygon(const std::vector<P>& v) {
  Solid2<Rational> S;
  for (std::size_t i = 0; i < v.size(); ++i) S.facets.push_back(segment(v[i], v[(i + 1) % v.size()]));
  return S;
}

CutPoint2<Rational> at(std::size_t facet, const Rational& s, const Rational& tx, const Rational& ty) {
  CutPoint2<Rational> c;
  c.facet = facet;
  c.param = s;
  c.tangent = {tx, ty};
  return c;
}

// The outline of a corridor of half-width w around an axis-parallel polyline with right-angle turns
// (no two consecutive segments collinear): the right side forward, the left side back
// (counter-clockwise). At a turn the offset lines meet at c + w (n_in + n_out), n the unit left
// normals (exact: the segments are axis-parallel).
Solid2<Rational> corridor(const std::vector<P>& c, const Rational& w) {
  auto normal = [](const P& a, const P& b) {
    P d{b[0] - a[0], b[1] - a[1]};
    const Rational len = d[0] != 0 ? (d[0] < 0 ? Rational(-d[0]) : d[0]) : (d[1] < 0 ? Rational(-d[1]) : d[1]);
    return P{-d[1] / len, d[0] / len};
  };
  const std::size_t n = c.size();
  std::vector<P> left, right;
  for (std::size_t i = 0; i < n; ++i) {
    P nn;
    if (i == 0) nn = normal(c[0], c[1]);
    else if (i + 1 == n) nn = normal(c[n - 2], c[n - 1]);
    else {
      const P a = normal(c[i - 1], c[i]), b = normal(c[i], c[i + 1]);
      nn = {a[0] + b[0], a[1] + b[1]};
    }
    left.push_back({c[i][0] + w * nn[0], c[i][1] + w * nn[1]});
    right.push_back({c[i][0] - w * nn[0], c[i][1] - w * nn[1]});
  }
  std::vector<P> loop = right;
  for (std::size_t i = n; i-- > 0;) loop.push_back(left[i]);
  return polygon(loop);
}

}  // namespace

std::vector<std::string> cut_example_names() { return {"square", "L", "U", "J", "K", "maze", "snake"}; }

CutExample cut_example(const std::string& name) {
  CutExample e;
  e.name = name;
  if (name == "square") {
    e.description = "the unit square cut from the middle of the bottom to the middle of the top";
    e.solid = polygon({{q(0), q(0)}, {q(1), q(0)}, {q(1), q(1)}, {q(0), q(1)}});
    e.cut.ends = {at(0, q(1, 2), q(0), q(1)), at(2, q(1, 2), q(0), q(-1))};
  } else if (name == "L") {
    e.description = "Figure 10's L-shaped domain [0,2]^2 minus (1,2]^2, cut from the right end (2, 1/2) to the top end (1/2, 2) around the reflex corner (1, 1)";
    e.solid = polygon({{q(0), q(0)}, {q(2), q(0)}, {q(2), q(1)}, {q(1), q(1)}, {q(1), q(2)}, {q(0), q(2)}});
    e.cut.ends = {at(1, q(1, 2), q(-1), q(0)), at(4, q(1, 2), q(0), q(-1))};
  } else if (name == "U") {
    e.description =
        "a U of height 3 with arms [0,1] and [2,3] and round bottoms: the outer bottom the cubic (0,1),(0,-1/3),(3,-1/3),(3,1) "
        "(lowest point (3/2, 0)), the inner one (2,1),(2,1/3),(1,1/3),(1,1) (lowest point (3/2, 1/2)); cut along the middle "
        "from the left arm's top (1/2, 3) to the right arm's top (5/2, 3), both tangents pointing down";
    e.solid.facets = {segment({q(0), q(3)}, {q(0), q(1)}),
                      cubic({q(0), q(1)}, {q(0), q(-1, 3)}, {q(3), q(-1, 3)}, {q(3), q(1)}),
                      segment({q(3), q(1)}, {q(3), q(3)}),
                      segment({q(3), q(3)}, {q(2), q(3)}),
                      segment({q(2), q(3)}, {q(2), q(1)}),
                      cubic({q(2), q(1)}, {q(2), q(1, 3)}, {q(1), q(1, 3)}, {q(1), q(1)}),
                      segment({q(1), q(1)}, {q(1), q(3)}),
                      segment({q(1), q(3)}, {q(0), q(3)})};
    e.cut.ends = {at(7, q(1, 2), q(0), q(-1)), at(3, q(1, 2), q(0), q(-1))};
  } else if (name == "J") {
    e.description =
        "a J: stem [2,3]x[1,5] and a hook below y = 1 between the outer cubic (0,1),(0,-1/3),(3,-1/3),(3,1) and the inner "
        "cubic (2,1),(2,1/3),(1,1/3),(1,1) (the U's bottoms); cut from the stem's top (5/2, 5) around the hook to its tip (1/2, 1), "
        "both tangents pointing down";
    e.solid.facets = {segment({q(3), q(5)}, {q(2), q(5)}),
                      segment({q(2), q(5)}, {q(2), q(1)}),
                      cubic({q(2), q(1)}, {q(2), q(1, 3)}, {q(1), q(1, 3)}, {q(1), q(1)}),
                      segment({q(1), q(1)}, {q(0), q(1)}),
                      cubic({q(0), q(1)}, {q(0), q(-1, 3)}, {q(3), q(-1, 3)}, {q(3), q(1)}),
                      segment({q(3), q(1)}, {q(3), q(5)})};
    e.cut.ends = {at(0, q(1, 2), q(0), q(-1)), at(3, q(1, 2), q(0), q(-1))};
  } else if (name == "K") {
    e.description =
        "a K: the bar [0,1]x[0,5] and two arms of the polygon (1,2),(3,0),(9/2,0),(2,5/2),(9/2,5),(3,5),(1,3); cut from the lower "
        "arm's foot (15/4, 0) up through the junction to the bar's top (1/2, 5), tangents (-1,2) and (0,-1)";
    e.solid = polygon({{q(0), q(0)}, {q(1), q(0)}, {q(1), q(2)}, {q(3), q(0)}, {q(9, 2), q(0)}, {q(2), q(5, 2)}, {q(9, 2), q(5)},
                       {q(3), q(5)}, {q(1), q(3)}, {q(1), q(5)}, {q(0), q(5)}});
    e.cut.ends = {at(3, q(1, 2), q(-1), q(2)), at(9, q(1, 2), q(0), q(-1))};
  } else if (name == "maze") {
    e.description =
        "a maze corridor of width 1 around the axis-parallel path (0,0),(4,0),(4,2),(1,2),(1,4),(5,4),(5,6),(0,6) (five turns); "
        "cut lengthwise from the middle of the entrance to the middle of the exit, tangents along the corridor";
    e.solid = corridor({{q(0), q(0)}, {q(4), q(0)}, {q(4), q(2)}, {q(1), q(2)}, {q(1), q(4)}, {q(5), q(4)}, {q(5), q(6)}, {q(0), q(6)}},
                       q(1, 2));
    // facets: right side 0..6, the exit cap 7, left side 8..14, the entrance cap 15
    e.cut.ends = {at(15, q(1, 2), q(1), q(0)), at(7, q(1, 2), q(1), q(0))};
  } else if (name == "snake") {
    e.description =
        "a snake: the band between y = g(x) and y = g(x) + 1 for x in [0, 8], g the cubic B-spline with uniform knots and "
        "control values 0, 3, -3, 3, -3, 3, -3, 0 (walls x = t, both polynomial), closed by vertical caps; cut lengthwise from "
        "the left cap's middle to the right cap's, tangents along the band";
    std::vector<Rational> inner{q(8, 5), q(16, 5), q(24, 5), q(32, 5)};
    const auto U = clamped_knots<Rational>(3, q(0), q(8), inner);
    const long gy[] = {0, 3, -3, 3, -3, 3, -3, 0};
    // x(t) = t in the B-spline basis: control x at the Greville abscissae.
    std::vector<Rational> low, high;
    for (int i = 0; i < 8; ++i) {
      const Rational gx = (U[i + 1] + U[i + 2] + U[i + 3]) / 3;
      low.push_back(gx), low.push_back(q(gy[i]));
    }
    for (int i = 7; i >= 0; --i) {
      const Rational gx = (U[i + 1] + U[i + 2] + U[i + 3]) / 3;
      high.push_back(gx), high.push_back(q(gy[i]) + 1);
    }
    std::vector<Rational> Ur;
    for (auto it = U.rbegin(); it != U.rend(); ++it) Ur.push_back(q(8) - *it);
    e.solid.facets = {make_spline<Rational>({3}, {U}, 2, low), segment({q(8), q(0)}, {q(8), q(1)}),
                      make_spline<Rational>({3}, {Ur}, 2, high), segment({q(0), q(1)}, {q(0), q(0)})};
    e.cut.ends = {at(3, q(1, 2), q(1), q(0)), at(1, q(1, 2), q(-1), q(0))};
  } else {
    std::string names;
    for (const auto& n : cut_example_names()) names += (names.empty() ? "" : ", ") + n;
    names += " (2D) or";
    for (const auto& n : cut_example3_names()) names += " " + n + ",";
    names.back() = ' ';
    throw UsageError("example", "'" + name + "' is not an example", "give one of " + names + "(3D)");
  }
  return e;
}

}  // namespace splinex
