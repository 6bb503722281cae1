#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "fixtures/trimming_examples.hpp"
#include "untrim/trimming_polyline.hpp"
#include "spline/kernel.hpp"

using namespace splinex;

// s_u = 1/5 + 3/5 r + 1/5 t(1-t): the level set s_u = 1/2 is r*(t) = (3/10 - t(1-t)/5) / (3/5),
// rational at rational t, with |dr*/dt| <= 1/3, so the horizontal distance bounds the normal
// distance within a factor sqrt(1 + 1/9) < 1.06.
namespace {
// The inner surface of the tolerance studies, rounded to double (its control points are
// 1/5 + 3/5 i (+ 1/10) and 1/10 + 2/5 j).
BSpline<double> level_set_surface() {
  return convert<double>(parabola_trimming_inner(), [](const Rational& x) { return to_double(x); });
}
Rational rstar(const Rational& t) { return (Rational(3, 10) - t * (1 - t) / 5) / Rational(3, 5); }
}  // namespace

TEST_CASE("trimming polylines stay within eps of the exact level set") {
  const BSpline<double> S = level_set_surface();
  // The double control points are not exactly the rational ones (0.2, 0.1 round); the level set
  // of the double surface differs from r* by about 1e-16, far below the tolerances tested.
  for (double eps : {1e-2, 1e-4, 1e-6, 1e-8}) {
    TrimmingTolerance tol;
    tol.eps = eps;
    tol.grid = 8;
    const auto poly = trace_level_set(S, 0, 0.5, tol);
    REQUIRE(!poly.empty());
    const Rational bound = Rational(11, 10) * exact_from_double(eps) + Rational(1, 1000000000000LL);
    for (const auto& seg : poly)
      for (const auto& p : {seg.a, seg.b, Point2<double>{0.5 * (seg.a[0] + seg.b[0]), 0.5 * (seg.a[1] + seg.b[1])}}) {
        const Rational t = exact_from_double(p[1]), r = exact_from_double(p[0]);
        INFO("eps " << eps << " at (" << p[0] << ", " << p[1] << ")");
        CHECK(abs(Rational(r - rstar(t))) <= bound);
      }
    // Every horizontal line crosses the polyline exactly once.
    for (int i = 0; i < 20; ++i) CHECK(crossings_at(poly, (2 * i + 1) / 40.0).size() == 1);
  }
}

TEST_CASE("polyline side agrees with the exact sign away from the curve") {
  const BSpline<double> S = level_set_surface();
  for (double eps : {1e-3, 1e-6}) {
    TrimmingTolerance tol;
    tol.eps = eps;
    tol.grid = 8;
    const auto poly = trace_level_set(S, 0, 0.5, tol);
    int checked = 0, near = 0;
    for (int j = 0; j <= 60; ++j)
      for (int i = 0; i <= 60; ++i) {
        const Point2<double> r{i / 60.0 + 1e-7 * j, j / 60.0};
        if (r[0] > 1) continue;
        const Rational d = exact_from_double(r[0]) - rstar(exact_from_double(r[1]));
        // s_u >= 1/2 exactly when r >= r*(t) (s_u increases with r).
        if (abs(d) <= Rational(2) * exact_from_double(eps)) { ++near; continue; }
        CHECK(polyline_side(S, 0, 0.5, poly, r) == (d >= 0));
        ++checked;
      }
    CHECK(checked > 3000);
    INFO("points within 2 eps of the curve, not checked: " << near);
  }
}
