#include <catch2/catch.hpp>

#include "base/errors.hpp"
#include "float/mpfr.hpp"
#include "tests/helpers.hpp"

using namespace splinex;
using test::spline;

namespace {
const char* kCurve =
    R"({"type": "bspline", "degrees": [2], "knots": [[0, 0, 0, 0.1, 1, 1, 1]], "points": [[0.1, "1/3"], [1, 2], ["-3", 1e-3], [5, 7]],
       "weights": [1, "0.5", 2, "7/3"]})";

template <class E>
void expect_error(const std::string& text, const std::string& field_prefix, const Limits& limits = {}) {
  INFO(text);
  try {
    spline(text, limits);
    FAIL("no exception");
  } catch (const E& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).rfind(field_prefix, 0) == 0);
    CHECK(std::string(e.what()).find("fix:") != std::string::npos);
  }
}
}  // namespace

TEST_CASE("JSON numbers are read exactly from their text") {
  const auto S = spline(kCurve);
  CHECK(S.knots[0][3] == Rational(1, 10));
  CHECK(S.points[0] == Rational(1, 10));
  CHECK(S.points[1] == Rational(1, 3));
  CHECK(S.points[5] == Rational(1, 1000));
  CHECK(S.weights[1] == Rational(1, 2));
  // Integers beyond 64 bits and long decimals stay exact.
  const auto B = spline(R"({"type":"bspline","degrees":[0],"knots":[[0,1]],"points":[[123456789012345678901234567890, 0.1000000000000000000000000001]]})");
  CHECK(B.points[0] == Rational(Integer("123456789012345678901234567890")));
  CHECK(B.points[1] == Rational(Integer("1000000000000000000000000001"), Integer("10000000000000000000000000000")));
}

TEST_CASE("exact output is fractions in lowest terms and reads back identically") {
  const auto S = spline(kCurve);
  const Json out = spline_to_json(S);
  CHECK(out["knots"][0][3] == "1/10");
  CHECK(out["points"][2][1] == "1/1000");
  CHECK(spline_from_json(test::doc(out.dump())).points == S.points);
}

TEST_CASE("double output round-trips, MPFR output carries all digits") {
  const auto S = spline(kCurve);
  const auto D = convert<double>(S, [](const Rational& x) { return to_double(x); });
  const Json out = spline_to_json(D);
  const auto back = spline_from_json(test::doc(out.dump()));
  for (std::size_t i = 0; i < D.points.size(); ++i) CHECK(to_double(back.points[i]) == D.points[i]);
  // The printed text is read exactly; it must round to the same double (shortest round-trip text).
  Mpfr::Precision p(200);
  const auto M = convert<Mpfr>(S, [](const Rational& x) { return Mpfr(x); });
  const auto mback = spline_from_json(test::doc(spline_to_json(M).dump()));
  for (std::size_t i = 0; i < M.points.size(); ++i) CHECK(to_rational(Mpfr(mback.points[i])) == to_rational(M.points[i]));
}

TEST_CASE("bad documents get typed errors naming the field and the fix") {
  expect_error<ParseError>(R"({"type": "bspline", "degrees": [1)", "test");
  expect_error<ParseError>(R"({"type": "bspline", "type": "bspline"})", "test");  // duplicate key
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]],"colour":1})", "colour");
  expect_error<ValidationError>(R"({"type":"nurbs","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]]})", "type");
  expect_error<ValidationError>(R"({"type":"bspline","knots":[[0,0,1,1]],"points":[[0],[1]]})", "degrees");
  // Non-monotone knots.
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.7,0.5,1,1]],"points":[[0],[1],[2],[3]]})", "knots[0][3]");
  // Multiplicity above degree+1.
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,0.5,0.5,1,1]],"points":[[0],[1],[2],[3],[4]]})", "knots[0][4]");
  // Wrong number of control points (knots say 3, given 4).
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,1,1]],"points":[[0],[1],[2],[3]]})", "points");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1,1],"knots":[[0,0,1,1],[0,0,1,1]],"points":[[0],[1],[2]]})", "points");
  // Ragged points, wrong weights, zero and negative weights.
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0,1],[1]]})", "points[1]");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]],"weights":[1]})", "weights");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]],"weights":[1,0]})", "weights[1]");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]],"weights":[-1,1]})", "weights[0]");
  // NaN and Inf (not JSON numbers, so they come as strings).
  expect_error<ParseError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[["NaN"],[1]]})", "points[0][0]");
  expect_error<ParseError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,"Infinity",1]],"points":[[0],[1]]})", "knots[0][2]");
  // Empty domain, negative and fractional degrees, too few knots.
  expect_error<DomainError>(R"({"type":"bspline","degrees":[1],"knots":[[0,1,1,2]],"points":[[0],[1]]})", "knots[0]");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[-1],"knots":[[0,1]],"points":[[0]]})", "degrees[0]");
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1.5],"knots":[[0,0,1,1]],"points":[[0],[1]]})", "degrees[0]");
  // A degree that would exhaust memory is refused before any work.
  expect_error<ValidationError>(R"({"type":"bspline","degrees":[1000000000],"knots":[[0,1]],"points":[[0]]})", "degrees[0]");
  Limits small;
  small.max_control_points = 3;
  expect_error<SizeLimitError>(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.2,0.4,1,1]],"points":[[0],[1],[2],[3]]})", "points", small);
}

TEST_CASE("number lists") {
  CHECK(parse_number_list("0.5, 1/3,2e-1", "at") == std::vector<Rational>{Rational(1, 2), Rational(1, 3), Rational(1, 5)});
  CHECK(parse_number_list("", "at").empty());
  CHECK_THROWS_AS(parse_number_list("0.5,,1", "at"), ParseError);
}
