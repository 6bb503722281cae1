// Point projection (solve/projection.hpp) on surfaces whose closest points are known exactly: a
// plane, the exact sphere (stereographic, rational biquadratic) with a rational and an irrational
// closest point, a roof with a crease (a C^0 knot line), a cubic B-spline surface against dense
// sampling; refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "exact/rational.hpp"
#include "float/rounding.hpp"
#include "solve/curve_projection.hpp"
#include "solve/projection.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"
#include "tests/solve/solve_fixtures.hpp"

using namespace splinex;
using R = Rational;

namespace {

BSpline<R> plane() {  // z = 0 over [-1, 1]^2
  return make_spline<R>({1, 1}, {{R(-1), R(-1), R(1), R(1)}, {R(-1), R(-1), R(1), R(1)}}, 3,
                        {R(-1), R(-1), R(0), R(1), R(-1), R(0), R(-1), R(1), R(0), R(1), R(1), R(0)});
}

}  // namespace

TEST_CASE("projection: a point over a plane, closest point exact and certified", "[solve]") {
  const auto p = project_point<R>(plane(), {R(1, 3), R(1, 5), R(2)});
  REQUIRE(p.closest.size() == 1);
  CHECK(p.closest_certified);
  CHECK(p.complete);
  const auto& c = p.critical[p.closest[0]];
  CHECK(c.exact);
  CHECK(c.where == "interior");
  CHECK(c.lo == std::vector<R>{R(1, 3), R(1, 5)});
  CHECK(c.d2_lo == R(4));
  CHECK(p.distance2_lo == R(4));
  CHECK(p.distance2_hi == R(4));
  // The edges' own critical points (the foot on each boundary line) and the four corners.
  int edges = 0, corners = 0;
  for (const auto& x : p.critical) {
    edges += x.where == "edge";
    corners += x.where == "corner";
  }
  CHECK(edges == 4);
  CHECK(corners == 4);
}

TEST_CASE("projection: the exact sphere, a rational and an irrational closest point", "[solve]") {
  const auto S = test::stereographic_sphere();
  // (2, 2, -1) = 3 (2/3, 2/3, -1/3), the sphere point at (u, v) = (1/2, 1/2): distance 2.
  const auto a = project_point<R>(S, {R(2), R(2), R(-1)});
  REQUIRE(a.closest.size() == 1);
  CHECK(a.closest_certified);
  const auto& ca = a.critical[a.closest[0]];
  CHECK(ca.exact);
  CHECK(ca.lo == std::vector<R>{R(1, 2), R(1, 2)});
  CHECK(ca.point == std::vector<R>{R(2, 3), R(2, 3), R(-1, 3)});
  CHECK(ca.d2_lo == R(4));
  // (1, 1, 0): the closest sphere point (1, 1, 0) / sqrt 2 at u = v = 1 / sqrt 2; d^2 = 3 - 2 sqrt 2.
  const auto b = project_point<R>(S, {R(1), R(1), R(0)});
  REQUIRE(b.closest.size() == 1);
  CHECK(b.closest_certified);
  const auto& cb = b.critical[b.closest[0]];
  CHECK_FALSE(cb.exact);
  CHECK(cb.unique);
  for (int d = 0; d < 2; ++d) {
    CHECK(cb.lo[d] * cb.lo[d] * 2 < 1);
    CHECK(cb.hi[d] * cb.hi[d] * 2 > 1);
  }
  // d2_lo <= 3 - 2 sqrt 2 <= d2_hi, i.e. (3 - d2_lo)^2 >= 8 >= (3 - d2_hi)^2.
  CHECK((3 - b.distance2_lo) * (3 - b.distance2_lo) >= 8);
  CHECK((3 - b.distance2_hi) * (3 - b.distance2_hi) <= 8);
  CHECK(b.distance2_hi - b.distance2_lo < R(1, 1000000000));
}

TEST_CASE("projection: a roof, the closest point on its crease", "[solve]") {
  // z = 1 - |u| over u in [-1, 1], v in [0, 1]: bilinear with a knot at u = 0 (a crease: degree 1).
  const auto S = make_spline<R>({1, 1}, {{R(-1), R(-1), R(0), R(1), R(1)}, {R(0), R(0), R(1), R(1)}}, 3,
                                {R(-1), R(0), R(0), R(0), R(0), R(1), R(1), R(0), R(0),  //
                                 R(-1), R(1), R(0), R(0), R(1), R(1), R(1), R(1), R(0)});
  const auto p = project_point<R>(S, {R(0), R(1, 3), R(5)});
  REQUIRE(p.closest.size() == 1);
  CHECK(p.closest_certified);
  const auto& c = p.critical[p.closest[0]];
  CHECK(c.exact);
  CHECK(c.lo == std::vector<R>{R(0), R(1, 3)});
  CHECK(c.where == "edge");
  CHECK(c.d2_lo == R(16));
}

TEST_CASE("projection: a cubic B-spline surface, the certified distance below every sample", "[solve]") {
  // z = bumps over [0, 3]^2 with two interior knots per direction (C^2).
  const std::vector<R> k{R(0), R(0), R(0), R(0), R(1), R(2), R(3), R(3), R(3), R(3)};
  std::vector<R> pts;
  const int zs[36] = {0, 1, 0, 2, 1, 0, 1, 3, 2, 0, 1, 2, 0, 2, 4, 1, 0, 1, 2, 1, 0, 3, 2, 0, 1, 0, 2, 1, 1, 2, 0, 1, 0, 2, 1, 0};
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      pts.push_back(R(3 * i, 5));
      pts.push_back(R(3 * j, 5));
      pts.push_back(R(zs[i + 6 * j], 2));
    }
  const auto S = make_spline<R>({3, 3}, {k, k}, 3, pts);
  const std::vector<R> P{R(7, 5), R(8, 5), R(3)};
  const auto p = project_point<R>(S, P);
  CHECK(p.complete);
  REQUIRE(p.closest_certified);
  CHECK(p.distance2_hi - p.distance2_lo < R(1, 1000000000));
  // Every sample of the surface is at least as far (a sample is a surface point).
  R best(-1);
  for (int j = 0; j <= 30; ++j)
    for (int i = 0; i <= 30; ++i) {
      const auto x = evaluate(S, {R(i, 10), R(j, 10)});
      R d2(0);
      for (int c = 0; c < 3; ++c) d2 += (x[c] - P[c]) * (x[c] - P[c]);
      CHECK(p.distance2_lo <= d2);
      if (best < 0 || d2 < best) best = d2;
    }
  // And the closest point is not far from the best sample on a 0.1 grid.
  CHECK(best - p.distance2_hi < R(1, 2));
  // The same in double: the closest distance agrees.
  BSpline<double> Sd;
  Sd.degrees = S.degrees;
  Sd.q = 3;
  for (const auto& kv : S.knots) {
    Sd.knots.emplace_back();
    for (const auto& x : kv) Sd.knots.back().push_back(to_double(x));
  }
  for (const auto& x : S.points) Sd.points.push_back(to_double(x));
  const auto pd = project_point<double>(Sd, {1.4, 1.6, 3.0});
  CHECK_FALSE(pd.closest_certified);  // nothing is certified in double
  CHECK(std::abs(pd.distance2_hi - to_double(p.distance2_hi)) < 1e-9);
}

TEST_CASE("projection: refusals", "[solve]") {
  CHECK_THROWS_AS(project_point<R>(plane(), {R(0), R(0)}), ValidationError);
  const auto flat = make_spline<R>({0, 1}, {{R(0), R(1)}, {R(0), R(0), R(1), R(1)}}, 3, {R(0), R(0), R(0), R(0), R(1), R(0)});
  CHECK_THROWS_AS(project_point<R>(flat, {R(0), R(0), R(1)}), ValidationError);
  const auto curve = make_spline<R>({1}, {{R(0), R(0), R(1), R(1)}}, 3, {R(0), R(0), R(0), R(1), R(0), R(0)});
  CHECK_THROWS_AS(project_point<R>(curve, {R(0), R(0), R(1)}), ValidationError);
}

TEST_CASE("curve projection: Figure 12's situation, a circle over a saddle in four segments", "[solve]") {
  // The saddle z = (x^2 - y^2) / 8 over [-2, 2]^2 and the exact circle of radius 13/5 at z = 1/2
  // (four rational quarters, C^0 at the knots): the circle leaves the square's projection near the
  // axes, the projection leaves the domain through all four sides twice (tests/data/saddle.json,
  // circle.json; the feet of the axis points lie beyond |x| = 2 for radius > 5/2, those of the
  // diagonal points inside for radius < 2 sqrt 2).
  const auto S = test::spline(R"({"type": "bspline", "degrees": [2, 2], "knots": [[-2, -2, -2, 2, 2, 2], [-2, -2, -2, 2, 2, 2]],
    "points": [[-2, -2, 0], [0, -2, -1], [2, -2, 0], [-2, 0, 1], [0, 0, 0], [2, 0, 1], [-2, 2, 0], [0, 2, -1], [2, 2, 0]]})");
  const auto C = test::spline(R"({"type": "bspline", "degrees": [2], "knots": [[0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]],
    "points": [["13/5", 0, "1/2"], ["13/5", "13/5", "1/2"], [0, "13/5", "1/2"], ["-13/5", "13/5", "1/2"], ["-13/5", 0, "1/2"],
               ["-13/5", "-13/5", "1/2"], [0, "-13/5", "1/2"], ["13/5", "-13/5", "1/2"], ["13/5", 0, "1/2"]],
    "weights": [1, 1, 2, 2, 4, 4, 8, 8, 16]})");
  const auto r = project_curve(C, S);
  CHECK(r.segments == 4);
  CHECK(r.loops == 0);
  CHECK(r.certified_counts);
  CHECK(r.consistent);
  CHECK(r.max_cosine < 1e-12);
  // Eight ends, all on the surface's boundary, each with one branch.
  int ends = 0;
  for (const auto& p : r.special) {
    CHECK(p.kind == "surface boundary");
    CHECK(p.branches == 1);
    ++ends;
  }
  CHECK(ends == 8);
}

TEST_CASE("curve projection: a fold (turning point) and branches that end on the curve's ends", "[solve]") {
  // z = x^2 (a parabolic cylinder) and the vertical line (1/10, 0, t), t in [0, 2]: from below the
  // focal height one foot, above it three (the cubic 2x^3 + (1 - 2t) x - 1/10 = 0 gains two roots
  // at a fold), and the outer feet leave the domain at x = -1 (t = 31/20) and x = 1 (t = 29/20):
  // exactly, since 2 + (1 - 2t) (+-1) -+ 1/10 = 0 there.
  const auto S = solve_fixtures::fold_surface();
  const auto C = solve_fixtures::fold_line();
  const auto r = project_curve(C, S);
  CHECK(r.certified_counts);
  CHECK(r.consistent);
  CHECK(r.segments == 2);
  int turning = 0;
  bool left = false, right = false;
  for (const auto& p : r.special) {
    turning += p.kind == "turning point";
    if (p.kind == "surface boundary" && p.exact) {
      left = left || (p.lo == std::vector<R>{R(-1), R(0), R(31, 20)});
      right = right || (p.lo == std::vector<R>{R(1), R(0), R(29, 20)});
    }
  }
  CHECK(turning == 1);
  CHECK(left);
  CHECK(right);
}

// Issue 47 (reproducers in tests/data/repro/solver): the closest-point verdict, a pole, double.
using solve_fixtures::repro;

TEST_CASE("projection: no candidate that an undecided box may beat is named closest", "[solve]") {
  // z = x^2, the point 10^-25 off the axis at height 3/4: the feet near (+-1/2, 1/2, 1/4) at
  // d^2 = 1/2 -+ 10^-25 lie 10^-25 from split lines (found by inflating the cluster's hull), the
  // ridge point (0, 1/2, 0) at d^2 >= 9/16 is critical but farther.
  const R e = R(1) / R(boost::multiprecision::pow(boost::multiprecision::mpz_int(10), 25));
  const auto S = repro("pcyl.json");
  const std::vector<R> P{e, R(1, 2), R(3, 4)};
  const auto p = project_point<R>(S, P);
  REQUIRE(p.closest_certified);
  REQUIRE(p.closest.size() == 1);
  CHECK(R(0) < p.critical[p.closest[0]].point[0]);  // the foot at x > 0, nearer to P
  CHECK(p.distance2_lo <= R(1, 2) - e);
  CHECK(R(1, 2) - e <= p.distance2_hi);
  CHECK(p.distance2_hi < R(1, 2));
  // With a budget of 40 boxes per system the feet stay in undecided boxes (d^2 <= 3/4 + ...)
  // while the edges u = +-1 have certified critical points at d^2 = 17/16: the planted bug (an
  // undecided box's upper bound not lowering the bound of the minimum) names them closest.
  SolveOptions small;
  small.max_boxes = 40;
  const auto q = project_point<R>(S, P, small);
  CHECK_FALSE(q.closest_certified);
  REQUIRE_FALSE(q.undecided.empty());
  R best_box = q.undecided[0].d2_hi;
  for (const auto& u : q.undecided)
    if (u.d2_hi < best_box) best_box = u.d2_hi;
  CHECK(best_box < R(17, 16));
  for (std::size_t i : q.closest) CHECK_FALSE(best_box < q.critical[i].d2_lo);
  CHECK_FALSE(q.undecided_closest.empty());
  CHECK(q.reason.find("undecided") != std::string::npos);
}

TEST_CASE("projection: the pole of a surface of revolution is answered", "[solve]") {
  // The sphere octant with its pole edge collapsed; from (0, 0, 2) on the axis the distance does
  // not depend on the longitude (that equation vanishes identically): the pole at d^2 = 1.
  const auto p = project_point<R>(repro("octant.json"), {R(0), R(0), R(2)});
  REQUIRE_FALSE(p.closest.empty());
  CHECK(p.distance2_lo == 1);
  CHECK(p.distance2_hi == 1);
  for (std::size_t i : p.closest) {
    CHECK(p.critical[i].point == std::vector<R>{R(0), R(0), R(1)});
    CHECK((p.critical[i].along.empty() || p.critical[i].collapsed));
  }
  CHECK(p.closest_certified);
}

TEST_CASE("projection in double: enclosures outward, never inverted or negative", "[solve]") {
  // (-10/7, -6/7, 8/49) lies on the saddle z = (x^2 - y^2)/8; rounded to double it is within
  // 1e-16 of it. Each enclosure must hold the exact squared distance of the double data at its
  // box's centre (a round-to-nearest |D|^2 gave [5.9e-32, -9.9e-17]).
  const auto S = round_spline<double>(repro("saddle.json"));
  const std::vector<double> P{-10.0 / 7, -6.0 / 7, 8.0 / 49};
  const auto p = project_point<double>(S, P);
  const auto check = [&](const CriticalPoint<double>& c) {
    CHECK(0 <= c.d2_lo);
    CHECK(c.d2_lo <= c.d2_hi);
    std::vector<R> uv(2);
    for (int d = 0; d < 2; ++d) uv[d] = (exact_from_double(c.lo[d]) + exact_from_double(c.hi[d])) / 2;
    BSpline<R> Se;
    Se.degrees = S.degrees;
    Se.q = S.q;
    for (const auto& kv : S.knots) {
      Se.knots.emplace_back();
      for (double x : kv) Se.knots.back().push_back(exact_from_double(x));
    }
    for (double x : S.points) Se.points.push_back(exact_from_double(x));
    const auto x = evaluate(Se, uv);
    R d2(0);
    for (int k = 0; k < 3; ++k) d2 += (x[k] - exact_from_double(P[k])) * (x[k] - exact_from_double(P[k]));
    CHECK(exact_from_double(c.d2_lo) <= d2);
    CHECK(d2 <= exact_from_double(c.d2_hi));
  };
  for (const auto& c : p.critical) check(c);
  for (const auto& c : p.undecided) check(c);
  CHECK(0 <= p.distance2_lo);
  CHECK(p.distance2_lo <= p.distance2_hi);
  CHECK(p.distance2_hi < 1e-20);
}

TEST_CASE("curve projection: a generic case with two folds is certified (traced joins agree)", "[solve]") {
  // The line from (-1, 1/7, 3/2) to (1, 2/7, 3/2) over z = x^2 + y^2: the solution curve turns
  // back twice in t. Uniform tracing steps
  // (and an absolute stopping test that the rounding noise near a fold never meets) lost the
  // branches there: "the traced joins do not agree" although every count was right.
  const auto C = test::spline(R"({"type": "bspline", "degrees": [1], "knots": [["-1", "-1", "1", "1"]], "points": [["-1", "1/7", "3/2"], ["1", "2/7", "3/2"]]})");
  const auto r = project_curve(C, repro("paraboloid.json"));
  CHECK(r.certified_counts);
  CHECK(r.consistent);
  std::size_t turning = 0;
  for (const auto& p : r.special)
    if (p.kind == "turning point") {
      ++turning;
      CHECK(p.branches == 2);
    }
  CHECK(turning == 2);
  // Two feet born at one fold and dying at the other (a loop in (u, v, t)), and two short
  // segments entering and leaving through the surface's boundary (slices 0 2 3 2 3 2 0).
  CHECK(r.loops == 1);
  CHECK(r.segments == 2);
  CHECK(r.max_cosine < 1e-9);
}

// Issue 47 (planted bugs, tests/solve/test_planted.cpp): the certificates' regression checks.
TEST_CASE("projection: every distance enclosure holds the exact squared distance at its box's corners", "[solve]") {
  // The paraboloid z = x^2 + y^2 and P = (1, 1/3, 0): an irrational foot in a certified box. The
  // corners of every box are surface points: their exact distances (the spline evaluated by its
  // basis functions) lie in the box's enclosure, also where the enclosure is tight at a corner.
  const auto S = quadric_patch(R(1), R(1), R(1));
  const std::vector<R> P{R(1), R(1, 3), R(0)};
  const auto p = project_point<R>(S, P);
  REQUIRE(p.closest_certified);
  CHECK_FALSE(p.critical[p.closest[0]].exact);
  std::size_t boxes = 0;
  for (const auto* list : {&p.critical, &p.undecided})
    for (const auto& c : *list) {
      if (c.lo == c.hi) continue;
      ++boxes;
      for (std::size_t m = 0; m < 4; ++m) {
        const std::vector<R> uv{m & 1 ? c.hi[0] : c.lo[0], m & 2 ? c.hi[1] : c.lo[1]};
        const auto x = evaluate(S, uv);
        R d2(0);
        for (int k = 0; k < 3; ++k) d2 += (x[k] - P[k]) * (x[k] - P[k]);
        CHECK(c.d2_lo <= d2);
        CHECK(d2 <= c.d2_hi);
      }
    }
  CHECK(boxes > 0);
  CHECK(p.distance2_lo <= p.distance2_hi);
}

TEST_CASE("projection: a budget too small to finish names no farther point closest", "[solve]") {
  // z = x^2 and P = (1/10, 1/2, 3/4) with 10 boxes per system: the foot near (0.58, 1/2) is not
  // reached in the interior nor on the edges v = 0, 1; the queue left is undecided and keeps the
  // edge point (1, 1/2, 1) at d^2 = 349/400 from being certified: the surface point
  // (1/2, 1/2, 1/4) at d^2 = 41/100 beats it (exactly).
  const auto S = repro("pcyl.json");
  const std::vector<R> P{R(1, 10), R(1, 2), R(3, 4)};
  SolveOptions small;
  small.max_boxes = 10;
  const auto q = project_point<R>(S, P, small);
  CHECK_FALSE(q.closest_certified);
  CHECK_FALSE(q.undecided.empty());
  const auto x = evaluate(S, {R(1, 2), R(1, 2)});
  R closer(0);
  for (int k = 0; k < 3; ++k) closer += (x[k] - P[k]) * (x[k] - P[k]);
  REQUIRE(closer == R(41, 100));
  CHECK(q.distance2_lo <= closer);
  CHECK_FALSE(q.undecided_closest.empty());
}

TEST_CASE("curve projection: a budget too small to finish is not certified", "[solve]") {
  // The fold case above with 2 boxes per system: nothing is solved, so no count may be certified;
  // a slice that were certified would have to count at least the feet found by exact sign
  // changes of the foot equation 2u^3 + (1 - 2t) u - 1/10 (v = 0) on a grid of u in [-1, 1].
  const auto S = solve_fixtures::fold_surface();
  const auto C = solve_fixtures::fold_line();
  CurveProjectionOptions o;
  o.solve.max_boxes = 2;
  const auto r = project_curve(C, S, o);
  CHECK_FALSE(r.certified_counts);
  CHECK_FALSE(r.undecided.empty());
  REQUIRE_FALSE(r.slices.empty());
  for (const auto& sl : r.slices) {
    const auto g = [&](const R& u) -> R { return 2 * u * u * u + (1 - 2 * sl.t) * u - R(1, 10); };
    std::size_t changes = 0;
    for (int k = -8; k < 8; ++k) changes += g(R(k, 8)) * g(R(k + 1, 8)) < 0;
    if (sl.certified) CHECK(sl.roots >= changes);
  }
}
