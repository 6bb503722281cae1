// Point projection (solve/projection.hpp) on surfaces whose closest points are known exactly: a
// plane, the exact sphere (stereographic, rational biquadratic) with a rational and an irrational
// closest point, a roof with a crease (a C^0 knot line), a cubic B-spline surface against dense
// sampling; refusals.
#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "solve/curve_projection.hpp"
#include "solve/projection.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"

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
  const auto S = test::spline(R"({"type": "bspline", "degrees": [2, 2], "knots": [[-1, -1, -1, 1, 1, 1], [-1, -1, -1, 1, 1, 1]],
    "points": [[-1, -1, 1], [0, -1, -1], [1, -1, 1], [-1, 0, 1], [0, 0, -1], [1, 0, 1], [-1, 1, 1], [0, 1, -1], [1, 1, 1]]})");
  const auto C = test::spline(R"({"type": "bspline", "degrees": [1], "knots": [[0, 0, 2, 2]], "points": [["1/10", 0, 0], ["1/10", 0, 2]]})");
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
