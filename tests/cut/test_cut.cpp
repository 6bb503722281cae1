// papers/004 (cutting curves): the exact QP and its KKT check, the regularization matrix against an
// independent integral, validation of solids and cutting data, the guiding curve exactly and in
// double, and certified separation (including a guide that must fail).
#include <catch2/catch.hpp>

#include <chrono>

#include "base/errors.hpp"
#include "bernstein/tensor.hpp"
#include "cut/curve_facet.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/qp.hpp"
#include "cut/separation.hpp"
#include "io/cut_io.hpp"
#include "io/json_io.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"

using namespace splinex;

namespace {
Rational q(long a, long b = 1) { return Rational(a, b); }

QuadraticProgram<Rational> small_program() {
  // minimize (x - 1)^2 + (y - 2)^2 = x^2 + y^2 - 2x - 4y + 5 subject to x + y <= 2, x >= -10
  QuadraticProgram<Rational> p;
  p.n = 2;
  p.D = {q(1), q(0), q(0), q(1)};
  p.c = {q(-2), q(-4)};
  p.c0 = q(5);
  p.rows.push_back({{{0, q(1)}, {1, q(1)}}, q(2), false});
  p.rows.push_back({{{0, q(1)}}, q(-10), true});
  return p;
}
}  // namespace

TEST_CASE("cut: the exact QP solver's minimizer, multipliers and KKT check", "[cut]") {
  const auto p = small_program();
  const auto s = solve_qp(p);
  REQUIRE(s.status == QPStatus::optimal);
  // The projection of (1, 2) onto x + y <= 2: (1/2, 3/2), multiplier 1 (gradient (-1, -1) = -1 * (1, 1)).
  CHECK(s.x == std::vector<Rational>{q(1, 2), q(3, 2)});
  CHECK(s.y[0] == q(1));
  CHECK(s.y[1] == q(0));
  CHECK(s.objective == q(1, 2));
  const auto k = check_kkt(p, s);
  CHECK(k.holds);
  CHECK(k.active == 1);
  CHECK(positive_definite(p));
  // A wrong minimizer fails the check, naming the condition.
  auto wrong = s;
  wrong.x[0] = q(1, 3);
  CHECK_FALSE(check_kkt(p, wrong).holds);
  auto wrong2 = s;
  wrong2.y[0] = q(2);
  CHECK(check_kkt(p, wrong2).failed.find("stationarity") != std::string::npos);
  // Infeasible: x >= 1 and x <= 0; the Farkas certificate is checked exactly.
  QuadraticProgram<Rational> inf = p;
  inf.rows = {{{{0, q(1)}}, q(1), true}, {{{0, q(1)}}, q(0), false}};
  const auto si = solve_qp(inf);
  REQUIRE(si.status == QPStatus::infeasible);
  CHECK(check_kkt(inf, si).holds);
  // The same program in double: the rounded data are exact here, so the minimizer is the same.
  QuadraticProgram<double> pd;
  pd.n = 2;
  pd.D = {1, 0, 0, 1};
  pd.c = {-2, -4};
  pd.c0 = 5;
  pd.rows.push_back({{{0, 1.0}, {1, 1.0}}, 2.0, false});
  const auto sd = solve_qp(pd);
  REQUIRE(sd.status == QPStatus::optimal);
  CHECK(sd.x == std::vector<Rational>{q(1, 2), q(3, 2)});
  CHECK(check_kkt(exact_program(pd), sd).holds);
}

TEST_CASE("cut: the regularization matrix equals the integral of the second derivatives", "[cut]") {
  // Independent: each cell's Bernstein form of f, its second derivatives by bern_derivative, their
  // squares' integrals as coefficient means times the cell's area.
  for (const auto& [k, ky] : {std::pair{0, 0}, std::pair{1, 1}, std::pair{3, 3}, std::pair{1, 3}}) {
    const auto U = guide_knots(k), Uy = guide_knots(ky);
    const std::size_t n = U.size() - 4, ny = Uy.size() - 4, N = n * ny;
    const auto M = k == ky ? regularization_matrix(U) : regularization_matrix(U, Uy);
    std::vector<Rational> c(N);
    for (std::size_t i = 0; i < N; ++i) c[i] = Rational(static_cast<long>((i * 7919) % 13) - 6, static_cast<long>(1 + i % 5));
    Rational quad(0);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) quad += c[i] * M[i * N + j] * c[j];
    const auto f = make_spline<Rational>({3, 3}, {U, Uy}, 1, c);
    Rational integral(0);
    for (const auto& piece : extract_bezier(f)) {
      Bernstein<Rational> b{{3, 3}, piece.spline.points};
      const Rational hx = piece.box[0].second - piece.box[0].first, hy = piece.box[1].second - piece.box[1].first;
      auto mean = [](const Bernstein<Rational>& g) {
        Rational s(0);
        for (const auto& v : g.c) s += v;
        return s / Rational(static_cast<long>(g.c.size()));
      };
      auto dxx = bern_derivative(bern_derivative(b, 0), 0);
      auto dyy = bern_derivative(bern_derivative(b, 1), 1);
      auto dxy = bern_derivative(bern_derivative(b, 0), 1);
      // bern_derivative differentiates in the local [0,1] parameter: divide by the cell's sides.
      const Rational sxx = mean(bern_product(dxx, dxx)) / (hx * hx * hx * hx);
      const Rational syy = mean(bern_product(dyy, dyy)) / (hy * hy * hy * hy);
      const Rational sxy = mean(bern_product(dxy, dxy)) / (hx * hx * hy * hy);
      integral += (sxx + 2 * sxy + syy) * hx * hy;
    }
    CHECK(quad == integral);
    // Affine functions (coefficients at the Greville abscissae) have no second derivatives: M c = 0.
    std::vector<Rational> g(n), gy(ny);
    for (std::size_t i = 0; i < n; ++i) g[i] = (U[i + 1] + U[i + 2] + U[i + 3]) / 3;
    for (std::size_t j = 0; j < ny; ++j) gy[j] = (Uy[j + 1] + Uy[j + 2] + Uy[j + 3]) / 3;
    std::vector<Rational> a(N);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < n; ++i) a[i + n * j] = 2 * g[i] - 3 * gy[j] + q(1, 7);
    for (std::size_t i = 0; i < N; ++i) {
      Rational r(0);
      for (std::size_t j = 0; j < N; ++j) r += M[i * N + j] * a[j];
      CHECK(r == 0);
    }
  }
}

TEST_CASE("cut: solids and cutting data are validated with typed errors", "[cut]") {
  auto e = cut_example("square");
  CHECK(signed_area(e.solid) == q(1));
  CHECK(signed_area(cut_example("L").solid) == q(3));
  // The U: two arms [0,1]x[1,3] and [2,3]x[1,3] (area 4) and below y = 1 the outer cubic's cap
  // (y = 1 - 4t(1-t), x = 9t^2 - 6t^3: integral of 4t(1-t) 18t(1-t) dt = 12/5) minus the inner one's
  // (y = 1 - 2t(1-t), x = 2 - 3t^2 + 2t^3: 2/5), by hand.
  CHECK(signed_area(cut_example("U").solid) == q(6));
  // Reversed loop: clockwise.
  auto rev = e.solid;
  std::reverse(rev.facets.begin(), rev.facets.end());
  for (auto& F : rev.facets) {
    std::swap(F.points[0], F.points[2]);
    std::swap(F.points[1], F.points[3]);
  }
  CHECK_THROWS_AS(validate_solid(rev), ValidationError);
  // A gap between facets.
  auto gap = e.solid;
  gap.facets[1].points[0] = q(1, 1) + q(1, 1000);
  CHECK_THROWS_WITH(validate_solid(gap), Catch::Contains("facets[0]"));
  // A tangent pointing out, along the boundary, or zero; a facet index out of range; a cusp-free corner.
  auto out = e.cut;
  out.ends[0].tangent = {q(0), q(-1)};
  CHECK_THROWS_WITH(validate_cut(e.solid, out), Catch::Contains("points[0].tangent"));
  out.ends[0].tangent = {q(1), q(0)};
  CHECK_THROWS_WITH(validate_cut(e.solid, out), Catch::Contains("points[0].tangent"));
  out.ends[0].tangent = {q(0), q(0)};
  CHECK_THROWS_AS(validate_cut(e.solid, out), ValidationError);
  auto far = e.cut;
  far.ends[1].facet = 9;
  CHECK_THROWS_WITH(validate_cut(e.solid, far), Catch::Contains("points[1].facet"));
  // At a convex corner (1, 0) = end of facet 0: inside iff strictly between the two edges.
  auto corner = e.cut;
  corner.ends[0] = {0, q(1), {q(-1), q(1)}};
  const auto v = validate_cut(e.solid, corner);
  CHECK(v.ends[0].facet == 1);
  CHECK(v.ends[0].param == q(0));
  corner.ends[0].tangent = {q(1), q(1)};
  CHECK_THROWS_AS(validate_cut(e.solid, corner), ValidationError);
  // At the L's reflex corner (1, 1): inside over 3/4 of the turn.
  auto L = cut_example("L");
  auto r = L.cut;
  r.ends[0] = {2, q(1), {q(1), q(-1)}};  // end of facet 2 = (1, 1), pointing down-right: inside
  CHECK_NOTHROW(validate_cut(L.solid, r));
  r.ends[0].tangent = {q(1), q(1)};  // into the missing square: outside
  CHECK_THROWS_AS(validate_cut(L.solid, r), ValidationError);
}

TEST_CASE("cut: facets at the edges of the input (degree 0, unclamped, rational, C^-1 knots) get typed errors", "[cut]") {
  const auto square = cut_example("square").solid;  // four segments, counter-clockwise from (0, 0)
  // Degree 0: a constant piece cannot join a loop.
  auto deg0 = square;
  deg0.facets[2] = make_spline<Rational>({0}, {{q(0), q(1)}}, 2, {q(1), q(1)});
  CHECK_THROWS_WITH(validate_solid(deg0), Catch::Contains("facets[2]") && Catch::Contains("degree 0"));
  // Unclamped: a uniform quadratic whose ends are not control points.
  auto open = square;
  open.facets[1] = make_spline<Rational>({2}, {{q(0), q(1), q(2), q(3), q(4), q(5)}}, 2, {q(1), q(0), q(1), q(1, 2), q(1), q(1)});
  CHECK_THROWS_WITH(validate_solid(open), Catch::Contains("facets[1].knots") && Catch::Contains("not clamped"));
  // Rational: refused, not silently read as polynomial.
  auto rat = square;
  rat.facets[3] = make_spline<Rational>({1}, {clamped_knots<Rational>(1, q(0), q(1))}, 2, {q(0), q(1), q(0), q(0)}, {q(1), q(2)});
  CHECK_THROWS_WITH(validate_solid(rat), Catch::Contains("facets[3]") && Catch::Contains("rational"));
  // A facet with a C^-1 knot (multiplicity degree + 1 inside) that jumps: the loop is not continuous
  // there. The facet's ends still join, so only the jump can be refused; validate() of the spline
  // accepts it, so the solid check must. Degree 1: (1,0) -> (1,1/2) | jump | (1,1/2 + 1/10) -> (1,1).
  auto jump = square;
  jump.facets[1] = make_spline<Rational>({1}, {{q(0), q(0), q(1, 2), q(1, 2), q(1), q(1)}}, 2,
                                         {q(1), q(0), q(1), q(1, 2), q(1), q(3, 5), q(1), q(1)});
  CHECK_THROWS_WITH(validate_solid(jump), Catch::Contains("facets[1]") && Catch::Contains("jump"));
  // The same knot without a jump (a C^0 corner inside the facet) is a legal facet.
  auto kink = square;
  kink.facets[1] = make_spline<Rational>({1}, {{q(0), q(0), q(1, 2), q(1, 2), q(1), q(1)}}, 2,
                                         {q(1), q(0), q(1), q(1, 2), q(1), q(1, 2), q(1), q(1)});
  CHECK_NOTHROW(validate_solid(kink));
  CHECK(signed_area(kink) == q(1));
}

TEST_CASE("cut: the guiding curve exactly, certified, and in double judged exactly", "[cut]") {
  for (const std::string name : {"square", "L", "U"}) {
    INFO(name);
    const auto e = cut_example(name);
    GuideOptions o;
    const auto R = guide_curve<Rational>(e.solid, e.cut, o);
    REQUIRE(R.status == QPStatus::optimal);
    CHECK(R.kkt.holds);
    CHECK(R.positive_definite);
    // found in floating point and certified exactly (issue 47 item 12), not by CGAL's exact solver
    CHECK(R.solution.method.rfind("float active set (", 0) == 0);
    CHECK(R.solution.method.find("certified exactly") != std::string::npos);
    CHECK(positive_definite_by_congruence(R.program));
    // The sample constraints hold exactly at the sample points.
    for (std::size_t i = 0; i < R.sample_points.size(); ++i) {
      const Rational v = evaluate(R.f, std::vector<Rational>{R.sample_points[i][0], R.sample_points[i][1]})[0];
      if (i < R.samples_positive) CHECK(v >= o.delta);
      else CHECK(v <= -o.delta);
    }
    const auto sep = certify_separation(R.solid, R.cut, R.f, o.strip);
    CHECK(sep.verdict.is_proved());
    // Double: the same program rounded, solved by the same solver; its minimizer is close to the
    // exact one but not equal (the data are rounded), and its KKT check holds for its own program.
    const auto D = guide_curve<double>(e.solid, e.cut, o);
    REQUIRE(D.status == QPStatus::optimal);
    INFO(D.kkt.failed);
    CHECK(D.kkt.holds);
    REQUIRE(D.coefficients.size() == R.coefficients.size());
    Rational err(0), mag(0);
    for (std::size_t i = 0; i < R.coefficients.size(); ++i) {
      Rational d = ArithTraits<double>::to_rational(D.f.points[i]) - R.coefficients[i];
      if (d < 0) d = -d;
      if (err < d) err = d;
      Rational m = R.coefficients[i] < 0 ? Rational(-R.coefficients[i]) : R.coefficients[i];
      if (mag < m) mag = m;
    }
    CHECK(err < mag * q(1, 1 << 20));
  }
}

TEST_CASE("cut: certified separation finds a guide that leaves the solid between samples", "[cut]") {
  // The square cut at x = 1/2: f = x - 1/2 is certified. Pulling one coefficient near the right edge
  // down makes f negative on a part of the right edge (b): a violation with an exact witness.
  const auto e = cut_example("square");
  GuideOptions o;
  const auto R = guide_curve<Rational>(e.solid, e.cut, o);
  const auto U = guide_knots(3);
  const std::size_t n = U.size() - 4;
  std::vector<Rational> c(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) c[i + n * j] = (U[i + 1] + U[i + 2] + U[i + 3]) / 3 - q(1, 2);
  auto f = make_spline<Rational>({3, 3}, {U, U}, 1, c);
  CHECK(certify_separation(R.solid, R.cut, f, o.strip).verdict.is_proved());
  f.points[(n - 1) + n * 3] = q(-2);
  const auto sep = certify_separation(R.solid, R.cut, f, o.strip);
  REQUIRE(sep.verdict.is_refuted());
  REQUIRE(sep.witness);
  CHECK(sep.witness->positive_side);
  CHECK(sep.witness->point[0] == q(1));  // on the right edge
  CHECK(evaluate(f, std::vector<Rational>{sep.witness->point[0], sep.witness->point[1]})[0] == sep.witness->value);
  CHECK(sep.witness->value <= 0);
}

TEST_CASE("cut: a sample-feasible RDCP solution that leaves the solid is refuted with an exact witness", "[cut]") {
  // The U with one sample per facet (its vertices only): RDCP is feasible and solved exactly (KKT
  // holds), but f* = 0 runs straight down the arms and leaves through the round bottom, where f*
  // must be positive (b: the outer boundary). With two samples per facet the guide is certified.
  const auto e = cut_example("U");
  GuideOptions o;
  o.samples = 1;
  const auto R = guide_curve<Rational>(e.solid, e.cut, o);
  REQUIRE(R.status == QPStatus::optimal);
  CHECK(R.kkt.holds);
  const auto sep = certify_separation(R.solid, R.cut, R.f, o.strip);
  REQUIRE(sep.verdict.is_refuted());
  REQUIRE(sep.witness);
  CHECK(sep.witness->facet == 1);  // the outer bottom
  CHECK(sep.witness->positive_side);
  CHECK(evaluate(R.f, std::vector<Rational>{sep.witness->point[0], sep.witness->point[1]})[0] <= 0);
  o.samples = 2;
  const auto R2 = guide_curve<Rational>(e.solid, e.cut, o);
  REQUIRE(R2.status == QPStatus::optimal);
  CHECK(certify_separation(R2.solid, R2.cut, R2.f, o.strip).verdict.is_proved());
  // The budget of pieces counts every piece of every boundary piece; the one found over it is
  // listed undecided and ends the certificate (no witness, no proof).
  for (std::size_t budget : {std::size_t(1), std::size_t(2)}) {
    SeparationOptions tight;
    tight.max_pieces = budget;
    const auto cut_short = certify_separation(R2.solid, R2.cut, R2.f, o.strip, tight);
    CHECK(cut_short.verdict.is_undecided());
    CHECK_FALSE(cut_short.witness);
    CHECK(cut_short.undecided.size() == 1);
    CHECK(cut_short.pieces + cut_short.excluded <= budget);
    CHECK(cut_short.verdict.reason().rfind("1 boundary piece(s) left undecided at the subdivision budget", 0) == 0);
  }
}

TEST_CASE("cut: the cutting curve fitted to the guide, certified valid, and the solid split exactly", "[cut]") {
  for (const std::string name : {"square", "L", "U"}) {
    INFO(name);
    const auto e = cut_example(name);
    const auto R = guide_curve<Rational>(e.solid, e.cut, GuideOptions{});
    REQUIRE(R.status == QPStatus::optimal);
    const auto cc = fit_cutting_curve(R.solid, R.cut, R.f);
    CHECK(cc.fit_max_deviation < 0.05);
    const auto v = certify_cutting_curve(R.solid, R.cut, cc.curve);
    CHECK(v.interpolates);
    CHECK(v.tangents);
    CHECK(v.regular.is_proved());
    CHECK(v.injective.is_proved());
    CHECK(v.inside.is_proved());
    CHECK(v.verdict.is_proved());
    const auto [S1, S2] = split_solid(R.solid, R.cut, cc.curve);
    CHECK(signed_area(S1) > 0);
    CHECK(signed_area(S2) > 0);
    CHECK(signed_area(S1) + signed_area(S2) == signed_area(R.solid));
  }
}

TEST_CASE("cut: an invalid cutting curve is refuted at an exact point outside the solid", "[cut]") {
  // The U's two arm tops joined by the cubic p, p + (0,-1), q + (0,-1), q: it has the right ends and
  // tangents but dips only to y = 9/4 between the arms, through the slot: C(1/2) = (3/2, 9/4) lies
  // outside the U.
  const auto e = cut_example("U");
  const auto C = make_spline<Rational>({3}, {clamped_knots<Rational>(3, q(0), q(1))}, 2,
                                       {q(1, 2), q(3), q(1, 2), q(2), q(5, 2), q(2), q(5, 2), q(3)});
  const auto cut = validate_cut(e.solid, e.cut);
  const auto v = certify_cutting_curve(e.solid, cut, C);
  CHECK(v.interpolates);
  CHECK(v.tangents);
  CHECK(v.regular.is_proved());
  CHECK(v.injective.is_proved());
  REQUIRE(v.inside.is_refuted());
  CHECK(v.verdict.is_refuted());
  REQUIRE(v.witness);
  CHECK(classify_point(e.solid, *v.witness) == -1);
  // Ray casting itself: inside, outside, on the boundary.
  CHECK(classify_point(e.solid, {q(1, 2), q(2)}) == 1);
  CHECK(classify_point(e.solid, {q(3, 2), q(2)}) == -1);
  CHECK(classify_point(e.solid, {q(3, 2), q(1, 4)}) == 1);   // between the two bottoms (0 and 1/2 at x = 3/2)
  CHECK(classify_point(e.solid, {q(3, 2), q(3, 4)}) == -1);  // above the inner bottom
  CHECK(classify_point(e.solid, {q(3, 2), q(-1, 8)}) == -1);
  // A self-intersecting loop is not certified injective; a curve with a cusp is refuted as irregular.
  const auto loop = make_spline<Rational>({3}, {clamped_knots<Rational>(3, q(0), q(1))}, 2, {q(0), q(0), q(2), q(1), q(2), q(-1), q(0), q(1)});
  const auto vl = certify_cutting_curve(e.solid, cut, loop);
  CHECK(vl.injective.is_undecided());
  const auto cusp = make_spline<Rational>({3}, {clamped_knots<Rational>(3, q(0), q(1))}, 2, {q(0), q(0), q(1), q(1), q(0), q(1), q(1), q(0)});
  const auto vc = certify_cutting_curve(e.solid, cut, cusp);
  CHECK(vc.regular.is_refuted());
  CHECK(vc.singular_s == q(1, 2));
}

namespace {
// A solid from Bezier facets given by their control points (degree = points - 1, domain [0, 1]).
Solid2<Rational> bezier_solid(const std::vector<std::vector<std::array<Rational, 2>>>& facets) {
  Solid2<Rational> S;
  for (const auto& f : facets) {
    const int p = static_cast<int>(f.size()) - 1;
    std::vector<Rational> pts;
    for (const auto& x : f) pts.push_back(x[0]), pts.push_back(x[1]);
    S.facets.push_back(make_spline<Rational>({p}, {clamped_knots<Rational>(p, q(0), q(1))}, 2, pts));
  }
  return S;
}
Solid2<Rational> polygon_solid(const std::vector<std::array<Rational, 2>>& v) {
  std::vector<std::vector<std::array<Rational, 2>>> f;
  for (std::size_t i = 0; i < v.size(); ++i) f.push_back({v[i], v[(i + 1) % v.size()]});
  return bezier_solid(f);
}
// Rational points on the unit circle, counter-clockwise: ((1 - u^2), 2u) / (1 + u^2) for u = k/m,
// |k| <= 4m (the angle 2 atan(u) within about 0.84 pi of 0).
std::vector<std::array<Rational, 2>> circle_points(long m) {
  std::vector<std::array<Rational, 2>> v;
  for (long k = -4 * m; k <= 4 * m; ++k) {
    const Rational u(k, m), d = 1 + u * u;
    v.push_back({Rational((1 - u * u) / d), Rational(2 * u / d)});
  }
  return v;
}
}  // namespace

TEST_CASE("cut: facet loops are checked exactly: self-intersections, figure eights and zero-length facets are typed errors", "[cut]") {
  using P = std::array<Rational, 2>;
  CHECK_NOTHROW(check_simple_loop(cut_example("square").solid));
  for (const auto& name : cut_example_names()) {
    INFO(name);
    CHECK_NOTHROW(validate_solid(cut_example(name).solid));
  }
  // Collinear neighbours (a straight continuation) and a loop of two facets are simple.
  CHECK_NOTHROW(validate_solid(polygon_solid({P{q(0), q(0)}, P{q(1), q(0)}, P{q(2), q(0)}, P{q(2), q(2)}, P{q(0), q(2)}, P{q(0), q(1)}})));
  CHECK_NOTHROW(validate_solid(bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(2), q(4)}, P{q(0), q(0)}}})));
  CHECK_THROWS_WITH(check_simple_loop(bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(0), q(0)}}})), Catch::Contains("turns back along"));
  // The figure eight of positive signed area (4): straight facets 0 and 2 cross at (8/3, 1), exactly.
  const auto eight = polygon_solid({P{q(0), q(-1)}, P{q(4), q(2)}, P{q(4), q(0)}, P{q(0), q(3)}});
  CHECK(signed_area(eight) == q(4));
  CHECK_THROWS_WITH(validate_solid(eight), Catch::Contains("facets[0]: meets facets[2] at (8/3, 1)") && Catch::Contains("not simple"));
  // A vertex on a facet that is not its neighbour (area 4 > 0): a pinch, exactly.
  const auto pinch = polygon_solid({P{q(0), q(0)}, P{q(4), q(0)}, P{q(4), q(2)}, P{q(2), q(0)}, P{q(0), q(2)}});
  CHECK(signed_area(pinch) > 0);
  CHECK_THROWS_WITH(validate_solid(pinch), Catch::Contains("facets[0]: meets facets[") && Catch::Contains("] at (2, 0)"));
  // A facet turning back along its predecessor (area 4 > 0).
  const auto back = polygon_solid({P{q(0), q(0)}, P{q(4), q(0)}, P{q(2), q(0)}, P{q(2), q(2)}, P{q(0), q(2)}});
  CHECK_THROWS_WITH(validate_solid(back), Catch::Contains("facets[0]: turns back along facets[1] at (4, 0)"));
  // A quadratic top facet dipping below the bottom (crossings at x = 4/3 and 8/3, parameters 1/3 and
  // 2/3: never a subdivision point): proved crossing by the intermediate value theorem. Area 4 > 0.
  const auto dip = bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(4), q(4)}}, {P{q(4), q(4)}, P{q(2), q(-5)}, P{q(0), q(4)}},
                                 {P{q(0), q(4)}, P{q(0), q(0)}}});
  CHECK(signed_area(dip) == q(4));
  CHECK_THROWS_WITH(validate_solid(dip), Catch::Contains("facets[0]: crosses facets[2] within [") && Catch::Contains("not simple"));
  // A cubic facet with a loop of its own (it crosses itself at parameters (7 -+ sqrt 21) / 14).
  const auto curl = bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(-2), q(6)}, P{q(6), q(6)}, P{q(0), q(0)}}});
  CHECK_THROWS_WITH(validate_solid(curl), Catch::Contains("facets[1]: crosses itself within ["));
  // Touching tangentially at a point no halving reaches (the top quadratic touches y = 0 at t = 2/5):
  // no exact decision; refused as not certified simple, naming the facets.
  const auto kiss = bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(4), q(4)}}, {P{q(4), q(4)}, P{q(2), q(-6)}, P{q(0), q(9)}},
                                  {P{q(0), q(9)}, P{q(0), q(0)}}});
  CHECK_THROWS_WITH(validate_solid(kiss), Catch::Contains("facets[0]: could not be proved apart from facets[2]") && Catch::Contains("not certified simple"));
  // The same quadratic lifted by 1/1000 is decided: apart.
  const Rational up(1, 1000);
  const auto lifted = bezier_solid({{P{q(0), q(0)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(4), q(4) + up}}, {P{q(4), q(4) + up}, P{q(2), q(-6) + up}, P{q(0), q(9) + up}},
                                    {P{q(0), q(9) + up}, P{q(0), q(0)}}});
  CHECK_NOTHROW(validate_solid(lifted));
  // A facet that is a single point, and a facet with a zero-length piece inside (C^-1 knots).
  auto point = cut_example("L").solid;
  point.facets.push_back(make_spline<Rational>({1}, {clamped_knots<Rational>(1, q(0), q(1))}, 2, {q(0), q(0), q(0), q(0)}));
  CHECK_THROWS_WITH(validate_solid(point), Catch::Contains("facets[6]: is a single point (0, 0)"));
  auto stall = cut_example("square").solid;
  stall.facets[1] = make_spline<Rational>({1}, {{q(0), q(0), q(1, 3), q(1, 3), q(2, 3), q(2, 3), q(1), q(1)}}, 2,
                                          {q(1), q(0), q(1), q(1, 2), q(1), q(1, 2), q(1), q(1, 2), q(1), q(1, 2), q(1), q(1)});
  CHECK_THROWS_WITH(validate_solid(stall), Catch::Contains("facets[1]: has a piece of zero length on parameters [1/3, 2/3]"));
}

TEST_CASE("cut: the loop check is near-linear: thousands of straight and curved facets", "[cut]") {
  using P = std::array<Rational, 2>;
  // 4001 exact points on the circle as a polygon; then the same arcs as quadratics (control point:
  // the tangents' intersection, rational), 1001 of them.
  const auto t0 = std::chrono::steady_clock::now();
  const auto v = circle_points(500);
  CHECK_NOTHROW(validate_solid(polygon_solid(v)));
  const auto w = circle_points(125);
  std::vector<std::vector<P>> arcs;
  for (std::size_t i = 0; i + 1 < w.size(); ++i) {
    // tangent lines at a and b: x . a = 1, x . b = 1 (unit circle): intersection by Cramer
    const P& a = w[i];
    const P& b = w[i + 1];
    const Rational det = a[0] * b[1] - a[1] * b[0];
    arcs.push_back({a, P{Rational((b[1] - a[1]) / det), Rational((a[0] - b[0]) / det)}, b});
  }
  arcs.push_back({w.back(), w.front()});
  CHECK_NOTHROW(validate_solid(bezier_solid(arcs)));
  // A zigzag of 4000 long edges whose boxes all overlap in x (a sweep in x alone would be quadratic).
  std::vector<P> z;
  for (long i = 0; i < 2000; ++i) z.push_back({q(0), q(i)}), z.push_back({q(1000), Rational(i) + q(1, 2)});
  z.push_back({q(1001), q(2000)}), z.push_back({q(-1), q(2000)});
  CHECK_NOTHROW(validate_solid(polygon_solid(z)));
  // One vertex pushed across the far side: a crossing found among thousands of pieces.
  auto bad = v;
  bad[2000] = P{q(-2), q(0)};
  CHECK_THROWS_WITH(validate_solid(polygon_solid(bad)), Catch::Contains("not simple"));
  // No timed assertion (house rule): a quadratic check shows as this case's time in ctest's log
  // (and its timeout), printed here for the reader.
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  WARN("loop checks of 1001 + 125 arcs + 4002 + 1001 pieces: " << seconds << " s");
}

TEST_CASE("cut: a forged KKT point with a negative multiplier is refused, and no rows is never proved", "[cut]") {
  // minimize x^2 - x subject to x >= 0: the minimizer is 1/2 (row inactive, multiplier 0). The forged
  // candidate x = 0 with multiplier -1 is feasible, complementary (the row is active) and stationary
  // (2x - 1 = -1 = y), so only the sign of the multiplier refutes it.
  QuadraticProgram<Rational> p;
  p.n = 1;
  p.D = {q(1)};
  p.c = {q(-1)};
  p.rows.push_back({{{0, q(1)}}, q(0), true});
  const auto s = solve_qp(p);
  REQUIRE(s.status == QPStatus::optimal);
  CHECK(s.x[0] == q(1, 2));
  CHECK(check_kkt(p, s).holds);
  CHECK(guide_verdict(true, p, check_kkt(p, s), positive_definite(p)).rfind("proved: ", 0) == 0);
  QPSolution forged;
  forged.status = QPStatus::optimal;
  forged.x = {q(0)};
  forged.y = {q(-1)};
  const auto k = check_kkt(p, forged);
  CHECK_FALSE(k.holds);
  CHECK(k.failed.find("negative") != std::string::npos);
  CHECK(guide_verdict(true, p, k, positive_definite(p)).rfind("not proved: ", 0) == 0);
  // Not positive definite: never "proved", and the reason is said.
  auto semi = p;
  semi.D = {q(0)};
  semi.c = {q(1)};
  QPSolution at0{QPStatus::optimal, {q(0)}, {q(1)}, q(0), "by hand"};
  REQUIRE(check_kkt(semi, at0).holds);
  CHECK(guide_verdict(true, semi, check_kkt(semi, at0), positive_definite(semi)) ==
        "not proved: the objective's matrix is not positive definite (the minimizer need not be unique)");
  // No constraint rows: the unconstrained minimizer is exact, but nothing was checked against b*
  // and b-bar*: undecided, in either arithmetic.
  auto none = p;
  none.rows.clear();
  const auto sn = solve_qp(none);
  REQUIRE(check_kkt(none, sn).holds);
  CHECK(guide_verdict(true, none, check_kkt(none, sn), true).rfind("undecided: the program has no constraint rows", 0) == 0);
  CHECK(guide_verdict(false, none, check_kkt(none, sn), true).rfind("undecided: ", 0) == 0);
}

TEST_CASE("cut: a strip over the whole boundary leaves RDCP without rows and the separation undecided", "[cut]") {
  const auto e = cut_example("L");
  GuideOptions o;
  o.strip = q(10);
  const auto R = guide_curve<Rational>(e.solid, e.cut, o);
  REQUIRE(R.status == QPStatus::optimal);
  CHECK(R.program.rows.empty());
  CHECK(R.samples_positive + R.samples_negative == 0);
  CHECK(guide_verdict(true, R.program, R.kkt, R.positive_definite).rfind("undecided: ", 0) == 0);
  const auto sep = certify_separation(R.solid, R.cut, R.f_exact, o.strip);
  CHECK(sep.pieces == 0);
  CHECK(sep.excluded > 0);
  CHECK(sep.verdict.is_undecided());
  CHECK(sep.verdict.reason().find("nothing was checked") != std::string::npos);
  // With the default strip the same guide's check certifies pieces.
  const auto R2 = guide_curve<Rational>(e.solid, e.cut, GuideOptions{});
  const auto sep2 = certify_separation(R2.solid, R2.cut, R2.f_exact, GuideOptions{}.strip);
  CHECK(sep2.verdict.is_proved());
  CHECK(sep2.pieces > 0);
}

TEST_CASE("cut: the exact guide of the long-number reproducer is certified from the float solve (repro/cut 1)", "[cut]") {
  // star5_d2 (tests/data/repro/cut): 5 quadratic facets with 6- to 11-digit denominators. CGAL's
  // exact solver took 131 s on its program (49 variables, 72 rows); the float active set (one row)
  // certified exactly gives the same verdict. The double run's rounded program has another
  // minimizer, close to this one.
  const std::string file = __FILE__;
  const std::string dir = file.substr(0, file.rfind('/')) + "/../data/repro/cut/";
  const auto S = solid2_from_json(read_json_file(dir + "star5_d2.solid.json"));
  const auto C = cut2_from_json(read_json_file(dir + "star5_d2.cut.json"));
  const GuideOptions o;
  const auto R = guide_curve<Rational>(S, C, o);
  REQUIRE(R.status == QPStatus::optimal);
  INFO(R.solution.method);
  CHECK(R.solution.method == "float active set (1 active rows), certified exactly");
  CHECK(R.program.n == 49);
  CHECK(R.program.rows.size() == 72);
  CHECK(guide_verdict(true, R.program, R.kkt, R.positive_definite) ==
        "proved: the unique minimizer of RDCP (KKT conditions exact, objective positive definite)");
  CHECK(certify_separation(R.solid, R.cut, R.f_exact, o.strip).verdict.is_proved());
  const auto D = guide_curve<double>(S, C, o);
  REQUIRE(D.status == QPStatus::optimal);
  CHECK(D.solution.method == "exact solver on the rounded program (CGAL, Gmpzf)");
  const auto err = coefficient_error(R.coefficients, D.f_exact.points);
  CHECK(err.max_abs_error > 0);
  CHECK(err.max_abs_error < err.max_abs * Rational(1, 1 << 20));
}
