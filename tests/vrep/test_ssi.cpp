// The float surface-surface intersection and its exact judge (vrep/boolean/ssi.hpp): a plane and a
// paraboloid meeting in the circle u^2 + v^2 = 1/4 (the oracle), certificates that must bound the
// true distance, and refusals where nothing can be certified.
#include <catch2/catch.hpp>

#include <cmath>

#include "exact/rational.hpp"
#include "float/rounding.hpp"
#include "spline/kernel.hpp"
#include "vrep/boolean/ssi.hpp"

using namespace splinex;
using R = Rational;

namespace {

// z = 0 over [-1, 1]^2 (bilinear).
BSpline<R> plane(const R& z) {
  return make_spline<R>({1, 1}, {{R(-1), R(-1), R(1), R(1)}, {R(-1), R(-1), R(1), R(1)}}, 3,
                        {R(-1), R(-1), z, R(1), R(-1), z, R(-1), R(1), z, R(1), R(1), z});
}

// (s, t, s^2 + t^2 - c) over [-1, 1]^2, biquadratic: s^2 has the Bernstein coefficients 1, -1, 1.
BSpline<R> paraboloid(const R& c) {
  const R x[3] = {R(-1), R(0), R(1)}, b[3] = {R(1), R(-1), R(1)};
  std::vector<R> pts;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      pts.push_back(x[i]);
      pts.push_back(x[j]);
      pts.push_back(b[i] + b[j] - c);
    }
  return make_spline<R>({2, 2}, {{R(-1), R(-1), R(-1), R(1), R(1), R(1)}, {R(-1), R(-1), R(-1), R(1), R(1), R(1)}}, 3, pts);
}

}  // namespace

TEST_CASE("vrep ssi: a plane and a paraboloid meet in a circle, every point certified near it") {
  const auto P = plane(R(0)), Q = paraboloid(R(1, 4));
  SsiOptions o;
  o.step = 1.0 / 16;
  o.grid = 16;
  const auto r = intersect_surfaces(round_spline<double>(P), round_spline<double>(Q), o);
  REQUIRE(r.branches.size() == 1);
  CHECK(r.branches[0].closed);
  const auto& pts = r.branches[0].points;
  CHECK(pts.size() > 40);  // circumference pi at chord 1/16: about 50
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& x = pts[i];
    const auto& y = pts[(i + 1) % pts.size()];
    // The oracle: the circle of radius 1/2 (in both parameter planes, which are the x, y plane).
    CHECK(std::abs(std::hypot(x[0], x[1]) - 0.5) < 1e-11);
    CHECK(std::abs(x[0] - x[2]) < 1e-11);
    SsiParams dir, mid;
    for (int k = 0; k < 4; ++k) {
      dir[k] = y[k] - x[k];
      mid[k] = (x[k] + y[k]) / 2;
    }
    const auto j = judge_point(P, Q, x, dir);
    REQUIRE(j.certified);
    CHECK(j.gap2 < R(1, 1000000) * R(1, 1000000) * R(1, 1000000));  // |S1 - S2| < 1e-9 ... Newton's 1e-12
    CHECK(j.distance2_bound < R(1, 1000000000));
    // A chord's midpoint lies inside the circle: its distance to it, 1/2 - |m|, must not exceed
    // the certified bound (the bound is on the distance to one true point, at least the distance
    // to the curve).
    const auto m = judge_point(P, Q, mid, dir);
    REQUIRE(m.certified);
    const double to_circle = 0.5 - std::hypot(mid[0], mid[1]);
    CHECK(to_circle > 0);
    CHECK(to_double(m.distance2_bound) >= to_circle * to_circle * (1 - 1e-9));
    CHECK(to_double(m.distance2_bound) < 1e-5);  // chord 1/16 on radius 1/2: the sagitta 1e-3
  }
}

TEST_CASE("vrep ssi: loops only a few steps round close once, without running on") {
  // Circles of radius 1/15, 1/20, 1/30 at step 1/16 (circumference 6.7, 5 and 3.4 steps): one
  // closed branch each, every vertex on the circle (a runaway marching went round 200000 points).
  const auto P = plane(R(0));
  for (const R& r : {R(1, 15), R(1, 20), R(1, 30)}) {
    SsiOptions o;
    o.grid = 16;
    const auto res = intersect_surfaces(round_spline<double>(P), round_spline<double>(paraboloid(r * r)), o);
    INFO(to_double(r));
    REQUIRE(res.branches.size() == 1);
    CHECK(res.branches[0].closed);
    CHECK(res.branches[0].points.size() >= 3);
    CHECK(res.branches[0].points.size() <= 16);
    for (const auto& x : res.branches[0].points) CHECK(std::abs(std::hypot(x[0], x[1]) - to_double(r)) < 1e-11);
  }
}

TEST_CASE("vrep ssi: a branch that ends on the boundary, its end points certified on the boundary line") {
  // The plane over [0, 1] x [-1, 1] holds half of the circle: one open branch from (0, -1/2) to (0, 1/2).
  const auto P = make_spline<R>({1, 1}, {{R(0), R(0), R(1), R(1)}, {R(-1), R(-1), R(1), R(1)}}, 3,
                                {R(0), R(-1), R(0), R(1), R(-1), R(0), R(0), R(1), R(0), R(1), R(1), R(0)});
  const auto Q = paraboloid(R(1, 4));
  SsiOptions o;
  o.grid = 16;
  const auto r = intersect_surfaces(round_spline<double>(P), round_spline<double>(Q), o);
  REQUIRE(r.branches.size() == 1);
  const auto& pts = r.branches[0].points;
  CHECK_FALSE(r.branches[0].closed);
  REQUIRE(pts.size() > 10);
  for (const auto* e : {&pts.front(), &pts.back()}) {
    CHECK((*e)[0] == 0.0);  // on the boundary u = 0, exactly
    CHECK(std::abs(std::abs((*e)[1]) - 0.5) < 1e-11);
    const auto j = judge_point(P, Q, *e, {0, 1, 0, 1});
    INFO(j.why_not);
    CHECK(j.certified);
    CHECK(j.distance2_bound < R(1, 1000000000));
  }
}

TEST_CASE("vrep ssi: no intersection, no certificate where there is nothing to certify, hostile input") {
  SsiOptions o;
  o.grid = 8;
  CHECK(intersect_surfaces(round_spline<double>(plane(R(0))), round_spline<double>(plane(R(1))), o).branches.empty());
  // A point far from the circle: Krawczyk cannot prove a root near it.
  const auto P = plane(R(0)), Q = paraboloid(R(1, 4));
  auto far = judge_point(P, Q, {0.9, 0.9, 0.9, 0.9}, {1, 0, 1, 0});
  CHECK_FALSE(far.certified);
  const R d = exact_from_double(0.9), z = 2 * d * d - R(1, 4);  // the paraboloid's height at the double 0.9
  CHECK(far.gap2 == z * z);
  // Tangential contact (the paraboloid touching the plane at the origin): F' is singular there.
  const auto T = paraboloid(R(0));
  const auto t = judge_point(P, T, {0, 0, 0, 0}, {1, 0, 1, 0});
  CHECK_FALSE(t.certified);
  CHECK(t.gap2 == 0);
  CHECK_FALSE(t.why_not.empty());
  // A point on the boundary far from the curve is not certified either.
  const auto b = judge_point(P, Q, {-1, 0, -1, 0}, {0, 1, 0, 1});
  CHECK_FALSE(b.certified);
  // Not surfaces, outside the domains, bad options.
  const auto curve = make_spline<R>({1}, {{R(0), R(0), R(1), R(1)}}, 3, {R(0), R(0), R(0), R(1), R(1), R(1)});
  CHECK_THROWS_AS(judge_point(curve, Q, {0, 0, 0, 0}, {1, 0, 0, 0}), ValidationError);
  CHECK_THROWS_AS(judge_point(P, Q, {2, 0, 0, 0}, {1, 0, 0, 0}), ValidationError);
  o.step = 0;
  CHECK_THROWS_AS(intersect_surfaces(round_spline<double>(P), round_spline<double>(Q), o), ValidationError);
}
