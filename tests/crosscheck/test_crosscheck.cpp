#include <catch2/catch.hpp>
#include <random>
#include <set>

#include "base/errors.hpp"
#include "crosscheck/crosscheck.hpp"
#include "crosscheck/operations.hpp"
#include "fixtures/random_spline.hpp"
#include "fixtures/teapot.hpp"
#include "tests/helpers.hpp"

using namespace splinex;

TEST_CASE("crosscheck measures double error exactly: tiny but not zero for decimal data") {
  std::mt19937_64 rng(17);
  RandomSplineSpec spec;
  spec.degrees = {3};
  spec.counts = {12};
  const auto S = random_spline(spec, rng);
  Operation op;
  op.kind = Operation::Kind::elevate;
  op.by = 2;
  const auto d = crosscheck(op, S, ArithSpec::parse("double"));
  CHECK(d.structure_match);
  CHECK(d.control_points.max_abs > 0);
  CHECK(d.control_points.rel() < 1e-14);
  CHECK(d.precision == 53);
  CHECK(d.grid.count == 65 * 3);  // 65 grid points, 3 coordinates each
  const auto m = crosscheck(op, S, ArithSpec::parse("mpfr:200"));
  CHECK(m.control_points.max_abs > 0);
  CHECK(m.control_points.max_abs < d.control_points.max_abs);
  CHECK(m.control_points.rel() < 1e-55);
  CHECK(m.control_points.bits_lost(200) < 8);
  CHECK_THROWS_AS(crosscheck(op, S, ArithSpec::parse("gmp")), UsageError);
  // exact is the fraction-free kernel, judged against the GMP reference: no error at all.
  const auto e = crosscheck(op, S, ArithSpec::parse("exact"));
  CHECK(e.structure_match);
  CHECK(e.control_points.max_abs == 0);
  CHECK(e.grid.max_abs == 0);
  CHECK(e.precision == 0);
}

TEST_CASE("dyadic data and dyadic knots: double insertion of a midpoint is exact") {
  const auto S = test::spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,0.5,1,1,1]],"points":[[0],[1],[3],[2]]})");
  Operation op;
  op.kind = Operation::Kind::insert_knots;
  op.knots = {Rational(1, 4), Rational(3, 4)};
  const auto r = crosscheck(op, S, ArithSpec::parse("double"));
  CHECK(r.control_points.max_abs == 0);
  CHECK(r.control_points.bits_lost(53) == 0);
}

TEST_CASE("nearly coincident knots that double cannot separate are reported, not crashed on") {
  // 1/10 and 1/10 + 2^-60 round to the same double: in double the knot has multiplicity 2 = p+1,
  // and inserting 1/10 + 2^-61 (rounds to it too) would exceed it.
  const Rational eps = Rational(1) / Rational(Integer(1) << 60);
  const auto S = make_spline<Rational>({1}, {{0, 0, Rational(1, 10), Rational(1, 10) + eps, 1, 1}}, 1, {0, 1, 2, 3});
  Operation op;
  op.kind = Operation::Kind::insert_knots;
  op.knots = {Rational(1, 10) + eps / 2};
  const auto r = crosscheck(op, S, ArithSpec::parse("double"));
  CHECK_FALSE(r.structure_match);
  CHECK(r.structure_note.find("float run failed") != std::string::npos);
  // With 113 bits the knots stay distinct and the run succeeds.
  CHECK(crosscheck(op, S, ArithSpec::parse("mpfr:113")).structure_match);
}

TEST_CASE("the teapot surfaces merge exactly from the bundled data") {
  const auto patches = read_bpt(data_path("teapot.bpt"));
  REQUIRE(patches.size() == 32);
  CHECK(patches[0].points[3] == Rational(7, 5));     // point 1 = (1.4, -0.784, 2.4)
  CHECK(patches[0].points[4] == Rational(-98, 125));
  const auto surfaces = teapot_surfaces(patches);
  REQUIRE(surfaces.size() == 4);
  CHECK(surfaces[0].name == "body");
  CHECK(surfaces[0].surface.count(0) == 13);
  CHECK(surfaces[0].surface.count(1) == 10);
  CHECK(surfaces[3].surface.count(0) == 13);
  CHECK(surfaces[3].surface.count(1) == 7);
  // Patches that do not share an edge cannot be merged.
  CHECK_THROWS_AS(merge_bezier_grid(patches, {{0, 2}}, "bad"), ValidationError);
  CHECK_THROWS_AS(read_bpt("/nonexistent.bpt"), UsageError);
}

TEST_CASE("operation_table: one row per kernel operation, read back by name, every kind once", "[crosscheck][operations]") {
  std::set<Operation::Kind> kinds;
  for (const auto& row : operation_table()) {
    const Operation op = Operation::parse_kind(row.name);
    CHECK(op.kind == row.kind);
    CHECK(op.name() == row.name);
    CHECK(kinds.insert(row.kind).second);
  }
  // every kind but crosscheck's identity baseline has its row
  CHECK(kinds.size() == 7);
  CHECK(kinds.count(Operation::Kind::identity) == 0);
  CHECK(Operation::parse_kind("identity").kind == Operation::Kind::identity);
  try {
    Operation::parse_kind("refine-all");
    FAIL("an unknown operation was accepted");
  } catch (const UsageError& e) {
    CHECK(std::string(e.what()).find(operation_names() + " or identity") != std::string::npos);
  }
}
