// Planted bugs for cutting's certificates (issue 47): each certificate is handed an input that is
// wrong in exactly one way, by a rational epsilon where that makes sense, and must refuse it; the
// same certificate on the correct input holds, so none of these tests can pass by refusing
// everything. The certificates: the QP proof (check_kkt and positive_definite, behind the "proved"
// verdict), the float-then-exact active-set certificate of solve_qp (a wrong active set is
// rejected and solve_qp falls back to CGAL's exact solver: qp_testing::ScopedPlantedActiveSet is
// the one test seam, since solve_qp's float phase cannot be handed a set directly), certified
// separation (a guide crossing the boundary between the samples), and the validity of the facet
// loop (check_simple_loop: figure eights).
#include <catch2/catch.hpp>

#include <cmath>

#include "base/errors.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/qp.hpp"
#include "cut/separation.hpp"
#include "cut/solid.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/knots.hpp"

using namespace splinex;

namespace {

Rational q(long a, long b = 1) { return Rational(a, b); }

// "1 ulp": a rational epsilon at double's last bit for numbers near 1.
const Rational eps = Rational(1) / Rational(Integer(1) << 53);

QuadraticProgram<Rational> program(std::size_t n, std::vector<Rational> D, std::vector<Rational> c) {
  QuadraticProgram<Rational> p;
  p.n = n;
  p.D = std::move(D);
  p.c = std::move(c);
  return p;
}

QPSolution point(std::vector<Rational> x, std::vector<Rational> y) {
  QPSolution s;
  s.status = QPStatus::optimal;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

bool proved(const QuadraticProgram<Rational>& p, const KKTCheck& k) { return guide_verdict(true, p, k, positive_definite(p)).rfind("proved: ", 0) == 0; }

// minimize (x - 1)^2 + (y - 2)^2 subject to x + y <= 2 (row 0), x >= -10 (row 1): minimizer
// (1/2, 3/2), multipliers (1, 0).
QuadraticProgram<Rational> projection_program() {
  auto p = program(2, {q(1), q(0), q(0), q(1)}, {q(-2), q(-4)});
  p.c0 = q(5);
  p.rows.push_back({{{0, q(1)}, {1, q(1)}}, q(2), false});
  p.rows.push_back({{{0, q(1)}}, q(-10), true});
  return p;
}

// The L example's exact RDCP (49 variables, 86 rows, one active row), solved once.
const GuideResult<Rational>& l_guide() {
  static const auto R = guide_curve<Rational>(cut_example("L").solid, cut_example("L").cut, GuideOptions{});
  return R;
}

Rational slack(const QuadraticProgram<Rational>::Row& row, const std::vector<Rational>& x) {
  Rational ax(0);
  for (const auto& [i, v] : row.a) ax += v * x[i];
  return row.at_least ? Rational(ax - row.b) : Rational(row.b - ax);
}

}  // namespace

TEST_CASE("cut planted: the QP proof refuses a point wrong in exactly one KKT condition", "[cut][planted]") {
  SECTION("a negative multiplier (the forged minimizer of x^2 - x at x = 0, y = -1)") {
    auto p = program(1, {q(1)}, {q(-1)});
    p.rows.push_back({{{0, q(1)}}, q(0), true});
    CHECK(check_kkt(p, point({q(1, 2)}, {q(0)})).holds);
    const auto k = check_kkt(p, point({q(0)}, {q(-1)}));
    CHECK_FALSE(k.holds);
    CHECK(k.failed == "multiplier of row 0 is negative");
    CHECK_FALSE(proved(p, k));
  }
  SECTION("primal infeasible by eps: minimize x^2 subject to x >= eps, forged x = 0, y = 0") {
    // stationary (2x = 0 = y), y >= 0, complementary (y = 0): only the row fails, by eps
    auto p = program(1, {q(1)}, {q(0)});
    p.rows.push_back({{{0, q(1)}}, eps, true});
    CHECK(check_kkt(p, point({eps}, {2 * eps})).holds);
    const auto k = check_kkt(p, point({q(0)}, {q(0)}));
    CHECK(k.failed == "row 0 is violated");
    CHECK_FALSE(proved(p, k));
  }
  SECTION("complementary slackness: minimize x^2 - x subject to x >= 0, x <= 1, forged x = 1, y = (1, 0)") {
    // feasible, y >= 0, stationary (2x - 1 = 1 = y0 - y1), but y0 > 0 on the inactive row 0
    auto p = program(1, {q(1)}, {q(-1)});
    p.rows.push_back({{{0, q(1)}}, q(0), true});
    p.rows.push_back({{{0, q(1)}}, q(1), false});
    CHECK(check_kkt(p, point({q(1, 2)}, {q(0), q(0)})).holds);
    const auto k = check_kkt(p, point({q(1)}, {q(1), q(0)}));
    CHECK(k.failed == "complementary slackness fails in row 0");
    CHECK_FALSE(proved(p, k));
  }
  SECTION("stationarity off by eps: the projection program's multiplier 1 + eps") {
    const auto p = projection_program();
    CHECK(check_kkt(p, point({q(1, 2), q(3, 2)}, {q(1), q(0)})).holds);
    const auto k = check_kkt(p, point({q(1, 2), q(3, 2)}, {q(1) + eps, q(0)}));
    CHECK(k.failed == "stationarity fails in variable 0");
    CHECK_FALSE(proved(p, k));
  }
  SECTION("the same four flaws planted in a real RDCP minimizer (the L, 49 variables)") {
    const auto& R = l_guide();
    REQUIRE(R.status == QPStatus::optimal);
    REQUIRE(proved(R.program, R.kkt));
    const auto& p = R.program;
    const auto& s = R.solution;
    std::size_t active = p.rows.size(), inactive = p.rows.size();
    for (std::size_t r = 0; r < p.rows.size(); ++r) {
      if (s.y[r] > 0 && active == p.rows.size()) active = r;
      if (slack(p.rows[r], s.x) > 0 && inactive == p.rows.size()) inactive = r;
    }
    REQUIRE(active < p.rows.size());
    REQUIRE(inactive < p.rows.size());
    {  // an inactive row moved to eps beyond the minimizer: only feasibility fails
      auto bad = p;
      auto& row = bad.rows[inactive];
      row.b = row.at_least ? Rational(row.b + slack(row, s.x) + eps) : Rational(row.b - slack(row, s.x) - eps);
      const auto k = check_kkt(bad, s);
      CHECK(k.failed == "row " + std::to_string(inactive) + " is violated");
      CHECK_FALSE(proved(bad, k));
    }
    {  // the active row's multiplier + eps: only stationarity fails
      auto bad = s;
      bad.y[active] += eps;
      const auto k = check_kkt(p, bad);
      CHECK(k.failed.rfind("stationarity fails", 0) == 0);
      CHECK_FALSE(proved(p, k));
    }
    {  // multiplier eps on an inactive row: complementary slackness (checked before stationarity)
      auto bad = s;
      bad.y[inactive] = eps;
      CHECK(check_kkt(p, bad).failed == "complementary slackness fails in row " + std::to_string(inactive));
    }
    {  // the active row's multiplier negated
      auto bad = s;
      bad.y[active] = -bad.y[active];
      CHECK(check_kkt(p, bad).failed == "multiplier of row " + std::to_string(active) + " is negative");
    }
    {  // one coefficient moved by eps: some condition fails
      auto bad = s;
      bad.x[R.program.n / 2] += eps;
      CHECK_FALSE(check_kkt(p, bad).holds);
    }
  }
}

TEST_CASE("cut planted: positive definiteness is refused for a matrix indefinite by eps", "[cut][planted]") {
  // [[1, 1], [1, 1 + t]]: positive definite for t > 0, singular at 0, indefinite for t < 0. Neither
  // certificate accepts 0 or -eps (a tolerance anywhere would); +eps is proved by elimination (in
  // double the matrix is singular, so the congruence certificate proves nothing there).
  for (const Rational& t : {eps, Rational(0), Rational(-eps)}) {
    INFO(to_fraction_string(t));
    const auto p = program(2, {q(1), q(1), q(1), q(1) + t}, {q(0), q(0)});
    CHECK(positive_definite_by_elimination(p) == (t > 0));
    CHECK(positive_definite(p) == (t > 0));
    if (t <= 0) CHECK_FALSE(positive_definite_by_congruence(p));
  }
  // Two matrices with the same doubles [[1, 1], [1, 1 + 2^-52]] (positive definite in double, the
  // double Cholesky succeeds): [[1, 1 + w], [1 + w, 1 + u]], u = 2^-53 + 2^-60, det = u - 2w - w^2.
  // w = 2^-56: positive definite; w = u/2: det = -w^2 < 0, indefinite. The congruence certificate
  // starts from the same float factor for both and must tell them apart exactly.
  const Rational u = Rational(1) / Rational(Integer(1) << 53) + Rational(1) / Rational(Integer(1) << 60);
  for (const Rational& w : {Rational(1) / Rational(Integer(1) << 56), Rational(u / 2)}) {
    const auto p = program(2, {q(1), q(1) + w, q(1) + w, q(1) + u}, {q(0), q(0)});
    const bool pd = u - 2 * w - w * w > 0;
    INFO(to_fraction_string(w));
    CHECK(to_double(q(1) + w) == 1.0);
    CHECK(to_double(q(1) + u) == 1.0 + std::ldexp(1.0, -52));
    CHECK(positive_definite_by_congruence(p) == pd);
    CHECK(positive_definite_by_elimination(p) == pd);
    CHECK(positive_definite(p) == pd);
  }
  // Positive diagonal, negative eigenvalue (-1): a KKT point (the origin) but never "proved".
  const auto p = program(2, {q(1), q(2), q(2), q(1)}, {q(0), q(0)});
  const auto origin = point({q(0), q(0)}, {});
  REQUIRE(check_kkt(p, origin).holds);
  CHECK_FALSE(positive_definite(p));
  CHECK(guide_verdict(true, p, check_kkt(p, origin), positive_definite(p)) ==
        "not proved: the objective's matrix is not positive definite (the minimizer need not be unique)");
  // Not symmetric: the congruence certificate proves nothing.
  CHECK_FALSE(positive_definite_by_congruence(program(2, {q(2), q(1), q(0), q(2)}, {q(0), q(0)})));
  // A real RDCP matrix: both certificates prove it.
  CHECK(positive_definite_by_congruence(l_guide().program));
  CHECK(positive_definite_by_elimination(l_guide().program));
}

TEST_CASE("cut planted: a wrong active set is rejected, and solve_qp falls back to the exact solver", "[cut][planted]") {
  const auto p = projection_program();
  // The right set (row 0) is certified; the multipliers are the exact ones.
  const auto good = certify_active_set(p, {0}, 0);
  REQUIRE(good.certified);
  CHECK(good.solution.x == std::vector<Rational>{q(1, 2), q(3, 2)});
  CHECK(good.solution.y == std::vector<Rational>{q(1), q(0)});
  CHECK(check_kkt(p, good.solution).holds);
  // No rows held: the unconstrained minimizer (1, 2) violates row 0.
  const auto none = certify_active_set(p, {}, 0);
  CHECK_FALSE(none.certified);
  CHECK(none.why == "row 0 is violated by the active set's point");
  // Both rows held: x = -10, y = 12, multipliers -20 (row 0) and -42 (row 1, the most negative).
  const auto both = certify_active_set(p, {0, 1}, 0);
  CHECK_FALSE(both.certified);
  CHECK(both.why == "the multiplier of active row 1 is negative");
  // One exact repair mends either.
  CHECK(certify_active_set(p, {}, 1).certified);
  CHECK(certify_active_set(p, {0, 1}, 1).active == std::vector<std::size_t>{0});
  // Dependent rows (row 0 twice): a singular KKT system, refused without throwing.
  auto dup = p;
  dup.rows.push_back(dup.rows[0]);
  const auto singular = certify_active_set(dup, {0, 2}, 0);
  CHECK_FALSE(singular.certified);
  CHECK(singular.why.find("singular") != std::string::npos);
  // A row that does not exist.
  CHECK_FALSE(certify_active_set(p, {7}, 3).certified);

  // solve_qp with the planted sets: the wrong ones fall back to CGAL, with the reason in `method`.
  for (const std::vector<std::size_t>& planted : {std::vector<std::size_t>{}, std::vector<std::size_t>{0, 1}}) {
    qp_testing::ScopedPlantedActiveSet plant(planted);
    const auto s = solve_qp(p);
    REQUIRE(s.status == QPStatus::optimal);
    CHECK(s.x == std::vector<Rational>{q(1, 2), q(3, 2)});
    CHECK(check_kkt(p, s).holds);
    CHECK(s.method.rfind("exact solver (CGAL, Gmpz), after the planted active set was not certified: ", 0) == 0);
  }
  {
    qp_testing::ScopedPlantedActiveSet plant({0});
    CHECK(solve_qp(p).method == "float active set (1 active rows), certified exactly");
  }
  // Off: the float path certifies.
  CHECK(solve_qp(p).method == "float active set (1 active rows), certified exactly");
  // Programs the float phase cannot take fall back too, with the reason: D only semidefinite
  // (minimize x subject to x >= 0), numbers beyond double's range (10^400 (x^2 - x), x >= 0).
  {
    auto semi = program(1, {q(0)}, {q(1)});
    semi.rows.push_back({{{0, q(1)}}, q(0), true});
    const auto s = solve_qp(semi);
    REQUIRE(s.status == QPStatus::optimal);
    CHECK(s.x == std::vector<Rational>{q(0)});
    CHECK(check_kkt(semi, s).holds);
    CHECK(s.method == "exact solver (CGAL, Gmpz), after the float solve failed: the objective's matrix is not positive definite in double");
    const Rational big = Rational(boost::multiprecision::pow(Integer(10), 400));
    auto huge = program(1, {big}, {Rational(-big)});
    huge.rows.push_back({{{0, q(1)}}, q(0), true});
    const auto h = solve_qp(huge);
    REQUIRE(h.status == QPStatus::optimal);
    CHECK(h.x == std::vector<Rational>{q(1, 2)});
    CHECK(h.method == "exact solver (CGAL, Gmpz), after the float solve failed: the objective is beyond double's range");
  }

  // A real RDCP: its float-certified minimizer and CGAL's exact one (forced by planting the empty
  // set, which is wrong here: the L has an active row) are the same rationals (Lemma 1: unique).
  const auto& R = l_guide();
  REQUIRE(R.solution.method.rfind("float active set", 0) == 0);
  REQUIRE(R.kkt.active >= 1);
  qp_testing::ScopedPlantedActiveSet plant({});
  const auto cgal = solve_qp(R.program);
  CHECK(cgal.method.rfind("exact solver (CGAL, Gmpz)", 0) == 0);
  CHECK(cgal.x == R.solution.x);
  CHECK(cgal.y == R.solution.y);
}

TEST_CASE("cut planted: infeasible programs: a Farkas certificate from the float phase, checked exactly", "[cut][planted]") {
  // x >= 1 and x <= 0: the float phase finds it infeasible; its Farkas candidate checks exactly.
  auto p = program(1, {q(1)}, {q(0)});
  p.rows.push_back({{{0, q(1)}}, q(1), true});
  p.rows.push_back({{{0, q(1)}}, q(0), false});
  const auto s = solve_qp(p);
  REQUIRE(s.status == QPStatus::infeasible);
  CHECK(check_kkt(p, s).holds);
  CHECK(s.method == "float active set, Farkas certificate (2 rows) checked exactly");
  // a Farkas certificate with a wrong multiplier is refused
  auto bad = s;
  bad.y[1] += eps;
  CHECK_FALSE(check_kkt(p, bad).holds);
  // x <= 1 - eps: infeasible by eps, below the float phase's tolerance (it answers x = 1); the
  // exact repair adds the violated row, the KKT system turns singular, the rows form a Farkas
  // certificate.
  p.rows[1].b = q(1) - eps;
  const auto s2 = solve_qp(p);
  REQUIRE(s2.status == QPStatus::infeasible);
  CHECK(check_kkt(p, s2).holds);
  CHECK(s2.method == "float active set, Farkas certificate (2 rows) checked exactly after 1 exact repair");
  // x <= 1: feasible, x = 1
  p.rows[1].b = q(1);
  const auto f = solve_qp(p);
  REQUIRE(f.status == QPStatus::optimal);
  CHECK(f.x == std::vector<Rational>{q(1)});
  CHECK(check_kkt(p, f).holds);
}

TEST_CASE("cut planted: a guide that crosses the boundary between the samples is not certified separating", "[cut][planted]") {
  // The unit square cut from (1/2, 0) to (1/2, 1); b is the right part. f = x - 1/2 separates. The
  // planted f = x - 1/2 - (2 + t)(1/4 - (y - y0)^2), y0 = 33/64, t = 2^-30, is right everywhere
  // outside the strip except on the right edge (b) within about 2^-17 of y0, where it dips to -t/4:
  // every sample has the right sign, and the certificate must find the dip.
  const auto e = cut_example("square");
  const auto R = guide_curve<Rational>(e.solid, e.cut, GuideOptions{});
  REQUIRE(R.frame.scale == 1);
  const Rational y0(33, 64), t = Rational(1) / Rational(Integer(1) << 30);
  const Rational b0 = q(1, 4) - y0 * y0, b1 = b0 + y0, b2 = q(1, 4) - (1 - y0) * (1 - y0);  // Bernstein form of 1/4 - (y - y0)^2
  auto surface = [&](const Rational& k) {
    std::vector<Rational> c;
    for (const Rational& b : {b0, b1, b2})
      for (const Rational& x : {q(0), q(1)}) c.push_back(x - q(1, 2) - k * b);
    return make_spline<Rational>({1, 2}, {clamped_knots<Rational>(1, q(0), q(1)), clamped_knots<Rational>(2, q(0), q(1))}, 1, c);
  };
  const auto straight = make_spline<Rational>({1, 1}, {clamped_knots<Rational>(1, q(0), q(1)), clamped_knots<Rational>(1, q(0), q(1))}, 1,
                                              {q(-1, 2), q(1, 2), q(-1, 2), q(1, 2)});
  CHECK(certify_separation(R.solid, R.cut, straight, GuideOptions{}.strip).verdict.is_proved());
  // 2 - t: right everywhere outside the strip, certified too
  CHECK(certify_separation(R.solid, R.cut, surface(2 - t), GuideOptions{}.strip).verdict.is_proved());
  const auto f = surface(2 + t);
  CHECK(evaluate(f, std::vector<Rational>{q(1), y0})[0] == -t / 4);
  for (std::size_t i = 0; i < R.sample_points.size(); ++i) {
    const Rational v = evaluate(f, std::vector<Rational>{R.sample_points[i][0], R.sample_points[i][1]})[0];
    if (i < R.samples_positive) CHECK(v > 0);
    else CHECK(v < 0);
  }
  const auto sep = certify_separation(R.solid, R.cut, f, GuideOptions{}.strip);
  CHECK(sep.verdict.is_refuted());
  REQUIRE(sep.witness);
  CHECK(sep.witness->positive_side);
  CHECK(sep.witness->point[0] == q(1));
  CHECK(sep.witness->value < 0);
  CHECK(evaluate(f, std::vector<Rational>{sep.witness->point[0], sep.witness->point[1]})[0] == sep.witness->value);
  // Flipped: f's negative is wrong on all of b and b-bar.
  auto flipped = straight;
  for (auto& v : flipped.points) v = -v;
  CHECK(certify_separation(R.solid, R.cut, flipped, GuideOptions{}.strip).verdict.is_refuted());
}

TEST_CASE("cut planted: figure-eight facet loops are refused, their simple neighbours accepted", "[cut][planted]") {
  using P = std::array<Rational, 2>;
  auto bezier_solid = [](const std::vector<std::vector<P>>& facets) {
    Solid2<Rational> S;
    for (const auto& f : facets) {
      const int p = static_cast<int>(f.size()) - 1;
      std::vector<Rational> pts;
      for (const auto& x : f) pts.push_back(x[0]), pts.push_back(x[1]);
      S.facets.push_back(make_spline<Rational>({p}, {clamped_knots<Rational>(p, q(0), q(1))}, 2, pts));
    }
    return S;
  };
  // A cubic S from (0,0) to (4,0), y = 9t(1-t)(1-3t), over the chord back along y = 0: it crosses
  // the chord at t = 1/3 (no halving point), so the loop is a figure eight; the right lobe
  // (counter-clockwise) is the larger, so the signed area is positive and only the simplicity
  // check can refuse it.
  const auto eight = bezier_solid({{P{q(0), q(0)}, P{q(1), q(3)}, P{q(3), q(-6)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(0), q(0)}}});
  REQUIRE(signed_area(eight) > 0);
  CHECK_THROWS_AS(check_simple_loop(eight), ValidationError);
  CHECK_THROWS_WITH(check_simple_loop(eight), Catch::Contains("not simple"));
  CHECK_THROWS_AS(validate_solid(eight), ValidationError);
  // The same S over a chord pushed down below its lowest point: simple, accepted.
  const auto lens = bezier_solid({{P{q(0), q(0)}, P{q(1), q(3)}, P{q(3), q(-6)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(2), q(-16)}, P{q(0), q(0)}}});
  CHECK_NOTHROW(check_simple_loop(lens));
  // The polygon figure eight of the reproducer (repro/cut, figure_eight.solid.json): segments 0 and 2
  // cross at (8/3, 1); signed area 4 > 0.
  const auto poly = bezier_solid({{P{q(0), q(-1)}, P{q(4), q(2)}}, {P{q(4), q(2)}, P{q(4), q(0)}}, {P{q(4), q(0)}, P{q(0), q(3)}}, {P{q(0), q(3)}, P{q(0), q(-1)}}});
  CHECK(signed_area(poly) == q(4));
  CHECK_THROWS_WITH(check_simple_loop(poly), Catch::Contains("(8/3, 1)"));
}
