// Property test over the structured generator (issue 13): every kernel operation in every
// arithmetic on random legal inputs (degree 0..7, C^-1 knots, unclamped, tiny gaps, rational with
// weights 1e-6..1e6, values beyond double's range).
//   exact (GMP):  the result is judged by independent evaluation: R(phi(x)) == S(x) exactly at
//                 random parameters that are not knots (phi: the operation's reparametrization);
//   FLINT:        equals the GMP result exactly;
//   exact (the fraction-free kernel, run_operation_exact): equals the GMP result exactly;
//   double, mpfr: a typed splinex::Error (RangeError when the input does not fit the format), or a
//                 crosscheck report whose errors are finite and whose structure matches the exact
//                 result; never another exception, a non-finite value or a crash.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "crosscheck/crosscheck.hpp"
#include "crosscheck/operations_ff.hpp"
#include "crosscheck/operations_impl.hpp"
#include "exact/flint_rational.hpp"
#include "fixtures/random_spline.hpp"
#include "spline/kernel.hpp"

namespace sx = splinex;
using sx::Rational;

namespace {

bool is_knot(const sx::BSpline<Rational>& S, int d, const Rational& x) {
  return std::binary_search(S.knots[d].begin(), S.knots[d].end(), x);
}

// A parameter of S strictly inside the domain and on no knot (denominator 1000003, a prime).
std::vector<Rational> sample(std::mt19937_64& rng, const sx::BSpline<Rational>& S) {
  std::vector<Rational> x;
  for (int d = 0; d < S.dim(); ++d) {
    Rational v;
    do v = S.domain_lo(d) + (S.domain_hi(d) - S.domain_lo(d)) * Rational(static_cast<long>(1 + rng() % 1000001), 1000003);
    while (is_knot(S, d, v));
    x.push_back(v);
  }
  return x;
}

sx::Operation random_op(std::mt19937_64& rng, const sx::BSpline<Rational>& S) {
  sx::Operation op;
  op.dir = static_cast<int>(rng() % S.dim());
  const Rational lo = S.domain_lo(op.dir), hi = S.domain_hi(op.dir);
  switch (rng() % 7) {
    case 0:
    case 1:
      op.kind = sx::Operation::Kind::insert_knots;
      op.boehm = rng() % 2;
      for (int i = 0, k = 1 + static_cast<int>(rng() % 3); i < k; ++i)
        op.knots.push_back(lo + (hi - lo) * Rational(static_cast<long>(1 + rng() % 7), 8));
      break;
    case 2:
      op.kind = sx::Operation::Kind::elevate;
      op.by = 1 + static_cast<int>(rng() % 2);
      op.method = rng() % 2 ? sx::ElevationMethod::blossom : sx::ElevationMethod::bezier_pieces;
      break;
    case 3: op.kind = sx::Operation::Kind::extract_bezier; break;
    case 4:
      op.kind = sx::Operation::Kind::split;
      op.at = lo + (hi - lo) * Rational(static_cast<long>(1 + rng() % 7), 8);
      break;
    case 5:
      op.kind = sx::Operation::Kind::reparametrize;
      op.lo = Rational(-3, 7);
      op.hi = Rational(static_cast<long>(1 + rng() % 9), 4);
      break;
    default: op.kind = sx::Operation::Kind::reverse; break;
  }
  return op;
}

// R(phi(x)) == S(x) for the result piece that holds x.
void judge_exact(const sx::Operation& op, const sx::BSpline<Rational>& S, const std::vector<sx::BSpline<Rational>>& R,
                 const std::vector<Rational>& x) {
  std::vector<Rational> y = x;
  const int d = op.dir;
  const Rational a = S.domain_lo(d), b = S.domain_hi(d);
  if (op.kind == sx::Operation::Kind::reparametrize) y[d] = op.lo + (x[d] - a) * (op.hi - op.lo) / (b - a);
  if (op.kind == sx::Operation::Kind::reverse) y[d] = a + b - x[d];
  const auto want = sx::evaluate(S, x);
  int holders = 0;
  for (const auto& P : R) {
    bool in = true;
    for (int k = 0; k < P.dim(); ++k) in = in && !(y[k] < P.domain_lo(k)) && y[k] < P.domain_hi(k);
    if (!in) continue;
    ++holders;
    REQUIRE(sx::evaluate(P, y) == want);
  }
  REQUIRE(holders == 1);
}

}  // namespace

TEST_CASE("property: every operation in every arithmetic on the structured generator") {
  std::mt19937_64 rng(13013);
  sx::Limits limits;
  limits.max_control_points = 200000;
  int exact_checked = 0, float_reports = 0, typed_errors = 0, ff_checked = 0;
  for (int c = 0; c < 400; ++c) {
    const auto sc = sx::structured_case(rng);
    const auto& S = sc.spline;
    const auto op = random_op(rng, S);
    INFO("case " << c << ": " << op.name() << " dir " << op.dir << " on degrees " << S.degrees.size());
    std::vector<sx::BSpline<Rational>> R;
    try {
      R = sx::run_operation(op, S, limits);
    } catch (const sx::Error&) {
      ++typed_errors;  // e.g. a knot raised above multiplicity p+1
      continue;
    }
    for (int k = 0; k < 3; ++k) judge_exact(op, S, R, sample(rng, S));
    ++exact_checked;
    // FLINT: the same numbers.
    const auto SF = sx::convert<sx::FlintRational>(S, [](const Rational& r) { return sx::FlintRational(r); });
    const auto RF = sx::run_operation(op, SF, limits);
    REQUIRE(RF.size() == R.size());
    for (std::size_t i = 0; i < R.size(); ++i) {
      const auto back = sx::convert<Rational>(RF[i], [](const sx::FlintRational& r) { return r.to_rational(); });
      REQUIRE(back.knots == R[i].knots);
      REQUIRE(back.points == R[i].points);
      REQUIRE(back.weights == R[i].weights);
    }
    // The fraction-free kernel (where the operation is written for it; GMP otherwise): the same numbers.
    const auto RX = sx::run_operation_exact(op, S, limits);
    REQUIRE(RX.size() == R.size());
    for (std::size_t i = 0; i < R.size(); ++i) {
      REQUIRE(RX[i].degrees == R[i].degrees);
      REQUIRE(RX[i].knots == R[i].knots);
      REQUIRE(RX[i].points == R[i].points);
      REQUIRE(RX[i].weights == R[i].weights);
    }
    if (sx::runs_fraction_free(op)) ++ff_checked;
    // Floats: a typed error or a finite report with matching structure.
    for (const char* fl : {"double", "mpfr:64"}) {
      try {
        const auto rep = sx::crosscheck(op, S, sx::ArithSpec::parse(fl), 3, limits);
        INFO(fl << ": " << rep.structure_note);
        if (!rep.structure_match && rep.structure_note.rfind("the float run failed: ", 0) == 0) {
          ++typed_errors;  // a typed splinex::Error in the float run, reported by the crosscheck
          continue;
        }
        REQUIRE(rep.structure_match);
        REQUIRE(std::isfinite(rep.control_points.abs()));
        REQUIRE(std::isfinite(rep.grid.abs()));
        REQUIRE(std::isfinite(rep.grid.bits_lost(rep.precision)));
        ++float_reports;
      } catch (const sx::RangeError&) {
        ++typed_errors;  // the exact input does not fit the format (values beyond it, knots merging)
      }
    }
  }
  INFO(exact_checked << " exact results judged, " << ff_checked << " of them fraction-free, " << float_reports
                     << " float reports, " << typed_errors << " typed errors");
  CHECK(exact_checked >= 300);
  CHECK(ff_checked >= 100);
  CHECK(float_reports >= 400);
}
