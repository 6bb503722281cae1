// Trimming by freeform solids (issue 18, papers/002 Figures 10 and 14): solids known only by their
// trivariates. Point membership against the implicit oracle, volumes against closed forms and the
// implicit path, certified component counts, the teapot's handle meeting its body twice.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "fixtures/teapot.hpp"
#include "fixtures/teapot_vmodel.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/freeform/freeform.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

using namespace splinex;
using R = Rational;

namespace {

const R pi_lo = R(314159265) / R(100000000), pi_hi = R(314159266) / R(100000000);

BSpline<R> box(std::vector<R> lo, std::vector<R> hi) { return box_cells<R>(lo, hi).front(); }

FreeformCell<R> cell(const BSpline<R>& V, std::vector<FreeformCondition<R>> c, std::size_t boxes) {
  FreeformOptions o;
  o.max_boxes = boxes;
  return freeform_cell(V, c, o);
}

}  // namespace

TEST_CASE("vrep freeform: a glued solid's boundary leaves out its inner faces, points agree with the exact implicit region") {
  const auto S = freeform_solid<R>("cylinder", cylinder_cells<R>(R(1), R(2)));
  CHECK(S.faces == 30);
  CHECK(S.inner_faces == 16);  // eight glued pairs: square and sectors, sectors and their neighbours
  // Exact answers on both sides of the curved boundary and on it.
  CHECK(classify_point_freeform(S, {R(0), R(0), R(1)}) == Truth::in);
  CHECK(classify_point_freeform(S, {R(7, 10), R(7, 10), R(1)}) == Truth::in);    // 0.98 < 1
  CHECK(classify_point_freeform(S, {R(71, 100), R(71, 100), R(1)}) == Truth::out);  // 1.0082 > 1
  CHECK(classify_point_freeform(S, {R(3, 5), R(4, 5), R(1)}) == Truth::mixed);     // on the side: 9/25 + 16/25 = 1
  CHECK(classify_point_freeform(S, {R(0), R(0), R(2)}) == Truth::mixed);           // on the top
  CHECK(classify_point_freeform(S, {R(0), R(0), R(5, 2)}) == Truth::out);
  // Random points against the implicit region (an independent exact oracle: x^2 + y^2 <= 1, 0 <= z <= 2).
  const auto implicit = cylinder_region<R>(R(1), R(2));
  std::mt19937 rng(18);
  std::uniform_int_distribution<int> coord(-120, 120), height(-20, 220);
  int in = 0, out = 0;
  for (int k = 0; k < 40; ++k) {
    const std::vector<R> x{R(coord(rng), 100), R(coord(rng), 100), R(height(rng), 100)};
    const Truth want = classify_point(implicit, x);
    const Truth got = classify_point_freeform(S, x);
    INFO(x[0] << ", " << x[1] << ", " << x[2]);
    if (want == Truth::mixed) CHECK(got == Truth::mixed);
    else CHECK(got == want);
    in += got == Truth::in;
    out += got == Truth::out;
  }
  CHECK(in > 5);
  CHECK(out > 5);
}

TEST_CASE("vrep freeform: boxes cut by a freeform box: exact volumes enclosed, the two sides add up") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto U = freeform_solid<R>("U", {box({R(1, 3), R(-1), R(-1)}, {R(3), R(3), R(3)})});
  const auto inside = cell(V, {{&U, true}}, 1024), outside = cell(V, {{&U, false}}, 1024);
  CHECK(inside.cls.kind == CellClass<R>::cut);
  CHECK(outside.cls.kind == CellClass<R>::cut);
  CHECK(inside.volume.lower <= R(20, 3));
  CHECK(R(20, 3) <= inside.volume.upper);
  CHECK(outside.volume.lower <= R(4, 3));
  CHECK(R(4, 3) <= outside.volume.upper);
  // The enclosure narrows with the budget.
  const auto coarse = cell(V, {{&U, true}}, 256);
  CHECK(inside.volume.upper - inside.volume.lower < coarse.volume.upper - coarse.volume.lower);
  CHECK(inside.volume.lower + outside.volume.lower <= R(8));
  CHECK(R(8) <= inside.volume.upper + outside.volume.upper);
  CHECK(inside.components == 1);
  CHECK(outside.components == 1);
  // No condition: the whole trivariate, its volume exactly.
  const auto whole = cell(V, {}, 64);
  CHECK(whole.cls.kind == CellClass<R>::whole);
  CHECK(whole.volume.lower == R(8));
  CHECK(whole.volume.upper == R(8));
  // Disjoint: empty, volume 0.
  const auto far = freeform_solid<R>("far", {box({R(5), R(5), R(5)}, {R(6), R(6), R(6)})});
  const auto none = cell(V, {{&far, true}}, 64);
  CHECK(none.cls.kind == CellClass<R>::empty);
  CHECK(none.volume.upper == R(0));
  CHECK(none.components == 0);
}

TEST_CASE("vrep freeform: same_boxes tells a double run that decided every box as the exact one from planted differences") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  // Dyadic data: the double run reads exactly the exact run's input.
  const auto U = freeform_solid<R>("U", {box({R(1, 4), R(-1), R(-1)}, {R(3), R(3), R(3)})});
  const auto e = cell(V, {{&U, true}}, 256);
  const auto Vd = box_cells<double>({0, 0, 0}, {2, 2, 2}).front();
  const auto Ud = freeform_solid<double>("U", {box_cells<double>({0.25, -1, -1}, {3, 3, 3}).front()});
  FreeformOptions o;
  o.max_boxes = 256;
  const auto d = freeform_cell(Vd, {{&Ud, true}}, o);
  REQUIRE(e.boxes.size() > 2);
  CHECK(same_boxes(e, d));
  auto moved = d;  // one bound an ulp off
  moved.boxes[1].hi[0] = std::nextafter(moved.boxes[1].hi[0], 10.0);
  CHECK_FALSE(same_boxes(e, moved));
  auto flipped = d;  // one truth changed
  flipped.boxes[0].truth = flipped.boxes[0].truth == Truth::in ? Truth::mixed : Truth::in;
  CHECK_FALSE(same_boxes(e, flipped));
  auto fewer = d;  // one box missing
  fewer.boxes.pop_back();
  CHECK_FALSE(same_boxes(e, fewer));
  auto swapped = d;  // the same boxes in another order
  std::swap(swapped.boxes.front(), swapped.boxes.back());
  CHECK(same_boxes(e, swapped));
  auto doubled = d;  // a box twice in place of another
  doubled.boxes.back() = doubled.boxes.front();
  CHECK_FALSE(same_boxes(e, doubled));
}

TEST_CASE("vrep freeform: component counts are certified lower bounds (two slabs through a bar)") {
  const auto V = box({R(0), R(0), R(0)}, {R(4), R(1), R(1)});
  const auto U = freeform_solid<R>("slabs", {box({R(1, 3), R(-1), R(-1)}, {R(4, 3), R(2), R(2)}),
                                             box({R(7, 3), R(-1), R(-1)}, {R(10, 3), R(2), R(2)})});
  CHECK(U.inner_faces == 0);
  const auto inside = cell(V, {{&U, true}}, 1024), outside = cell(V, {{&U, false}}, 1024);
  CHECK(inside.components == 2);
  CHECK(inside.cover_components == 2);
  CHECK(outside.components == 3);
  CHECK(inside.volume.lower <= R(2));
  CHECK(R(2) <= inside.volume.upper);
}

TEST_CASE("vrep freeform: a box cut by the five-cell cylinder: pi / 12 enclosed, agreeing with the implicit path") {
  const auto V = box({R(0), R(0), R(1, 3)}, {R(2), R(2), R(2, 3)});
  const auto C = freeform_solid<R>("cylinder", cylinder_cells<R>(R(1), R(1)));
  const auto r = cell(V, {{&C, true}}, 2048);
  CHECK(r.cls.kind == CellClass<R>::cut);
  CHECK(r.volume.lower <= pi_lo / R(12));
  CHECK(pi_hi / R(12) <= r.volume.upper);
  CHECK(r.volume.upper - r.volume.lower < R(1, 10));
  const auto implicit = trimmed_volume(V, cylinder_region<R>(R(1), R(1)), 2048);
  CHECK(implicit.lower <= r.volume.upper);
  CHECK(r.volume.lower <= implicit.upper);
  CHECK(r.components == 1);
}

TEST_CASE("vrep freeform: the edges of trimmed cells, exactly: crossings by the solver, runs by point queries") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto U = freeform_solid<R>("U", {box({R(1, 3), R(-1), R(-1)}, {R(3), R(3), R(3)})});
  const auto e = freeform_edges<R>(V, {{&U, true}});
  CHECK(e.corners == 4);
  std::size_t pieces = 0, points = 0;
  for (const auto& x : e.edges) {
    CHECK(x.status == FreeformEdges<R>::Edge::curve);
    pieces += x.pieces;
    points += x.points;
    if (x.along == 0) {
      REQUIRE(x.cuts.size() == 1);
      CHECK(x.cuts[0].first == R(1, 6));  // x = 2u = 1/3, an exact rational root
      CHECK(x.cuts[0].second == R(1, 6));
    }
  }
  CHECK(pieces == 8);
  CHECK(points == 4);
  // The same slice against the five-cell cylinder: the edges along x and y at the axis cross the
  // side at x = 1 and y = 1 (parameter 1/2), the edge along z at the axis is inside.
  const auto S = box({R(0), R(0), R(1, 3)}, {R(2), R(2), R(2, 3)});
  const auto C = freeform_solid<R>("cylinder", cylinder_cells<R>(R(1), R(1)));
  const auto c = freeform_edges<R>(S, {{&C, true}});
  CHECK(c.corners == 2);
  pieces = points = 0;
  for (const auto& x : c.edges) {
    CHECK(x.status == FreeformEdges<R>::Edge::curve);
    pieces += x.pieces;
    points += x.points;
    for (const auto& cut : x.cuts) {
      CHECK(cut.first <= R(1, 2));
      CHECK(R(1, 2) <= cut.second);
    }
  }
  CHECK(pieces == 5);
  CHECK(points == 4);
}

TEST_CASE("vrep freeform: a rational cell (a cylinder sector) cut by a slab: a third of its volume, enclosed") {
  const auto V = cylinder_cells<R>(R(1), R(1))[1];
  REQUIRE(V.is_rational());
  const auto slab = freeform_solid<R>("slab", {box({R(-2), R(-2), R(1, 3)}, {R(2), R(2), R(2, 3)})});
  const auto r = cell(V, {{&slab, true}}, 1024);
  const auto whole = volume_enclosure(V, 4096);
  // The sector is extruded along z linearly, so the slab holds exactly a third of it.
  CHECK(r.cls.kind == CellClass<R>::cut);
  CHECK(r.volume.lower <= whole.upper / R(3));
  CHECK(whole.lower / R(3) <= r.volume.upper);
  CHECK(r.components == 1);
}

TEST_CASE("vrep freeform: the teapot's handle meets its body in two certified components, the volumes add up (Figure 14)") {
  const auto T = teapot_solids();
  const auto B = freeform_solid<R>("body", {T.body}), H = freeform_solid<R>("handle", {T.handle}),
             C = freeform_solid<R>("cavity", {T.cavity});
  CHECK(B.inner_faces == 2);  // the seam u = 0 / u = 4 of the body of revolution
  // The handle's end corners: inside the shell with the preimage on the body's patch boundary u = 2
  // (the data's symmetry plane y = 0), certified by the face system; one is a body control point on
  // its outer surface, exactly: on the boundary.
  CHECK(classify_point_freeform(B, {R(-8, 5), R(0), R(81, 40)}) == Truth::in);
  CHECK(classify_point_freeform(B, {R(-2), R(0), R(9, 10)}) == Truth::mixed);
  CHECK(C.inner_faces == 2);
  const auto meet = cell(T.handle, {{&B, true}}, 2048);
  CHECK(meet.cls.kind == CellClass<R>::cut);
  CHECK(meet.components == 2);  // the paper's two V-cells shared by handle and body
  const auto rest = cell(T.handle, {{&B, false}, {&C, false}}, 2048);
  const auto poke = cell(T.handle, {{&C, true}}, 512);
  const auto whole = volume_enclosure(T.handle);
  REQUIRE(whole.lower == whole.upper);
  CHECK(meet.volume.lower + rest.volume.lower <= whole.lower);
  CHECK(whole.lower <= meet.volume.upper + rest.volume.upper + poke.volume.upper);
  CHECK(R(0) < meet.volume.lower);
}

TEST_CASE("vrep freeform: a cell that folds is refused with two exact points of opposite det J (the teapot's rim scaled inward)") {
  BSpline<R> body;
  for (const auto& t : teapot_surfaces(read_bpt(data_path("teapot.bpt"))))
    if (t.name == "body") body = t.surface;
  auto inner = body;
  for (std::size_t i = 0; i < inner.size(); ++i)
    for (int k = 0; k < 2; ++k) inner.points[i * 3 + k] *= R(9, 10);
  const auto rimmed = ruled(body, inner);
  CHECK_THROWS_WITH(freeform_solid<R>("rimmed", {rimmed}), Catch::Contains("folds: det J is positive at"));
  const auto U = freeform_solid<R>("U", {box({R(0), R(0), R(0)}, {R(1), R(1), R(1)})});
  CHECK_THROWS_AS(freeform_cell<R>(rimmed, {{&U, true}}), DomainError);
  // The model's body (below the rim) does not fold.
  CHECK_NOTHROW(freeform_solid<R>("body", {teapot_solids().body}));
}

TEST_CASE("vrep freeform: a fold between the grid points is refused by the certificate (issue 50)") {
  // V(u, v, w) = (f(u), v, w) with f cubic and f'(u) = (u - 1/10)(u - 3/20): det J = f'(u) is
  // positive at every u = i/4 of the 5 x 5 x 5 grid and negative on (1/10, 3/20), so the grid sees
  // one sign and (before issue 50) accepted the cell; certify_cell_shape finds both signs.
  auto cubic_in_u = [](std::vector<R> f) {
    BSpline<R> V;
    V.degrees = {3, 1, 1};
    V.knots = {{R(0), R(0), R(0), R(0), R(1), R(1), R(1), R(1)}, {R(0), R(0), R(1), R(1)}, {R(0), R(0), R(1), R(1)}};
    V.q = 3;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) V.points.insert(V.points.end(), {f[i], R(j), R(k)});
    return V;
  };
  const auto folded = cubic_in_u({R(0), R(1, 200), R(-19, 600), R(67, 300)});
  CHECK_THROWS_AS(freeform_solid<R>("thin-fold", {folded}), DomainError);  // as the grid's folds
  CHECK_THROWS_WITH(freeform_solid<R>("thin-fold", {folded}), Catch::Contains("folds: det J changes sign"));
  const auto U = freeform_solid<R>("U", {box({R(0), R(0), R(0)}, {R(1), R(1), R(1)})});
  CHECK_THROWS_AS(freeform_cell<R>(folded, {{&U, true}}), DomainError);
  // The same shape without the fold (f(u) = u, elevated to degree 3) is accepted, and so is one
  // whose det J is 0 only on a face (f'(u) = u^2: f = u^3 / 3, collapsed at u = 0).
  CHECK_NOTHROW(freeform_solid<R>("straight", {cubic_in_u({R(0), R(1, 3), R(2, 3), R(1)})}));
  CHECK_NOTHROW(freeform_solid<R>("touching", {cubic_in_u({R(0), R(0), R(0), R(1, 3)})}));
}

TEST_CASE("vrep freeform: numbers longer than Limits::max_input_bits are refused before the work, naming the field") {
  auto V = box({R(0), R(0), R(0)}, {R(1), R(1), R(1)});
  R big(1);
  for (int i = 0; i < 5000; ++i) big *= 2;  // 2^5000: 5001 bits
  V.points[3] = R(1) + R(1) / big;           // corner (1, 0, 0) moved 2^-5000 along x
  try {
    freeform_solid<R>("long", {V});
    FAIL("a 5001-bit number was accepted");
  } catch (const SizeLimitError& e) {
    CHECK(std::string(e.what()).find("long.cells[0].points") != std::string::npos);
  }
  CHECK_THROWS_AS(freeform_cell<R>(V, {}), SizeLimitError);
  Limits wide;
  wide.max_input_bits = 6000;
  CHECK_NOTHROW(freeform_solid<R>("long", {V}, wide));
  // A solid's second cell is checked before the first cell's work (a fold the grid would see).
  auto folding = V;
  folding.points[3] = R(-2);  // corner (1, 0, 0) pulled to x = -2: det J changes sign
  folding.points[4] = R(0);
  try {
    freeform_solid<R>("two", {folding, V});
    FAIL("accepted a long number");
  } catch (const SizeLimitError& e) {
    CHECK(std::string(e.what()).find("two.cells[1].points") != std::string::npos);
  }
}

TEST_CASE("vrep freeform: bad input is refused with typed errors naming the field") {
  const auto V = box({R(0), R(0), R(0)}, {R(1), R(1), R(1)});
  CHECK_THROWS_AS(freeform_solid<R>("empty", {}), ValidationError);
  auto flat = V;
  flat.degrees = {0, 1, 1};
  flat.knots[0] = {R(0), R(1)};
  flat.points.resize(12);
  CHECK_THROWS_AS(freeform_solid<R>("flat", {flat}), ValidationError);
  const auto U = freeform_solid<R>("U", {V});
  CHECK_THROWS_AS(classify_point_freeform(U, {R(0), R(0)}), ValidationError);
  CHECK_THROWS_AS(freeform_cell<R>(V, {{nullptr, true}}), ValidationError);
  FreeformOptions none;
  none.max_boxes = 0;
  CHECK_THROWS_AS(freeform_cell<R>(V, {{&U, true}}, none), ValidationError);
  auto open = V;
  open.knots[0] = {R(-1), R(0), R(1), R(2)};  // unclamped: its faces are not layers of the net
  CHECK_THROWS_AS(freeform_solid<R>("open", {open}), ValidationError);
  CHECK_THROWS_AS(freeform_cell<R>(open, {{&U, true}}), ValidationError);
}
