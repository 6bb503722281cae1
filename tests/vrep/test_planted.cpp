// Planted bugs for every certificate of V-rep (issue 47, "Prove it"): for each test-only plant of
// vrep/model/planted.hpp, an input that reaches the mutated branch, the wrong certified answer the plant
// gives (detected independently: exact point values of det J from the kernel's derivatives, exact
// point classification, hand counts and closed forms of chi), and the right answer with it off.
// Each case also runs the check of an ordinary test under the plant and shows that it fails.
//
// SPLINEX_VREP_PLANT=<name> in the environment plants that bug for the whole test process (test
// only; the library never reads it): then the ordinary vrep tests show which of them catch it
// (docs/vrep/model.md, "Planted bugs"). The cases below run their "off" halves under an explicit
// ScopedPlant(Plant::none), so they hold in such a run too.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <utility>

#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "spline/evaluate.hpp"
#include "spline/insert.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/validate.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_euler.hpp"
#include "vrep/topology/trimmed_glue.hpp"
#include "vrep/topology/trimmed_topology.hpp"

using namespace splinex;
using R = Rational;
using vrep_testing::Plant;
using vrep_testing::ScopedPlant;

namespace {

// --- The whole-process plant of SPLINEX_VREP_PLANT (tests only). ---
const std::pair<const char*, Plant> kPlants[] = {
    {"regularity_corners_only", Plant::regularity_corners_only},
    {"regularity_drops_upper_u", Plant::regularity_drops_upper_u},
    {"regularity_sign_flipped", Plant::regularity_sign_flipped},
    {"classify_skips_plane", Plant::classify_skips_plane},
    {"classify_first_piece_only", Plant::classify_first_piece_only},
    {"cases_ignore_pieces", Plant::cases_ignore_pieces},
    {"region_arc_unchecked", Plant::region_arc_unchecked},
    {"surface_shape_unchecked", Plant::surface_shape_unchecked},
    {"euler_monotone_sign", Plant::euler_monotone_sign},
    {"euler_drops_mid_face", Plant::euler_drops_mid_face},
    {"glue_counts_ignored", Plant::glue_counts_ignored},
    {"vmodel_twin_by_loop", Plant::vmodel_twin_by_loop},
    {"validate_sweep_bound", Plant::validate_sweep_bound},
    {"validate_corner_in_edge", Plant::validate_corner_in_edge},
    {"validate_flat_skipped", Plant::validate_flat_skipped},
    {"validate_interior_zero", Plant::validate_interior_zero},
};
const bool kEnvironmentPlant = [] {
  const char* name = std::getenv("SPLINEX_VREP_PLANT");
  if (!name) return false;
  for (const auto& [n, p] : kPlants)
    if (std::strcmp(n, name) == 0) {
      vrep_testing::planted = p;
      return true;
    }
  return false;
}();

/// det J at x from the kernel's derivatives, exactly (independent of certify_regularity).
R det_at(const BSpline<R>& V, const std::vector<R>& x) {
  R J[3][3];
  for (int c = 0; c < 3; ++c) {
    std::vector<int> ord(3, 0);
    ord[c] = 1;
    const auto d = derivative(V, x, ord);
    for (int r = 0; r < 3; ++r) J[r][c] = d[r];
  }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

/// x(u) cubic with x'(u) = 100 (u - 3/5)(u - 9/10) (Bernstein coefficients 54, -21, 4), y = v,
/// z = w: det J = x'(u) is positive at every corner of the domain and on u <= 1/2 (its Bernstein
/// coefficients there 54, 33/2, 13/2... all positive), negative for 3/5 < u < 9/10: det J(3/4, .) = -9/4.
BSpline<R> folded_cubic() {
  BSpline<R> V;
  V.degrees = {3, 1, 1};
  V.knots = {{0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}};
  V.q = 3;
  const R X[4] = {R(0), R(18), R(11), R(37, 3)};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) V.points.insert(V.points.end(), {X[i], R(j), R(k)});
  return V;
}

BSpline<R> unit_box(std::vector<R> lo, std::vector<R> hi) { return box_cells<R>(lo, hi).front(); }

/// Figure 1 b of papers/002, as tests/vrep/test_trivariate.cpp builds it: the quadratic identity
/// cube on knots (0, 1/3, 2/3, 1) with three inner control points of the top layer pulled up to
/// z = 9/5.
BSpline<R> figure_1b() {
  BSpline<R> C;
  C.degrees = {2, 2, 2};
  const std::vector<R> U{0, 0, 0, R(1, 3), R(2, 3), 1, 1, 1};
  C.knots = {U, U, U};
  C.q = 3;
  const R g[5] = {R(0), R(1, 6), R(1, 2), R(5, 6), R(1)};  // Greville abscissae
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) C.points.insert(C.points.end(), {g[i], g[j], g[k]});
  const std::size_t n = 5;
  for (const auto& [i, j] : std::vector<std::pair<std::size_t, std::size_t>>{{1, 1}, {2, 1}, {1, 2}}) C.points[(i + n * (j + n * 3)) * 3 + 2] = R(9, 5);
  return C;
}

/// The ordinary regularity check of a singular trivariate (test_trivariate.cpp): singular, with
/// witnesses whose independent determinants are 0 or of opposite signs.
bool certified_singular_with_witnesses(const BSpline<R>& V) {
  const auto rep = certify_regularity(V);
  if (!rep.verdict.is_refuted() || rep.point.size() != 3) return false;
  const R a = det_at(V, rep.point);
  if (rep.other.empty()) return a == 0;
  const R b = det_at(V, rep.other);
  return (a < 0 && 0 < b) || (b < 0 && 0 < a);
}

R model_volume(const VModel<R>& M) {
  R v(0);
  for (std::size_t c = 0; c < M.cells.size(); ++c) v += cell_volume(M, c);
  return v;
}

/// g >= 0 for g = x + 8 y^2 - 8 y - 1/2 (independent of z): on every face z = const of the unit
/// box, two pieces (near y = 0 and y = 1, where x >= 1/2 - 8 y (1 - y)); the line y = 1/2 lies
/// outside (g = x - 5/2 < 0 for x <= 1), so the pieces are apart.
Region<R> two_tongues() {
  Poly3<R> g;
  g.terms[{1, 0, 0}] = R(1);
  g.terms[{0, 2, 0}] = R(8);
  g.terms[{0, 1, 0}] = R(-8);
  g.terms[{0, 0, 0}] = R(-1, 2);
  return region_leaf(g, "two tongues");
}

const TrimmedTopology<R>::Surface& face_surface(const TrimmedTopology<R>& t, int dir, int side) {
  for (const auto& s : t.surfaces)
    if (s.dir == dir && s.side == side) return s;
  throw std::logic_error("no such face");
}

/// A trimmed model whose two contact halves have different piece counts (a region written by hand,
/// larger than its cells, as docs/vrep/model.md says documents must not be): A = [0,1]^3; B's trivariate
/// [1/2,2] x [0,1]^2 trimmed to x >= 1, y <= 1/3; the region A u [1,2]x[0,1/3]x[0,1] u
/// [1,2]x[2/3,1]x[0,1]. A's face x = 1 has the model on its other side in 2 pieces (y <= 1/3,
/// y >= 2/3), B's surface x = 1 in 1 (y <= 1/3, against A). One set cannot have 2 and 1 pieces:
/// the match must be refused.
TrimmedModel<R> mismatched_contact() {
  TrimmedModel<R> M;
  M.trivariates = {unit_box({0, 0, 0}, {1, 1, 1}), unit_box({R(1, 2), 0, 0}, {2, 1, 1})};
  TrimmedModel<R>::Cell a, b;
  a.trivariate = 0;
  a.trim = region_and<R>({});
  a.name = "A";
  b.trivariate = 1;
  b.trim = region_and<R>({test::above(0, R(1)), region_not(test::above(1, R(1, 3)))});
  b.name = "B";
  b.status = Truth::mixed;
  M.cells = {a, b};
  M.region = region_or<R>({box_region<R>({0, 0, 0}, {1, 1, 1}), box_region<R>({1, 0, 0}, {2, R(1, 3), 1}), box_region<R>({1, R(2, 3), 0}, {2, 1, 1})});
  return M;
}

/// The contact twin between A's face x = 1 (cell 0, dir 0, side 1) and B's trimming surface.
const TrimmedGluing<R>::Twin* contact_twin(const TrimmedGluing<R>& G) {
  for (const auto& t : G.twins) {
    if (t.how.rfind("contact", 0) != 0) continue;
    const auto& a = G.halves[t.a];
    const auto& b = G.halves[t.b];
    if ((a.cell == 0 && a.dir == 0 && a.side == 1 && b.cell == 1 && b.leaf >= 0) || (b.cell == 0 && b.dir == 0 && b.side == 1 && a.cell == 1 && a.leaf >= 0))
      return &t;
  }
  return nullptr;
}

/// A cell on [1,2] x [0,1]^2 whose face x = 1 bulges into x > 1 (biquadratic, the middle control
/// point at x = 3/2) with straight edges: it meets [0,1]^3 only in the four edges of that face.
BSpline<R> bulged_neighbour() {
  BSpline<R> V;
  V.degrees = {1, 2, 2};
  V.knots = {{0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  V.q = 3;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 2; ++i) {
        const R x = i == 1 ? R(2) : (j == 1 && k == 1 ? R(3, 2) : R(1));
        V.points.insert(V.points.end(), {x, R(j, 2), R(k, 2)});
      }
  return V;
}

}  // namespace

TEST_CASE("vrep planted: the environment plant, when given, is a known name") {
  const char* name = std::getenv("SPLINEX_VREP_PLANT");
  if (name) {
    INFO("SPLINEX_VREP_PLANT=" << name);
    CHECK(kEnvironmentPlant);
  }
  // The seam restores what was planted before it.
  const Plant before = vrep_testing::planted;
  {
    ScopedPlant p(Plant::euler_monotone_sign);
    CHECK(vrep_testing::is_planted(Plant::euler_monotone_sign));
    {
      ScopedPlant q(Plant::none);
      CHECK(vrep_testing::planted == Plant::none);
    }
    CHECK(vrep_testing::planted == Plant::euler_monotone_sign);
  }
  CHECK(vrep_testing::planted == before);
}

TEST_CASE("vrep planted: regularity read from the corners alone certifies a folded cell") {
  const auto V = folded_cubic();
  // Independently: det J = x'(u) from the kernel's derivatives, positive at the corners, -9/4 inside.
  CHECK(det_at(V, {R(0), R(0), R(0)}) == 54);
  CHECK(det_at(V, {R(1), R(1), R(1)}) == 4);
  CHECK(det_at(V, {R(3, 4), R(1, 2), R(1, 2)}) == R(-9, 4));
  {
    ScopedPlant off(Plant::none);
    const auto rep = certify_regularity(V);
    REQUIRE(rep.verdict.is_refuted());
    REQUIRE_FALSE(rep.other.empty());
    CHECK(det_at(V, rep.point) * det_at(V, rep.other) < 0);  // the witnesses, confirmed
    CHECK_THROWS_AS(validate_cells({V}, {"fold"}, "vmodel"), ValidationError);
    CHECK(certified_singular_with_witnesses(figure_1b()));
  }
  {
    ScopedPlant on(Plant::regularity_corners_only);
    const auto rep = certify_regularity(V);
    CHECK(rep.verdict.is_proved());  // wrong: det J(3/4, 1/2, 1/2) = -9/4 < 0
    CHECK(rep.sign == 1);
    CHECK_NOTHROW(validate_cells({V}, {"fold"}, "vmodel"));  // the fold passes validation
    // Figure 1 b of the ordinary test (test_trivariate.cpp) still comes out singular: its sign
    // change shows at corners of its Bezier pieces, so only a fold strictly inside a piece, as
    // here, refutes this plant.
    CHECK(certified_singular_with_witnesses(figure_1b()));
  }
}

TEST_CASE("vrep planted: regularity with the upper-u subdivision boxes dropped certifies a folded cell") {
  const auto V = folded_cubic();  // folded only for 3/5 < u < 9/10: inside the dropped half
  {
    ScopedPlant off(Plant::none);
    CHECK(certify_regularity(V).verdict.is_refuted());
    CHECK(certified_singular_with_witnesses(V));
  }
  {
    ScopedPlant on(Plant::regularity_drops_upper_u);
    const auto rep = certify_regularity(V);
    CHECK(rep.verdict.is_proved());  // wrong: det J(3/4, 1/2, 1/2) = -9/4
    CHECK(det_at(V, {R(3, 4), R(1, 2), R(1, 2)}) < 0);
    CHECK_FALSE(certified_singular_with_witnesses(V));
    CHECK_NOTHROW(validate_cells({V}, {"fold"}, "vmodel"));
  }
}

TEST_CASE("vrep planted: a flipped sign of det J is refuted by the kernel's derivatives") {
  const auto C = unit_box({0, 0, 0}, {1, 2, 3});  // det J = 6 in its parameters [0,1]^3
  const std::vector<R> centre{R(1, 2), R(1, 2), R(1, 2)};
  CHECK(det_at(C, centre) == 6);
  {
    ScopedPlant off(Plant::none);
    const auto rep = certify_regularity(C);
    CHECK(rep.verdict.is_proved());
    CHECK(rep.sign == 1);
  }
  {
    ScopedPlant on(Plant::regularity_sign_flipped);
    const auto rep = certify_regularity(C);
    CHECK(rep.verdict.is_proved());
    CHECK(rep.sign == -1);  // wrong: det J = 6 > 0 at the centre
    // The ordinary test (the identity cube has sign +1, test_trivariate.cpp) fails.
    CHECK_FALSE(rep.sign * det_at(C, centre) > 0);
  }
}

TEST_CASE("vrep planted: point and piece classification with a half-space skipped") {
  const auto M = glue(box_cells<R>({0, 0, 0}, {1, 1, 1}));
  const std::vector<R> outside{R(3, 2), R(1, 2), R(1, 2)};  // x = 3/2 > 1, the box's largest x
  // A = [0,3] x [0,1]^2, B = [1,2] x [0,1]^2: A n B = B, volume exactly 1.
  const auto A = glue(box_cells<R>({0, 0, 0}, {3, 1, 1}));
  const auto B = glue(box_cells<R>({1, 0, 0}, {2, 1, 1}));
  {
    ScopedPlant off(Plant::none);
    CHECK(cells_containing(M, outside).empty());
    CHECK(cells_containing(M, {R(1, 2), R(1, 2), R(1, 2)}) == std::vector<std::size_t>{0});
    CHECK(model_volume(boolean_op(A, B, BooleanOp::intersect)) == 1);
    CHECK(model_volume(boolean_op(A, B, BooleanOp::subtract)) == 2);
  }
  {
    ScopedPlant on(Plant::classify_skips_plane);
    CHECK(cells_containing(M, outside) == std::vector<std::size_t>{0});  // wrong: x = 3/2 is outside [0, 1]
    // The Boolean keeps A's piece [2,3] as inside B: vol(A n B) = 2, not 1 (the ordinary volume
    // test, test_boolean.cpp, fails).
    CHECK(model_volume(boolean_op(A, B, BooleanOp::intersect)) == 2);
    CHECK_FALSE(model_volume(boolean_op(A, B, BooleanOp::subtract)) == 2);
  }
}

TEST_CASE("vrep planted: a cell classified on its region localized from its first Bezier piece only") {
  // [0,2] x [0,1]^2 with a knot at u = 1/2 (x = 1): two Bezier pieces; the region x <= 3/2 holds
  // on the first and cuts the second.
  const auto V = insert_knot(unit_box({0, 0, 0}, {2, 1, 1}), 0, R(1, 2));
  const auto region = region_not(test::above(0, R(3, 2)));
  const std::vector<R> far = evaluate(V, {R(7, 8), R(1, 2), R(1, 2)});
  CHECK(far == std::vector<R>{R(7, 4), R(1, 2), R(1, 2)});
  CHECK(classify_point(region, far) == Truth::out);  // independently: a point of the cell outside the region
  {
    ScopedPlant off(Plant::none);
    const auto cls = classify_cell(V, region);
    CHECK(cls.kind == CellClass<R>::cut);
    REQUIRE(cls.outside.size() == 3);
    CHECK(classify_point(region, evaluate(V, cls.outside)) == Truth::out);
    // The trimmed Boolean keeps it as a cut cell.
    const auto I = trimmed_boolean(as_trimmed(glue(std::vector<BSpline<R>>{V}), box_region<R>({0, 0, 0}, {2, 1, 1})),
                                   as_trimmed(glue(box_cells<R>({-1, -1, -1}, {R(3, 2), 2, 2})), box_region<R>({-1, -1, -1}, {R(3, 2), 2, 2})),
                                   BooleanOp::intersect);
    REQUIRE(I.cells.size() == 1);
    CHECK(I.cells[0].status == Truth::mixed);
  }
  {
    ScopedPlant on(Plant::classify_first_piece_only);
    const auto cls = classify_cell(V, region);
    CHECK(cls.kind == CellClass<R>::whole);  // wrong: V(7/8, 1/2, 1/2) = (7/4, 1/2, 1/2) lies outside
    const auto I = trimmed_boolean(as_trimmed(glue(std::vector<BSpline<R>>{V}), box_region<R>({0, 0, 0}, {2, 1, 1})),
                                   as_trimmed(glue(box_cells<R>({-1, -1, -1}, {R(3, 2), 2, 2})), box_region<R>({-1, -1, -1}, {R(3, 2), 2, 2})),
                                   BooleanOp::intersect);
    REQUIRE(I.cells.size() == 1);
    CHECK(I.cells[0].status == Truth::in);  // the whole cell kept: volume 2 where the intersection has 3/2
  }
}

TEST_CASE("vrep planted: face pieces counted with a leaf taken as one arc without counting its roots") {
  const auto V = unit_box({0, 0, 0}, {1, 1, 1});
  const auto trim = two_tongues();
  // Independently: (3/4, 0, 0) and (3/4, 1, 0) are in the region, the line y = 1/2 of the face
  // z = 0 is not (g = x - 5/2 < 0): at least two pieces; g >= 0 needs y (1 - y) <= 1/16, so no more.
  CHECK(classify_point(trim, {R(3, 4), R(0), R(0)}) == Truth::in);
  CHECK(classify_point(trim, {R(3, 4), R(1), R(0)}) == Truth::in);
  // The same cell as a one-cell trimmed model: every face piece is a boundary V-surface.
  TrimmedModel<R> M = as_trimmed(glue(std::vector<BSpline<R>>{V}), region_and<R>({box_region<R>({0, 0, 0}, {1, 1, 1}), trim}));
  M.cells[0].trim = trim;
  TrimmedGlueOptions o;
  o.max_boxes = 2048;
  auto z0 = [](const TrimmedGluing<R>& G) {
    for (const auto& h : G.halves)
      if (h.dir == 2 && h.side == 0) return h.boundary;
    return std::size_t(99);
  };
  {
    ScopedPlant off(Plant::none);
    const auto t = trimmed_topology(V, trim, 2048);
    const auto& f = face_surface(t, 2, 0);
    INFO(f.undecided_reason);
    REQUIRE(f.decided);
    CHECK(f.pieces == 2);
    CHECK(f.at_least == 2);
    CHECK(face_surface(t, 0, 1).pieces == 2);  // x = 1: y <= 1/2 - sqrt(3)/4 or y >= 1/2 + sqrt(3)/4
    CHECK(face_surface(t, 1, 0).pieces == 1);  // y = 0: x >= 1/2
    const auto G = trimmed_glue(M, o);
    CHECK(G.decided);
    CHECK(z0(G) == 2);
  }
  {
    ScopedPlant on(Plant::region_arc_unchecked);
    // The gluing counts the face with count_region alone: 1 boundary V-surface where there are 2.
    const auto G = trimmed_glue(M, o);
    CHECK(G.decided);
    CHECK(z0(G) == 1);  // wrong
    // trimmed_topology cross-checks the exact count against its certified lower bound (points in
    // separate components of the cover) and refuses the wrong count as an internal error.
    CHECK_THROWS_WITH(trimmed_topology(V, trim, 2048), Catch::Contains("below the certified lower bound (2)"));
  }
}

TEST_CASE("vrep planted: trimming-surface pieces counted without checking that the sides are contractible") {
  // The unit box trimmed to (z - 1/3)(z - 2/3) >= 0: two slabs; the trimming surface bounds the
  // cell in two planes z = 1/3 and z = 2/3. Independently: the points (1/2, 1/2, 1/3) and
  // (1/2, 1/2, 2/3) are on it, and the plane z = 1/2 between them is outside the cell.
  const auto V = unit_box({0, 0, 0}, {1, 1, 1});
  Poly3<R> g;
  g.terms[{0, 0, 2}] = R(1);
  g.terms[{0, 0, 1}] = R(-1);
  g.terms[{0, 0, 0}] = R(2, 9);
  const auto trim = region_leaf(g, "two planes");
  CHECK(poly_at(g, std::vector<R>{R(1, 2), R(1, 2), R(1, 3)}.data()) == 0);
  CHECK(poly_at(g, std::vector<R>{R(1, 2), R(1, 2), R(2, 3)}.data()) == 0);
  CHECK(classify_point(trim, {R(1, 5), R(4, 5), R(1, 2)}) == Truth::out);
  TrimmedModel<R> M = as_trimmed(glue(std::vector<BSpline<R>>{V}), region_and<R>({box_region<R>({0, 0, 0}, {1, 1, 1}), trim}));
  M.cells[0].trim = trim;
  TrimmedGlueOptions o;
  o.max_boxes = 2048;
  auto surface = [](const TrimmedGluing<R>& G) {
    for (const auto& h : G.halves)
      if (h.leaf == 0) return h.boundary;
    return std::size_t(99);
  };
  {
    ScopedPlant off(Plant::none);
    const auto t = trimmed_topology(V, trim, 2048);
    for (const auto& s : t.surfaces)
      if (s.leaf == 0) {
        REQUIRE(s.decided);
        CHECK(s.pieces == 2);
      }
    const auto G = trimmed_glue(M, o);
    CHECK(G.decided);
    CHECK(surface(G) == 2);
  }
  {
    ScopedPlant on(Plant::surface_shape_unchecked);
    const auto G = trimmed_glue(M, o);
    INFO("pieces under the plant: " << surface(G));
    CHECK(G.decided);
    CHECK(surface(G) == 1);  // wrong: two planes
    CHECK_THROWS_WITH(trimmed_topology(V, trim, 2048), Catch::Contains("below the certified lower bound (2)"));
  }
}

TEST_CASE("vrep planted: the Euler characteristic with the monotone step's sign flipped") {
  // A box with a spherical cavity: chi = 2 (b0 = 1, b2 = 1); a solid ball: 1.
  const auto V = unit_box({0, 0, 0}, {2, 2, 2});
  const auto cavity = region_not(test::ball({R(1), R(1), R(1)}, R(1, 2)));
  {
    ScopedPlant off(Plant::none);
    const auto e = trimmed_euler(V, cavity);
    REQUIRE(e.decided);
    CHECK(e.chi == 2);
    CHECK(e.duality);
  }
  {
    ScopedPlant on(Plant::euler_monotone_sign);
    const auto e = trimmed_euler(V, cavity);
    REQUIRE(e.decided);
    CHECK(e.chi != 2);  // wrong (-22)
    INFO("chi under the plant: " << e.chi);
  }
}

TEST_CASE("vrep planted: the Euler characteristic with the open face between halves dropped") {
  const auto V = unit_box({0, 0, 0}, {2, 2, 2});
  const auto cavity = region_not(test::ball({R(1), R(1), R(1)}, R(1, 2)));
  {
    ScopedPlant off(Plant::none);
    const auto e = trimmed_euler(V, cavity);
    REQUIRE(e.decided);
    CHECK(e.chi == 2);
  }
  {
    ScopedPlant on(Plant::euler_drops_mid_face);
    const auto e = trimmed_euler(V, cavity);
    INFO("chi under the plant: " << e.chi << ", interior " << e.interior_chi_c);
    CHECK_FALSE((e.decided && e.chi == 2));  // wrong (or no answer)
  }
}

TEST_CASE("vrep planted: trimmed gluing matches two contact halves whose piece counts differ") {
  const auto M = mismatched_contact();
  TrimmedGlueOptions o;
  o.max_boxes = 2048;
  {
    ScopedPlant off(Plant::none);
    const auto G = trimmed_glue(M, o);
    // The halves' internal pieces, counted by hand: A's face x = 1: 2; B's surface x = 1: 1.
    std::size_t a_face = 99, b_surface = 99;
    for (const auto& h : G.halves) {
      if (h.cell == 0 && h.dir == 0 && h.side == 1) a_face = h.unmatched;
      if (h.cell == 1 && h.leaf >= 0 && h.internal > 0) b_surface = h.unmatched;
    }
    CHECK(a_face == 2);
    CHECK(b_surface == 1);
    const auto* t = contact_twin(G);
    REQUIRE(t);
    CHECK_FALSE(t->decided);
    CHECK_FALSE(t->undecided_reason.empty());
    CHECK_FALSE(G.decided);
  }
  {
    ScopedPlant on(Plant::glue_counts_ignored);
    const auto G = trimmed_glue(M, o);
    const auto* t = contact_twin(G);
    REQUIRE(t);
    CHECK(t->decided);  // wrong: one set of 2 and 1 pieces
    CHECK(t->pieces == 2);
    CHECK(G.decided);  // and the whole gluing claims to be decided
  }
  // The ordinary test of a decided gluing (test_trimmed_glue.cpp's Figure 3) is unchanged: its
  // contact halves have equal counts, so this plant needs the case above.
}

TEST_CASE("vrep planted: V-model gluing twins faces by their loop without comparing the surfaces") {
  // [0,1]^3 and a neighbour whose face x = 1 bulges away from it: they share the face's four
  // edges and nothing else. A u B is two balls glued along a circle: chi = 1 + 1 - 0 = 2.
  const std::vector<BSpline<R>> cells{unit_box({0, 0, 0}, {1, 1, 1}), bulged_neighbour()};
  CHECK(evaluate(cells[1], {R(0), R(1, 2), R(1, 2)})[0] == R(9, 8));  // the face's centre is not on A's face x = 1
  {
    ScopedPlant off(Plant::none);
    const auto M = glue(cells);
    CHECK(check_invariants(M).ok());
    CHECK(M.internal_surfaces() == 0);
    CHECK(M.euler_characteristic() == 2);
  }
  {
    ScopedPlant on(Plant::vmodel_twin_by_loop);
    const auto M = glue(cells);
    CHECK(check_invariants(M).ok());  // the invariants hold
    CHECK(M.internal_surfaces() == 1);
    CHECK(M.euler_characteristic() == 1);  // wrong: 2
  }
}

TEST_CASE("vrep planted: validation with the pair sweep stopping early accepts overlapping cells") {
  struct Case {
    const char* what;
    std::vector<BSpline<R>> cells;
    std::vector<R> common;  // a point strictly inside both cells (parameters strictly inside both)
  };
  const std::vector<Case> cases{
      {"duplicated", {unit_box({0, 0, 0}, {1, 1, 1}), unit_box({0, 0, 0}, {1, 1, 1})}, {R(1, 2), R(1, 2), R(1, 2)}},
      {"contained", {unit_box({0, 0, 0}, {1, 1, 1}), unit_box({R(1, 4), R(1, 4), R(1, 4)}, {R(3, 4), R(3, 4), R(3, 4)})}, {R(1, 2), R(1, 2), R(1, 2)}},
      // (Not [1/2, 3/2] x [0,1]^2: its corners lie inside the other's edges, which the conformity
      // check refuses on its own; these corners lie inside the other cell.)
      {"overlapping", {unit_box({0, 0, 0}, {1, 1, 1}), unit_box({R(1, 2), R(-1, 2), R(-1, 2)}, {R(3, 2), R(3, 2), R(3, 2)})}, {R(3, 4), R(1, 2), R(1, 2)}},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    // Independently: the common point is strictly inside both boxes (each cell's corners bound it).
    for (const auto& V : c.cells) {
      const auto lo = evaluate(V, {R(0), R(0), R(0)}), hi = evaluate(V, {R(1), R(1), R(1)});
      for (int d = 0; d < 3; ++d) CHECK((lo[d] < c.common[d] && c.common[d] < hi[d]));
    }
    {
      ScopedPlant off(Plant::none);
      CHECK_THROWS_AS(validate_cells(c.cells, {"a", "b"}, "vmodel"), ValidationError);
    }
    {
      ScopedPlant on(Plant::validate_sweep_bound);
      const auto rep = validate_cells(c.cells, {"a", "b"}, "vmodel");  // wrong: no exception
      CHECK(rep.pairs_tested == 0);
      CHECK(rep.verdict() == "valid");
    }
  }
}

TEST_CASE("vrep planted: validation without the corner-in-edge test accepts a partial edge contact") {
  // [0,1]^3 and [1,2] x [1,2] x [1/2,2] touch along x = y = 1, 1/2 <= z <= 1 (tests/data/repro/vrep
  // edge_a, edge_b): the point set's chi is 1 + 1 - 1 = 1 (they meet in a segment), the glued
  // model's 2, so gluing them as they are is wrong.
  const std::vector<BSpline<R>> cells{unit_box({0, 0, 0}, {1, 1, 1}), unit_box({1, 1, R(1, 2)}, {2, 2, 2})};
  {
    ScopedPlant off(Plant::none);
    CHECK_THROWS_AS(validate_vmodel(glue(cells), "vmodel"), ValidationError);
  }
  {
    ScopedPlant on(Plant::validate_corner_in_edge);
    const auto M = glue(cells);
    const auto rep = validate_vmodel(M, "vmodel");  // wrong: accepted
    CHECK(rep.verdict() == "valid");
    CHECK(M.euler_characteristic() == 2);  // and its chi is not the point set's 1
  }
}

TEST_CASE("vrep planted: validation that lets a flat cell pass, or an interior zero of det J") {
  // tests/data/repro/vrep/flat.json: the unit square's trivariate with its top layer on z = 0.
  BSpline<R> flat = unit_box({0, 0, 0}, {1, 1, 1});
  for (std::size_t i = 0; i < flat.size(); ++i) flat.points[i * 3 + 2] = R(0);
  // twisted.json: the top face turned half a turn, det J = (1 - 2w)^2, 0 on the plane w = 1/2,
  // which the cell maps to the single point (1/2, 1/2, 1/2).
  BSpline<R> twisted = unit_box({0, 0, 0}, {1, 1, 1});
  for (std::size_t i = 4; i < 8; ++i) {
    twisted.points[i * 3] = R(1) - twisted.points[i * 3];
    twisted.points[i * 3 + 1] = R(1) - twisted.points[i * 3 + 1];
  }
  // Independently: neither cell is injective on its interior.
  CHECK(evaluate(flat, {R(1, 2), R(1, 2), R(1, 4)}) == evaluate(flat, {R(1, 2), R(1, 2), R(3, 4)}));
  CHECK(evaluate(twisted, {R(1, 4), R(1, 4), R(1, 2)}) == evaluate(twisted, {R(3, 4), R(3, 4), R(1, 2)}));
  CHECK(det_at(twisted, {R(1, 2), R(1, 2), R(1, 2)}) == 0);
  CHECK(det_at(flat, {R(1, 2), R(1, 2), R(1, 2)}) == 0);
  {
    ScopedPlant off(Plant::none);
    CHECK_THROWS_WITH(validate_cells({flat}, {"flat"}, "vmodel"), Catch::Contains("is flat"));
    CHECK_THROWS_WITH(validate_cells({twisted}, {"twisted"}, "vmodel"), Catch::Contains("is not regular inside"));
  }
  {
    ScopedPlant on(Plant::validate_flat_skipped);
    const auto rep = validate_cells({flat}, {"flat"}, "vmodel");  // wrong: accepted
    CHECK(rep.decided());
    CHECK(rep.degenerate.size() == 1);
  }
  {
    ScopedPlant on(Plant::validate_interior_zero);
    const auto rep = validate_cells({twisted}, {"twisted"}, "vmodel");  // wrong: accepted as degenerate
    CHECK(rep.decided());
    CHECK(rep.degenerate.size() == 1);
  }
}
