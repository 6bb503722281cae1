#include "cut/examples.hpp"

#include "spline/errors.hpp"
#include "spline/factories.hpp"

namespace splinex {

namespace {

using P = std::array<Rational, 2>;
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

}  // namespace

std::vector<std::string> cut_example_names() { return {"square", "L", "U"}; }

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
  } else {
    std::string names;
    for (const auto& n : cut_example_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("example", "'" + name + "' is not an example", "give one of " + names);
  }
  return e;
}

}  // namespace splinex
