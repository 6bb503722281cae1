// Trimmed V-cells on exact implicit regions (issue 18): the primitives' regions checked against
// their cells, exact point classification, cells cut along quadrics and a quartic, certified
// volumes against closed forms, tangential contact refused, and the trimmed path agreeing exactly
// with the planar one where both apply.
#include <catch2/catch.hpp>

#include <array>

#include "exact/rational.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"
#include "tests/vrep/trimmed_fixtures.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

using namespace splinex;
using R = Rational;

namespace {

using namespace trimmed_fixtures;

VolumeEnclosure<R> volume(const TrimmedModel<R>& M, std::size_t boxes = 4096) {
  VolumeEnclosure<R> v;
  for (const auto& c : M.cells) {
    const auto e = trimmed_volume(M.trivariates[c.trivariate], c.trim, boxes);
    v.lower += e.lower;
    v.upper += e.upper;
  }
  return v;
}

std::size_t count(const TrimmedModel<R>& M, const std::string& category) {
  std::size_t n = 0;
  for (const auto& c : M.cells) n += c.category == category;
  return n;
}

}  // namespace

TEST_CASE("vrep trimmed: the primitives' exact regions describe their cells, wrong ones are caught") {
  CHECK(check_region(glue(cylinder_cells<R>(R(1), R(2))), cylinder_region<R>(R(1), R(2))).empty());
  CHECK(check_region(glue(cone_cells<R>(R(1), R(1, 2), R(2))), cone_region<R>(R(1), R(1, 2), R(2))).empty());
  CHECK(check_region(glue(torus_cells<R>(R(3), R(1))), torus_region<R>(R(3), R(1))).empty());
  CHECK(check_region(glue(box_cells<R>({0, 0, 0}, {1, 2, 3})), box_region<R>({0, 0, 0}, {1, 2, 3})).empty());
  // A larger radius contains the cells, but their side faces lie on no surface of it.
  const auto wide = check_region(glue(cylinder_cells<R>(R(1), R(2))), cylinder_region<R>(R(11, 10), R(2)));
  CHECK(wide.size() == 4);
  // A smaller one cuts the sectors.
  const auto narrow = check_region(glue(cylinder_cells<R>(R(1), R(2))), cylinder_region<R>(R(9, 10), R(2)));
  CHECK(narrow.size() >= 4);
  // The cone's region is not the cylinder's.
  CHECK(!check_region(glue(cone_cells<R>(R(1), R(1, 2), R(2))), cylinder_region<R>(R(1), R(2))).empty());
}

TEST_CASE("vrep trimmed: exact point classification, on the surface included") {
  const auto C = place_region(cylinder_region<R>(R(1), R(2)), 0, {R(-1), R(0), R(1)});  // along x from x = -1 to 1
  CHECK(classify_point(C, {R(0), R(0), R(1)}) == Truth::in);
  CHECK(classify_point(C, {R(0), R(3, 5), R(1) + R(4, 5)}) == Truth::mixed);  // on the side: (3/5)^2 + (4/5)^2 = 1
  CHECK(classify_point(C, {R(0), R(3, 5), R(1) + R(4, 5) + R(1, 1000000)}) == Truth::out);
  CHECK(classify_point(C, {R(0), R(3, 5), R(1) + R(4, 5) - R(1, 1000000)}) == Truth::in);
  CHECK(classify_point(C, {R(-1), R(0), R(1)}) == Truth::mixed);  // on the end disk
  CHECK(classify_point(C, {R(3, 2), R(0), R(1)}) == Truth::out);
  const auto T = torus_region<R>(R(3), R(1));
  CHECK(classify_point(T, {R(3), R(0), R(0)}) == Truth::in);
  CHECK(classify_point(T, {R(0), R(0), R(0)}) == Truth::out);
  CHECK(classify_point(T, {R(4), R(0), R(0)}) == Truth::mixed);
  CHECK(classify_point(region_not(T), {R(0), R(0), R(0)}) == Truth::in);
}

TEST_CASE("vrep trimmed: a cylinder halved by a box, volume pi r^2 h / 2 enclosed") {
  // x >= 0 is oblique to the disk's inner square (corners at (4/5, 3/5)/2 rotated): no parameter plane.
  const auto C = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  const auto B = box({R(0), R(-2), R(-1)}, {R(2), R(2), R(3)});
  const auto M = trimmed_boolean(C, B, BooleanOp::intersect);
  CHECK(M.cells.size() == 4);  // the square and three of the four sectors meet x > 0
  std::size_t cut = 0;
  for (const auto& c : M.cells) cut += c.status == Truth::mixed;
  CHECK(cut == 3);  // the sector from -53 to 37 degrees lies in x > 0 whole; the square and two sectors are cut
  const auto v = volume(M, 1024);
  INFO(to_double(v.lower) << " " << to_double(v.upper));
  CHECK(v.lower < pi_lo);
  CHECK(pi_hi < v.upper);
  CHECK(v.upper - v.lower < R(1, 2));  // 3.036 .. 3.349 (the gap shrinks as boxes^(-1/2))
  // Subtraction gives the other half: both enclose pi, and together they enclose 2 pi.
  const auto S = trimmed_boolean(C, B, BooleanOp::subtract);
  const auto w = volume(S, 256);
  CHECK(w.lower < pi_lo);
  CHECK(pi_hi < w.upper);
}

TEST_CASE("vrep trimmed: on boxes the trimmed path gives the planar path's volumes exactly") {
  const auto A = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto B = box({R(1), R(1, 2), R(0)}, {R(3), R(3, 2), R(2)});
  const auto Am = glue(box_cells<R>({0, 0, 0}, {2, 2, 2})), Bm = glue(box_cells<R>({R(1), R(1, 2), R(0)}, {R(3), R(3, 2), R(2)}));
  for (auto op : {BooleanOp::intersect, BooleanOp::subtract, BooleanOp::unite}) {
    const auto T = trimmed_boolean(A, B, op);
    const auto P = boolean_op(Am, Bm, op);
    R planar(0);
    for (std::size_t c = 0; c < P.cells.size(); ++c) planar += cell_volume(P, c);
    const auto v = volume(T, 1 << 14);
    INFO(to_string(op));
    // Dyadic cuts: subdivision meets them exactly, no box stays mixed.
    CHECK(v.lower == v.upper);
    CHECK(v.lower == planar);
  }
  const auto U = trimmed_boolean(A, B, BooleanOp::unite);
  CHECK(count(U, "both") == 1);
  CHECK(count(U, "A") == 1);
  CHECK(count(U, "B") == 1);
}

TEST_CASE("vrep trimmed: tangential contact is refused, never guessed") {
  const auto C = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  // The box's face x = 1 touches the cylinder along the line (1, 0, z).
  const auto B = box({R(1), R(-2), R(-1)}, {R(2), R(2), R(3)});
  TrimOptions o;
  o.max_boxes = 512;
  CHECK_THROWS_AS(trimmed_boolean(C, B, BooleanOp::unite, Blend::sum_clipped, o), DomainError);
  // Moved through by 1/1000 it is an ordinary cut, decided.
  const auto B2 = box({R(999, 1000), R(-2), R(-1)}, {R(2), R(2), R(3)});
  const auto M = trimmed_boolean(C, B2, BooleanOp::intersect);
  CHECK(M.cells.size() == 1);
  // And 1/1000 away nothing is left of the intersection.
  const auto B3 = box({R(1001, 1000), R(-2), R(-1)}, {R(2), R(2), R(3)});
  CHECK_THROWS_AS(trimmed_boolean(C, B3, BooleanOp::intersect, Blend::sum_clipped, o), DomainError);  // empty result
  CHECK(trimmed_boolean(C, B3, BooleanOp::subtract, Blend::sum_clipped, o).cells.size() == 5);
}

TEST_CASE("vrep trimmed: Figure 4, cone union cylinder, cells in the three categories") {
  auto cone = cone_cells<R>(R(1), R(1, 2), R(2));
  const auto O1 = as_trimmed(glue(cone), cone_region<R>(R(1), R(1, 2), R(2)));
  const auto O2 = cylinder(R(1, 3), R(3), 0, {R(-3, 2), R(0), R(1)});  // along x through the cone at height 1
  const auto M = trimmed_boolean(O1, O2, BooleanOp::unite);
  CHECK(count(M, "A") >= 1);
  CHECK(count(M, "both") >= 1);
  CHECK(count(M, "B") >= 1);
  for (const auto& c : M.cells)
    if (c.category == "both") CHECK(c.inherited.size() >= 1);  // it holds trivariates of both models
  // The union's region classifies exactly.
  CHECK(classify_point(M.region, {R(0), R(0), R(1, 2)}) == Truth::in);     // in the cone only
  CHECK(classify_point(M.region, {R(-7, 5), R(0), R(1)}) == Truth::in);    // in the cylinder only
  CHECK(classify_point(M.region, {R(0), R(0), R(5, 2)}) == Truth::out);
  // vol(A u B) = vol A + vol B - vol(A n B), each side an enclosure: the intervals must meet.
  const auto I = trimmed_boolean(O1, O2, BooleanOp::intersect);
  const auto vu = volume(M, 256), va = volume(O1, 64), vb = volume(O2, 64), vi = volume(I, 256);
  CHECK(!(vu.upper < va.lower + vb.lower - vi.upper));
  CHECK(!(va.upper + vb.upper - vi.lower < vu.lower));
  // The cone frustum's volume pi h (r0^2 + r0 r1 + r1^2) / 3 = 7 pi / 6 lies in its enclosure.
  CHECK(va.lower < pi_lo * R(7, 6));
  CHECK(pi_hi * R(7, 6) < va.upper);
}

TEST_CASE("vrep trimmed: Figure 15's kind of solid, one union and two subtractions, 7 cells") {
  const auto base = box({R(-2), R(-2), R(0)}, {R(2), R(2), R(1)});
  const auto post = cylinder(R(1), R(3), 2, {R(0), R(0), R(0)});
  const auto U = trimmed_boolean(base, post, BooleanOp::unite);
  CHECK(U.cells.size() == 7);  // the base inside the post, the base outside it, the post's five cells above the base
  const auto H1 = trimmed_boolean(U, cylinder(R(1, 4), R(3), 2, {R(3, 2), R(3, 2), R(-1)}), BooleanOp::subtract);
  const auto H2 = trimmed_boolean(H1, cylinder(R(1, 4), R(3), 2, {R(-3, 2), R(-3, 2), R(-1)}), BooleanOp::subtract);
  CHECK(H2.cells.size() == 7);
  // Volume 16 + 3 pi - pi (the post's part in the base) - 2 pi / 16 (the holes) = 16 + 15 pi / 8.
  const auto v = volume(H2, 256);
  INFO(to_double(v.lower) << " " << to_double(v.upper));
  CHECK(v.lower < R(16) + pi_lo * R(15, 8));
  CHECK(R(16) + pi_hi * R(15, 8) < v.upper);
  CHECK(classify_point(H2.region, {R(3, 2), R(3, 2), R(1, 2)}) == Truth::out);  // in a hole
  CHECK(classify_point(H2.region, {R(1), R(3, 2), R(1, 2)}) == Truth::in);
  CHECK(classify_point(H2.region, {R(0), R(0), R(5, 2)}) == Truth::in);  // in the post
}

TEST_CASE("vrep trimmed: a torus cut by a slab along its quartic, and hostile regions") {
  const auto T = as_trimmed(glue(torus_cells<R>(R(3), R(1))), torus_region<R>(R(3), R(1)));
  const auto slab = box({R(-5), R(-5), R(-1, 3)}, {R(5), R(5), R(1, 3)});
  const auto M = trimmed_boolean(T, slab, BooleanOp::intersect);
  CHECK(!M.cells.empty());
  const auto v = volume(M, 256);
  CHECK(v.lower < v.upper);
  CHECK(R(0) < v.lower);
  // The zero polynomial is refused as a leaf.
  CHECK_THROWS_AS(region_leaf(Poly3<R>{}), ValidationError);
  Poly3<R> big;
  big.terms[{9, 0, 0}] = R(1);
  CHECK_THROWS_AS(classify_cell(glue(box_cells<R>({0, 0, 0}, {1, 1, 1})).trivariates[0], region_leaf(big)), SizeLimitError);
}

#include "io/trimmed_io.hpp"

TEST_CASE("vrep trimmed: regions and trimmed documents read exactly, hostile ones refused") {
  // Round trip: the cone's region, written and read, classifies the same points the same way.
  const auto C = place_region(cone_region<R>(R(1), R(1, 2), R(2)), 1, {R(1, 3), R(0), R(-7, 10)});
  const auto back = region_from_json(Json::parse(region_to_json(C).dump()));
  for (const auto& x : std::vector<std::vector<R>>{{R(1, 3), R(1), R(-7, 10)}, {R(0), R(0), R(0)}, {R(1, 3), R(1, 2), R(1, 10)}})
    CHECK(classify_point(back, x) == classify_point(C, x));
  // Decimal text is exact.
  const auto half = region_from_json(Json::parse(R"({"leaf": [["0.1", 0, 0, 0], ["-1", 1, 0, 0]]})"));
  CHECK(classify_point(half, {R(1, 10), R(0), R(0)}) == Truth::mixed);
  // Nesting beyond 64 levels, too many leaves, degree above 8, bad terms, unknown fields.
  std::string deep = R"({"leaf": [[1, 0, 0, 0]]})";
  for (int i = 0; i < 70; ++i) deep = R"({"not": )" + deep + "}";
  CHECK_THROWS_AS(region_from_json(Json::parse(deep)), SizeLimitError);
  Json many = Json::object();
  many["all"] = Json::array();
  for (int i = 0; i < 5000; ++i) many["all"].push_back(Json::parse(R"({"leaf": [[1, 0, 0, 0]]})"));
  CHECK_THROWS_AS(region_from_json(many), SizeLimitError);
  CHECK_THROWS_AS(region_from_json(Json::parse(R"({"leaf": [[1, 5, 4, 0]]})")), SizeLimitError);
  CHECK_THROWS_AS(region_from_json(Json::parse(R"({"leaf": [[1, -1, 0, 0]]})")), ValidationError);
  CHECK_THROWS_AS(region_from_json(Json::parse(R"({"leaf": [[0, 1, 0, 0]]})")), ValidationError);  // the zero polynomial
  CHECK_THROWS_AS(region_from_json(Json::parse(R"({"leaf": [[1, 0, 0, 0]], "colour": 1})")), ValidationError);
  CHECK_THROWS_AS(region_from_json(Json::parse(R"({"all": 3})")), ValidationError);
  CHECK_THROWS_AS(region_from_json(Json::parse(R"([])")), ValidationError);
  // A trimmed document: written and read back, the same volume enclosure.
  const auto Cy = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  const auto M = trimmed_boolean(Cy, box({R(0), R(-2), R(-1)}, {R(2), R(2), R(3)}), BooleanOp::intersect);
  const auto N = trimmed_from_json(Json::parse(trimmed_to_json(M).dump()));
  REQUIRE(N.cells.size() == M.cells.size());
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto a = trimmed_volume(M.trivariates[M.cells[c].trivariate], M.cells[c].trim, 64);
    const auto b = trimmed_volume(N.trivariates[N.cells[c].trivariate], N.cells[c].trim, 64);
    CHECK(a.lower == b.lower);
    CHECK(a.upper == b.upper);
  }
  // Hostile trimmed documents: a cell that is a curve, an inherited index out of range, a
  // negative weight.
  Json doc = trimmed_to_json(M);
  Json bad = doc;
  bad["cells"][0]["trivariate"] = Json::parse(R"({"type": "bspline", "degrees": [1], "knots": [[0, 0, 1, 1]], "points": [[0, 0, 0], [1, 0, 0]]})");
  const auto curve = trimmed_from_json(bad);
  CHECK_THROWS_AS(trimmed_volume(curve.trivariates[0], curve.cells[0].trim, 64), ValidationError);
  bad = doc;
  bad["cells"][0]["inherited"] = Json::array({7});
  CHECK_THROWS_AS(trimmed_from_json(bad), ValidationError);
  auto V = M.trivariates[M.cells[0].trivariate];
  if (V.is_rational()) {
    V.weights[0] = R(-1);
    CHECK_THROWS_AS(classify_cell(V, M.cells[0].trim), Error);
  }
  // A trivariate too large for the composed leaves is refused before the work (all leaves on one
  // piece above the limit); within it, the boxes' carried compositions are counted against it. A
  // box trimmed by the cylinder: its side (degree 2, 27 coefficients on the box) and two planes.
  const auto B = trimmed_boolean(box({R(0), R(-2), R(-1)}, {R(2), R(2), R(3)}), Cy, BooleanOp::intersect);
  REQUIRE(B.cells.size() == 1);
  const auto& BV = B.trivariates[B.cells[0].trivariate];
  Limits small;
  small.max_control_points = 30;
  CHECK_THROWS_WITH(classify_cell(BV, B.cells[0].trim, TrimOptions{}, R(0), small), Catch::Contains("region composed with the trivariate: the result would have 43"));
  small.max_control_points = 1000;
  CHECK(classify_cell(BV, B.cells[0].trim, TrimOptions{}, R(0), small).kind == CellClass<R>::cut);
  // The volume's boxes spending their whole budget (width 0): the mixed ones along the cylinder
  // carry more than 1000 coefficients together.
  CHECK_THROWS_WITH(trimmed_volume(BV, B.cells[0].trim, 900, small, R(0)), Catch::Contains("the boxes would carry"));
}

TEST_CASE("vrep trimmed: near tangency, exact certifies or refuses where double with a tolerance answers wrongly") {
  const auto C = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  auto slab = [](const R& g) { return box({R(1) + g, R(-2), R(-1)}, {R(2), R(2), R(3)}); };
  // A sliver of width 2^-20 exists: certified cut, exactly.
  const auto M = trimmed_boolean(C, slab(-R(1) / R(1 << 20)), BooleanOp::intersect);
  REQUIRE(M.cells.size() == 1);
  CHECK(M.cells[0].status == Truth::mixed);
  // Width 2^-30: beyond the default budget, refused exactly; in double at eps 1e-6 it is called
  // empty, which is wrong (the sliver has positive volume).
  const auto thin = slab(-R(1) / R(1LL << 30));
  CHECK_THROWS_AS(trimmed_boolean(C, thin, BooleanOp::intersect), DomainError);
  try {
    (void)trimmed_boolean(trimmed_to_double(C), trimmed_to_double(thin), BooleanOp::intersect, Blend::sum_clipped, {}, 1e-6);
    FAIL("double at eps 1e-6 was expected to call the sliver empty");
  } catch (const DomainError& e) {
    CHECK(std::string(e.what()).find("empty") != std::string::npos);
  }
  // And the sliver is there: an exact point in both models.
  const R x = R(1) - R(1) / R(1LL << 31);
  CHECK(classify_point(region_and<R>({C.region, thin.region}), {x, R(0), R(1)}) == Truth::in);
}

TEST_CASE("vrep trimmed: centroids, exact for polynomial cells, certified for curved cuts") {
  // An L-shaped union of boxes: the centroid (7/6, 5/6, 1/2) exactly.
  const auto L = trimmed_boolean(box({R(0), R(0), R(0)}, {R(2), R(1), R(1)}), box({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), BooleanOp::unite);
  const std::array<R, 3> expect{R(7, 6), R(5, 6), R(1, 2)};
  for (int a = 0; a < 3; ++a) {
    R m(0), v(0);
    for (const auto& c : L.cells) {
      const auto e = trimmed_moment(L.trivariates[c.trivariate], c.trim, a, 256);
      CHECK(e.moment.lower == e.moment.upper);
      m += e.moment.lower;
      v += e.volume.lower;
    }
    CHECK(m / v == expect[a]);
  }
  // The half cylinder x >= 0 (r 1, h 2): x-moment 2/3 r^3 h = 4/3 exactly, enclosed; z-moment pi (h/2).
  const auto C = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  const auto H = trimmed_boolean(C, box({R(0), R(-2), R(-1)}, {R(2), R(2), R(3)}), BooleanOp::intersect);
  R lo(0), hi(0);
  for (const auto& c : H.cells) {
    const auto e = trimmed_moment(H.trivariates[c.trivariate], c.trim, 0, 128);
    lo += e.moment.lower;
    hi += e.moment.upper;
  }
  INFO(to_double(lo) << " " << to_double(hi));
  CHECK(lo < R(4, 3));
  CHECK(R(4, 3) < hi);
  CHECK_THROWS_AS(trimmed_moment(C.trivariates[0], C.cells[0].trim, 3, 64), ValidationError);  // no coordinate 3
}

TEST_CASE("vrep trimmed: a region beyond double's range is refused when rounded, not turned into infinity") {
  Poly3<R> g;
  g.terms[{1, 0, 0}] = R(1);
  R big(1);
  for (int i = 0; i < 1100; ++i) big *= R(2);  // 2^1100 > DBL_MAX
  g.terms[{0, 0, 0}] = -big;
  CHECK_THROWS_AS(region_to_double(region_leaf(g)), Error);
}


TEST_CASE("vrep trimmed: integrals of attribute fields over (trimmed) cells, exact or certified") {
  const auto B = box({R(0), R(0), R(0)}, {R(2), R(1), R(1)});
  const auto& V = B.trivariates[0];
  const auto none = region_and<R>({});
  // f = x over [0,2]x[0,1]x[0,1]: 2, exactly; trimmed to x <= 1/2 (a dyadic parameter cut): 1/8.
  const auto f = test::affine_field(V, {R(1), R(0), R(0)}, R(0));
  auto e = trimmed_field_integral(V, none, f, 0, 64);
  CHECK(e.moment.lower == R(2));
  CHECK(e.moment.upper == R(2));
  CHECK(e.volume.lower == R(2));
  const auto half = region_and<R>({region_leaf(Poly3<R>{{{{0, 0, 0}, R(1, 2)}, {{1, 0, 0}, R(-1)}}})});
  e = trimmed_field_integral(V, half, f, 0, 256);
  CHECK(e.moment.lower == R(1, 8));
  CHECK(e.moment.upper == R(1, 8));
  // A field of its own structure: degree 2 in u (values 0, 0, 1: u^2), degree 0 in v and w, with
  // an interior knot at 1/3 in u: the same function u^2 = x^2 / 4, integral 2 / 3.
  auto g = make_spline<R>({2, 0, 0}, {{R(0), R(0), R(0), R(1), R(1), R(1)}, {R(0), R(1)}, {R(0), R(1)}}, 1, {R(0), R(0), R(1)});
  g = refine_knots(g, 0, {R(1, 3)});
  e = trimmed_field_integral(V, none, g, 0, 64);
  CHECK(e.moment.lower == R(2, 3));
  CHECK(e.moment.upper == R(2, 3));
  // Edge knots: a jump (multiplicity p + 1 at 1/2: 0 then 1) integrates to 2 * 1/2 = 1, and an
  // unclamped field (knots -1, 0, 1, 2: u on [0, 1]) to 2 * 1/2 = 1, exactly.
  const auto jump = make_spline<R>({1, 0, 0}, {{R(0), R(0), R(1, 2), R(1, 2), R(1), R(1)}, {R(0), R(1)}, {R(0), R(1)}}, 1, {R(0), R(0), R(1), R(1)});
  e = trimmed_field_integral(V, none, jump, 0, 64);
  CHECK(e.moment.lower == R(1));
  CHECK(e.moment.upper == R(1));
  const auto open = make_spline<R>({1, 0, 0}, {{R(-1), R(0), R(1), R(2)}, {R(0), R(1)}, {R(0), R(1)}}, 1, {R(0), R(1)});
  e = trimmed_field_integral(V, none, open, 0, 64);
  CHECK(e.moment.lower == R(1));
  CHECK(e.moment.upper == R(1));
  // Curved cells (rational): the constant field 1 integrates to the volume, 2 pi over the cylinder.
  const auto C = cylinder(R(1), R(2), 2, {R(0), R(0), R(0)});
  R lo(0), hi(0);
  for (const auto& c : C.cells) {
    const auto& W = C.trivariates[c.trivariate];
    const auto one = make_spline<R>({0, 0, 0}, {{W.domain_lo(0), W.domain_hi(0)}, {W.domain_lo(1), W.domain_hi(1)}, {W.domain_lo(2), W.domain_hi(2)}}, 1, {R(1)});
    const auto k = trimmed_field_integral(W, c.trim, one, 0, 256);
    const auto v = trimmed_volume(W, c.trim, 256);
    CHECK(k.moment.lower <= v.upper);
    CHECK(v.lower <= k.moment.upper);
    lo += k.moment.lower;
    hi += k.moment.upper;
  }
  INFO(to_double(lo) << " " << to_double(hi));
  CHECK(lo < 2 * pi_lo);
  CHECK(2 * pi_hi < hi);
  // Hostile: another domain, a missing component, a rational field.
  auto other = f;
  other.knots[0] = {R(0), R(0), R(2), R(2)};
  CHECK_THROWS_AS(trimmed_field_integral(V, none, other, 0, 64), ValidationError);
  CHECK_THROWS_AS(trimmed_field_integral(V, none, f, 1, 64), ValidationError);
  auto rat = f;
  rat.weights.assign(f.size(), R(1));
  rat.weights[0] = R(2);
  CHECK_THROWS_AS(trimmed_field_integral(V, none, rat, 0, 64), DomainError);
}

TEST_CASE("vrep trimmed: fields ride along the Booleans, the other model's named where not taken over") {
  auto A = box({R(0), R(0), R(0)}, {R(2), R(1), R(1)});
  auto B = box({R(1), R(0), R(0)}, {R(3), R(1), R(1)});
  A.cells[0].fields["f"] = test::affine_field(A.trivariates[0], {R(1), R(0), R(0)}, R(0));
  B.cells[0].fields["f"] = test::affine_field(B.trivariates[0], {R(2), R(1), R(0)}, R(1));
  const auto U = trimmed_boolean(A, B, BooleanOp::unite, Blend::sum);
  REQUIRE(U.cells.size() == 3);
  for (const auto& c : U.cells) {
    REQUIRE(c.fields.count("f") == 1);
    // Trimming keeps the parameters: the field is the source cell's, unchanged.
    const bool from_b = c.category == "B";
    CHECK(same_net(c.fields.at("f"), (from_b ? B : A).cells[0].fields.at("f")));
    if (c.category == "both") {
      REQUIRE(c.not_carried.size() == 1);
      CHECK(c.not_carried[0] == "f");
    } else CHECK(c.not_carried.empty());
  }
  // The integral of f = x over the A-only part x in [0, 1]: 1/2, exactly (the cut is dyadic).
  for (const auto& c : U.cells)
    if (c.category == "A") {
      const auto e = trimmed_field_integral(U.trivariates[c.trivariate], c.trim, c.fields.at("f"), 0, 256);
      CHECK(e.moment.lower == R(1, 2));
      CHECK(e.moment.upper == R(1, 2));
    }
}

TEST_CASE("cell_kind: settled boxes decide, unsettled ones decide only cut (with a point inside and one outside)", "[vrep][trimmed]") {
  using K = CellClass<Rational>;
  CHECK(cell_kind<Rational>(true, true, false) == K::whole);
  CHECK(cell_kind<Rational>(true, false, false) == K::empty);
  CHECK(cell_kind<Rational>(true, true, true) == K::cut);
  CHECK(cell_kind<Rational>(false, true, true) == K::cut);
  for (bool in : {false, true}) {
    const auto k = cell_kind<Rational>(false, in, !in);
    CHECK_FALSE(k.is_certain());
    CHECK(k.reason().find("without both witnesses") != std::string::npos);
    CHECK(std::string(to_string<Rational>(k)) == "undecided");
    CHECK_THROWS_AS(k.make_certain("the cell's kind"), UndecidedError);
  }
}
