// The V-model (issue 17): gluing, invariants, counts and queries of the primitives, regularity of
// every cell, and what a float gluing tolerance does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <random>
#include <set>

#include "exact/rational.hpp"
#include "spline/insert.hpp"
#include "spline/kernel.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/validate.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/model/vmodel_impl.hpp"  // vrep_detail::same_net_within, corners_differ
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

using namespace splinex;
using R = Rational;

namespace {

struct Counts {
  std::size_t points, curves, surfaces, cells, internal;
  long euler;
};

template <class T>
void check_model(const VModel<T>& M, const Counts& c) {
  const auto chk = check_invariants(M);
  INFO((chk.failures.empty() ? std::string("") : chk.failures.front()));
  CHECK(chk.ok());
  CHECK(M.points.size() == c.points);
  CHECK(M.curves.size() == c.curves);
  CHECK(M.surfaces.size() == c.surfaces);
  CHECK(M.cells.size() == c.cells);
  CHECK(M.internal_surfaces() == c.internal);
  CHECK(chk.euler == c.euler);
  CHECK(M.half_surfaces.size() == 6 * c.cells);
}

/// Every cell regular, all with the same sign.
void check_regular(const std::vector<BSpline<R>>& cells) {
  int sign = 0;
  for (const auto& V : cells) {
    const auto rep = certify_regularity(V);
    REQUIRE(rep.verdict.is_proved());
    if (sign == 0) sign = rep.sign;
    CHECK(rep.sign == sign);
  }
}

}  // namespace

TEST_CASE("vmodel: the exact corner test never changes same_surface's answer, and decides only nets that differ at a corner") {
  // Random clamped surfaces (rational or not, degrees 1-3), each against a refined and elevated
  // copy, the copy with an interior point moved, the copy with a corner moved, and an unrelated
  // surface. The answer must be the common-space comparison's, which is computed here directly.
  std::mt19937_64 rng(5017);
  auto num = [&] { return R(static_cast<long>(rng() % 41) - 20, 1 + static_cast<long>(rng() % 9)); };
  auto random_surface = [&](bool rational) {
    std::vector<int> deg{1 + static_cast<int>(rng() % 3), 1 + static_cast<int>(rng() % 3)};
    std::vector<std::vector<R>> K(2);
    for (int d = 0; d < 2; ++d) {
      K[d].assign(deg[d] + 1, R(0));
      if (rng() % 2) K[d].push_back(R(2, 5));
      K[d].insert(K[d].end(), deg[d] + 1, R(1));
    }
    auto S = spline_from<R>(deg, K, 3, [&](const std::vector<std::size_t>&) { return std::vector<R>{num(), num(), num()}; });
    if (rational)
      for (std::size_t i = 0; i < S.size(); ++i) S.weights.push_back(R(1 + static_cast<long>(rng() % 5), 1 + static_cast<long>(rng() % 3)));
    return S;
  };
  auto common_space_equal = [](const BSpline<R>& a, BSpline<R> b) {
    BSpline<R> x = a;
    if (x.is_rational() != b.is_rational()) {
      if (!x.is_rational()) x.weights.assign(x.size(), R(1));
      if (!b.is_rational()) b.weights.assign(b.size(), R(1));
    }
    const auto [A, B] = make_compatible(x, b);
    return A.points == B.points && A.weights == B.weights;
  };
  int same = 0, by_corner = 0, by_space = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const auto S = random_surface(trial % 2 == 1);
    auto C = elevate_degree(refine_knots(S, 0, {R(1, 3), R(5, 7)}), 1, 1);
    auto interior = C, corner = C;
    interior.points[(1 + C.count(0) * 1) * 3 + 2] += R(1, 1000);
    corner.points[(C.count(0) - 1) * 3] += R(1, 1000);  // the corner (u = 1, v = 0)
    for (const auto* other : {&C, &interior, &corner}) {
      const bool expected = common_space_equal(S, *other), got = vrep_detail::same_net_within(S, *other, R(0), Limits{});
      CHECK(got == expected);
      if (vrep_detail::corners_differ(S, *other, R(0))) {
        CHECK_FALSE(expected);  // the corner test decides only what the common space would
        ++by_corner;
      } else if (!expected) {
        ++by_space;
      } else {
        ++same;
      }
    }
    const auto U = random_surface(trial % 3 == 0);
    CHECK(vrep_detail::same_net_within(S, U, R(0), Limits{}) == common_space_equal(S, U));
    // Orientation: the reversed copy is the same surface, found by same_surface.
    CHECK(same_surface(S, reverse(C, 0), R(0)));
    CHECK_FALSE(same_surface(S, reverse(corner, 0), R(0)));
  }
  CHECK(same == 24);
  CHECK(by_corner == 24);
  CHECK(by_space == 24);
}

TEST_CASE("vmodel: one trivariate is 1 cell, 6 half-V-surfaces, 12 V-curves, 8 V-points (Section 3.2.1)") {
  const auto B = box_cells<R>({0, 0, 0}, {1, 2, 3});
  const auto M = glue(B);
  check_model(M, {8, 12, 6, 1, 0, 1});
  CHECK(M.boundary_surfaces() == 6);
  // Two boxes sharing a face: 12 points, 20 curves, 11 surfaces (1 internal), 2 cells.
  auto two = box_cells<R>({0, 0, 0}, {1, 1, 1});
  two.push_back(box_cells<R>({1, 0, 0}, {2, 1, 1})[0]);
  const auto M2 = glue(two);
  check_model(M2, {12, 20, 11, 2, 1, 1});
  CHECK(M2.shared(0, 1) == "surface");
  CHECK(M2.neighbours_of_cell(0) == std::vector<std::size_t>{1});
  // Boxes meeting along an edge only, and at a point only.
  auto edge = box_cells<R>({0, 0, 0}, {1, 1, 1});
  edge.push_back(box_cells<R>({1, 1, 0}, {2, 2, 1})[0]);
  CHECK(glue(edge).shared(0, 1) == "curve");
  auto corner = box_cells<R>({0, 0, 0}, {1, 1, 1});
  corner.push_back(box_cells<R>({1, 1, 1}, {2, 2, 2})[0]);
  CHECK(glue(corner).shared(0, 1) == "point");
  auto apart = box_cells<R>({0, 0, 0}, {1, 1, 1});
  apart.push_back(box_cells<R>({3, 3, 3}, {4, 4, 4})[0]);
  CHECK(glue(apart).shared(0, 1) == "none");
}

TEST_CASE("vmodel: the cylinder, cone and torus of five cells glue exactly, every cell regular") {
  // Counts (how they are counted): the disk has 8 points (4 square corners, 4 circle points), 12
  // edges (4 square sides, 4 spokes, 4 arcs) and 5 faces. Cylinder and cone: two disks, 8 vertical
  // edges, 12 vertical faces: 16 points, 32 curves, 22 surfaces,
  // 5 cells, Euler 16 - 32 + 22 - 5 = 1 (a ball). Internal: 4 square sides and 4 spokes. Torus: one disk (0 = 360 degrees), 8 circles,
  // 12 revolved edges: 8 points, 20 curves, 17 surfaces (internal: the 4 square sides and 4
  // spokes revolved, and each cell's face at 0 degrees glued to its own face at 360), 5 cells,
  // Euler 8 - 20 + 17 - 5 = 0 (a solid torus).
  const auto cyl = cylinder_cells<R>(R(2), R(3));
  const auto M = glue(cyl);
  check_model(M, {16, 32, 22, 5, 8, 1});
  check_regular(cyl);
  CHECK(M.neighbours_of_cell(0).size() == 4);  // the square touches the four sectors
  CHECK(M.shared(1, 3) == "none");             // opposite sectors
  CHECK(M.shared(1, 2) == "surface");          // neighbouring sectors share a spoke face
  // The vertical edges at the square's corners belong to three cells (the square and two sectors);
  // no other V-curve does.
  std::size_t three = 0;
  for (std::size_t c = 0; c < M.curves.size(); ++c) three += M.cells_of_curve(c).size() == 3;
  CHECK(three == 4);
  const auto cone = cone_cells<R>(R(2), R(1), R(3));
  check_model(glue(cone), {16, 32, 22, 5, 8, 1});
  check_regular(cone);
  const auto tor = torus_cells<R>(R(3), R(1));
  const auto T = glue(tor);
  check_model(T, {8, 20, 17, 5, 13, 0});
  check_regular(tor);
}

TEST_CASE("vmodel: Figure 8's single-trivariate cylinder and sphere are singular") {
  CHECK(certify_regularity(singular_cylinder<R>(R(1), R(2))).verdict.is_refuted());
  CHECK(certify_regularity(singular_sphere<R>(R(1))).verdict.is_refuted());
}

TEST_CASE("vmodel: gluing refuses a non-manifold face, and the invariants catch overlapping twins") {
  auto three = box_cells<R>({0, 0, 0}, {1, 1, 1});
  three.push_back(three[0]);
  const auto M = glue(three);  // two copies: every face glued to its copy, oriented the same way
  const auto chk = check_invariants(M);
  CHECK_FALSE(chk.ok());
  three.push_back(three[0]);
  CHECK_THROWS_AS(glue(three), ValidationError);
}

TEST_CASE("vmodel: a float gluing tolerance glues faces that differ and misses none here") {
  const auto cyl = cylinder_cells<R>(R(2), R(3));
  // Perturb the shared face of the square and sector 1 by delta in the sector (exactly).
  const R delta = R(1) / R(1L << 40);
  auto moved = cyl;
  // Sector 1's control point (u = 1, v = 1, w = 0), a corner of its face on the square's side,
  // moved along z by 2^-40.
  BSpline<R>& S = moved[1];
  S.points[(2 + 3 * 1 + 6 * 0) * 3 + 2] += delta;
  const auto exact = glue(moved);
  CHECK(exact.internal_surfaces() < glue(cyl).internal_surfaces());  // exactly: no longer the same face
  std::vector<BSpline<double>> dbl;
  for (const auto& V : moved) dbl.push_back(convert<double>(V, [](const R& x) { return to_double(x); }));
  CHECK(glue(dbl, 1e-9).internal_surfaces() == glue(cyl).internal_surfaces());  // eps says equal: a false glue
  CHECK(glue(dbl, 1e-15).internal_surfaces() == exact.internal_surfaces());
  std::vector<BSpline<double>> clean;
  for (const auto& V : cyl) clean.push_back(convert<double>(V, [](const R& x) { return to_double(x); }));
  check_model(glue(clean, 1e-12), {16, 32, 22, 5, 8, 1});  // rounding the exact primitive misses no glue here
}

TEST_CASE("vmodel attributes: fields on the cell's domain, constants on entities, evaluated exactly") {
  auto two = box_cells<R>({0, 0, 0}, {1, 1, 1});
  two.push_back(box_cells<R>({1, 0, 0}, {2, 1, 1})[0]);
  auto M = glue(two);
  // The shared face: cell 0's u = 1 face is cell 1's u = 0 face, one V-surface.
  CHECK(surface_of_face(M, 0, 0, 1) == surface_of_face(M, 1, 0, 0));
  CHECK(surface_of_face(M, 0, 0, 0) != surface_of_face(M, 1, 0, 1));
  // The edge along w at u = 1, v = 0 of cell 0 is the edge at u = 0, v = 0 of cell 1.
  CHECK(curve_of_edge(M, 0, 2, {1, 0, 0}) == curve_of_edge(M, 1, 2, {0, 0, 0}));
  CHECK(M.cells[0].corners[1] == M.cells[1].corners[0]);  // corner (1, 0, 0) of cell 0 is (0, 0, 0) of cell 1
  // A field: the distance-like polynomial u^2 + v w on the cell's domain.
  const auto F = spline_from<R>({2, 1, 1}, {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}}, 1, [](const std::vector<std::size_t>& i) {
    const R u = i[0] == 0 ? R(0) : i[0] == 1 ? R(0) : R(1);  // Bernstein coefficients of u^2: 0, 0, 1
    return std::vector<R>{u + R(static_cast<long>(i[1] * i[2]))};
  });
  attach_field(M, 0, "f", F);
  M.cells[0].attributes.constants["material"] = {R(7)};
  const auto v = evaluate_cell(M, 0, {R(1, 3), R(1, 2), R(3, 4)});
  CHECK(v.point == std::vector<R>{R(1, 3), R(1, 2), R(3, 4)});
  CHECK(v.fields.at("f") == std::vector<R>{R(1, 9) + R(3, 8)});
  CHECK(v.constants.at("material") == std::vector<R>{R(7)});
  auto G = F;
  G.knots[0] = {0, 0, 0, 2, 2, 2};
  CHECK_THROWS_AS(attach_field(M, 0, "g", G), ValidationError);
  CHECK_THROWS_AS(evaluate_cell(M, 5, {R(0), R(0), R(0)}), ValidationError);
}

TEST_CASE("vmodel: the sphere of seven cells glues exactly, every cell regular, radius certified") {
  // Counts: the cube's 8 corners and the 8 patch corners; 12 cube edges, 12 patch edges and 8
  // spokes; 6 cube faces, 12 faces between neighbouring ruled cells, 6 patches; 7 cells.
  // Euler 16 - 32 + 24 - 7 = 1 (a ball); internal: the 6 cube faces and the 12 side faces.
  const R r(3);
  const auto cells = sphere_cells<R>(r);
  REQUIRE(cells.size() == 7);
  const auto M = glue(cells);
  check_model(M, {16, 32, 24, 7, 18, 1});
  check_regular(cells);
  CHECK(M.neighbours_of_cell(0).size() == 6);
  CHECK(M.shared(1, 2) == "none");     // +z and -z
  CHECK(M.shared(1, 3) == "surface");  // +z and +x
  // Every patch point lies exactly on the ray of the cube's face point: on patch +z (cell 1,
  // w = 1), x / z = 2u - 1 and y / z = 2v - 1 (checked at 25 points, exact values).
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const R u(i, 4), v(j, 4);
      const auto p = evaluate(cells[1], {u, v, R(1)});
      CHECK(p[0] / p[2] == R(2) * u - R(1));
      CHECK(p[1] / p[2] == R(2) * v - R(1));
    }
  // The radius is approximate (no rational cube-sphere patch exists: its corners are irrational),
  // and its error is certified: bound >= every exact value, and small.
  for (int f = 1; f <= 6; ++f) {
    const auto dev = sphere_deviation(face(cells[f], 2, 1), {R(0), R(0), R(0)}, r);
    CHECK(dev.witness <= dev.bound);
    CHECK(R(0) < dev.witness);
    CHECK(dev.bound < R(1, 300));  // 2.5e-3 at degree 3, 4 pieces (docs/vrep/primitives.md)
  }
  // More pieces, smaller error; every face the same (the rotations are exact).
  const auto d4 = sphere_deviation(face(cells[1], 2, 1), {R(0), R(0), R(0)}, r);
  const auto d8 = sphere_deviation(face(sphere_cells<R>(r, 3, 8)[3], 2, 1), {R(0), R(0), R(0)}, r);
  CHECK(d8.bound < d4.bound);
  CHECK(sphere_deviation(face(cells[4], 2, 1), {R(0), R(0), R(0)}, r).bound == d4.bound);
  // Double: the same construction rounded glues to the same model.
  check_model(glue(sphere_cells<double>(3.0), 1e-12), {16, 32, 24, 7, 18, 1});
  CHECK_THROWS_AS(sphere_cells<R>(r, 1, 4), ValidationError);
  CHECK_THROWS_AS(sphere_cells<R>(r, 3, 0), ValidationError);
  CHECK_THROWS_AS(sphere_cells<R>(R(0)), ValidationError);
}

TEST_CASE("vmodel: gluing a 6 x 6 x 6 grid of boxes (indexed gluing), counts and Euler characteristic") {
  // n^3 boxes: (n+1)^3 V-points, 3 n (n+1)^2 V-curves, 3 n^2 (n+1) V-surfaces (3 n^2 (n-1)
  // internal), n^3 cells: Euler 1.
  const int n = 6;
  std::vector<BSpline<R>> boxes;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) boxes.push_back(box_cells<R>({R(i), R(j), R(k)}, {R(i + 1), R(j + 1), R(k + 1)})[0]);
  const std::size_t N = n, N1 = n + 1;
  check_model(glue(boxes), {N1 * N1 * N1, 3 * N * N1 * N1, 3 * N * N * N1, N * N * N, 3 * N * N * (N - 1), 1});
  std::vector<BSpline<double>> dbl;
  for (const auto& V : boxes) dbl.push_back(convert<double>(V, [](const R& x) { return to_double(x); }));
  check_model(glue(dbl, 1e-9), {N1 * N1 * N1, 3 * N * N1 * N1, 3 * N * N * N1, N * N * N, 3 * N * N * (N - 1), 1});
}

TEST_CASE("vmodel: a 4 x 4 x 4 grid of box primitives with the union of their regions glues (issue 47, repro vrep 5)") {
  // As `vrep glue` reads 64 `vrep primitive box` documents: the cells glued, the union of the 64
  // regions (nested two at a time, as io/vmodel_io.cpp appends them, 384 leaves) checked against
  // every cell, the model validated. Each cell's classification runs on the region localized to
  // it; composing all 384 leaves on every subdivision box was a 12.5M control-point refusal.
  const int n = 4;
  std::vector<BSpline<R>> boxes;
  std::optional<Region<R>> region;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const std::vector<R> lo{R(i), R(j), R(k)}, hi{R(i + 1), R(j + 1), R(k + 1)};
        boxes.push_back(box_cells<R>(lo, hi)[0]);
        region = region ? region_or<R>({*region, box_region<R>(lo, hi)}) : box_region<R>(lo, hi);
      }
  const auto M = glue(boxes);
  CHECK(check_region(M, *region).empty());
  CHECK(validate_vmodel(M, "vmodel").verdict() == "valid");
  check_model(M, {125, 300, 240, 64, 144, 1});  // the solid cube: chi 1
  // Its boundary (the V-surfaces with one half, their V-curves and V-points) is a sphere: chi 2.
  std::set<std::size_t> bcurves, bpoints;
  for (std::size_t c = 0; c < M.curves.size(); ++c)
    for (std::size_t s : M.curves[c].surfaces)
      if (M.surfaces[s].halves.size() == 1) {
        bcurves.insert(c);
        bpoints.insert(M.curves[c].ends.begin(), M.curves[c].ends.end());
      }
  CHECK(M.boundary_surfaces() == 96);
  CHECK(bcurves.size() == 192);
  CHECK(bpoints.size() == 98);
  CHECK(static_cast<long>(bpoints.size()) - static_cast<long>(bcurves.size()) + static_cast<long>(M.boundary_surfaces()) == 2);
  // One component: every cell reached through shared V-surfaces.
  std::vector<char> seen(M.cells.size(), 0);
  std::vector<std::size_t> todo{0};
  seen[0] = 1;
  while (!todo.empty()) {
    const std::size_t c = todo.back();
    todo.pop_back();
    for (std::size_t d : M.neighbours_of_cell(c))
      if (!seen[d]) {
        seen[d] = 1;
        todo.push_back(d);
      }
  }
  CHECK(std::count(seen.begin(), seen.end(), 1) == 64);
  R volume(0);
  for (std::size_t c = 0; c < M.cells.size(); ++c) volume += cell_volume(M, c);
  CHECK(volume == 64);
  // The localized classification against the whole region: inside, outside and across it. (A
  // cell across the boxes' shared faces stays undecided: the union's boxes meet there, and Kleene's
  // logic reads both sides as mixed on every box that straddles a face.)
  CHECK(classify_cell(box_cells<R>({R(5, 4), R(9, 4), R(13, 4)}, {R(7, 4), R(11, 4), R(15, 4)})[0], *region).kind == CellClass<R>::whole);
  CHECK(classify_cell(box_cells<R>({R(9, 2), R(0), R(0)}, {R(5), R(1), R(1)})[0], *region).kind == CellClass<R>::empty);
  CHECK(classify_cell(box_cells<R>({R(7, 2), R(1, 3), R(1, 3)}, {R(9, 2), R(1), R(1)})[0], *region).kind == CellClass<R>::cut);
  // The same with a knot at x = 4: the region's surface x = 4 is decided on the first Bezier piece
  // (x <= 4 holds there) but not on the second, so it stays in the localized formula.
  CHECK(classify_cell(insert_knot(box_cells<R>({R(7, 2), R(1, 3), R(1, 3)}, {R(9, 2), R(1), R(1)})[0], 0, R(1, 2)), *region).kind == CellClass<R>::cut);
  // A region missing one box does not describe the cells: the check says which.
  std::optional<Region<R>> less;
  for (int b = 0; b < 63; ++b) {
    const Region<R> r = box_region<R>({R(b / 16), R(b / 4 % 4), R(b % 4)}, {R(b / 16 + 1), R(b / 4 % 4 + 1), R(b % 4 + 1)});
    less = less ? region_or<R>({*less, r}) : r;
  }
  const auto fails = check_region(M, *less);
  REQUIRE(fails.size() >= 1);
  CHECK(fails.front().find("cells[63]") != std::string::npos);
}

TEST_CASE("vmodel: faces with the same four V-curves but different surfaces are not twins") {
  // [0,1]^3 and a cell on [1,2] x [0,1]^2 whose face x = 1 bulges into x > 1 (biquadratic, middle
  // control point at x = 3/2; its edges are the box's): the cells share the loop of four V-curves
  // and nothing else. A u B is two balls glued along a circle: chi 1 + 1 - 0 = 2, no internal face.
  BSpline<R> bulged;
  bulged.degrees = {1, 2, 2};
  bulged.knots = {{0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  bulged.q = 3;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 2; ++i) bulged.points.insert(bulged.points.end(), {i == 1 ? R(2) : (j == 1 && k == 1 ? R(3, 2) : R(1)), R(j, 2), R(k, 2)});
  CHECK(evaluate(bulged, {R(0), R(1, 2), R(1, 2)})[0] == R(9, 8));
  const auto M = glue(std::vector<BSpline<R>>{box_cells<R>({0, 0, 0}, {1, 1, 1})[0], bulged});
  check_model(M, {12, 20, 12, 2, 0, 2});
  CHECK(M.shared(0, 1) == "curve");
}

// Validation before use (vrep/model/validate.hpp; issue 47, reproducers vrep 2-4): proved defects are
// typed errors naming the cells, what cannot be decided is said, valid models pass.
namespace {

BSpline<R> unit_box(std::vector<R> lo, std::vector<R> hi) { return box_cells<R>(lo, hi)[0]; }

std::string refusal(const std::vector<BSpline<R>>& cells) {
  try {
    validate_cells(cells, {}, "vmodel");
  } catch (const ValidationError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("vmodel validation: duplicated, contained and overlapping cells are refused exactly") {
  const auto a = unit_box({0, 0, 0}, {1, 1, 1});
  CHECK_THAT(refusal({a, a}), Catch::Contains("vmodel.cells[1]") && Catch::Contains("same cell as vmodel.cells[0]"));
  CHECK_THAT(refusal({a, unit_box({R(1, 4), R(1, 4), R(1, 4)}, {R(3, 4), R(3, 4), R(3, 4)})}), Catch::Contains("lies inside vmodel.cells[0]"));
  CHECK_THAT(refusal({a, unit_box({R(1, 2), 0, 0}, {R(3, 2), 1, 1})}), Catch::Contains("overlaps vmodel.cells[1]"));
  // Overlap by 2^-60 is found; touching (a common face, edge or corner) is not an overlap.
  const R tiny = R(1) / R(Integer(1) << 60);
  CHECK_THAT(refusal({a, unit_box({1 - tiny, 0, 0}, {2, 1, 1})}), Catch::Contains("overlaps"));
  CHECK(refusal({a, unit_box({1, 0, 0}, {2, 1, 1}), unit_box({1, 1, 1}, {2, 2, 2})}).empty());
  // A rotated convex cell (a square turned 45 degrees, L1 ball of radius 1 around (c, -1/2)): its
  // control-point box overlaps a's, the separating axis decides.
  auto diamond = [&](const R& c) {
    BSpline<R> d = a;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const R x = d.points[3 * i], y = d.points[3 * i + 1];
      d.points[3 * i] = x - y + c;
      d.points[3 * i + 1] = x + y - R(3, 2);
    }
    return d;
  };
  const auto rep = validate_cells({a, diamond(R(7, 4))}, {}, "vmodel");
  CHECK(rep.pairs_tested == 1);
  CHECK(rep.verdict() == "valid");
  CHECK_THAT(refusal({a, diamond(R(3, 2))}), Catch::Contains("lies inside an edge"));  // touches along a's edge x = 1, y = 0
  CHECK_THAT(refusal({a, diamond(R(5, 4))}), Catch::Contains("overlaps"));
}

TEST_CASE("vmodel validation: folding, pinched and flat cells are refused, collapsed edges pass") {
  // x(u) = 4u - 3u^2: x' = 4 - 6u changes sign at u = 2/3 (a fold).
  BSpline<R> fold;
  fold.degrees = {2, 1, 1};
  fold.knots = {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}};
  fold.q = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int x : {0, 2, 1}) fold.points.insert(fold.points.end(), {R(x), R(j), R(k)});
  CHECK_THAT(refusal({fold}), Catch::Contains("folds: det J changes sign"));
  // A fold strictly inside one Bezier piece: x(u) cubic with x' = 100 (u - 3/5)(u - 9/10)
  // (control points 0, 18, 11, 37/3): det J > 0 at every corner of the domain, -9/4 at u = 3/4.
  BSpline<R> inner;
  inner.degrees = {3, 1, 1};
  inner.knots = {{0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}};
  inner.q = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (const R& x : {R(0), R(18), R(11), R(37, 3)}) inner.points.insert(inner.points.end(), {x, R(j), R(k)});
  CHECK(derivative(inner, {R(3, 4), R(1, 2), R(1, 2)}, {1, 0, 0})[0] == R(-9, 4));
  CHECK(certify_regularity(inner).verdict.is_refuted());
  CHECK_THAT(refusal({inner}), Catch::Contains("folds: det J changes sign"));
  // The top face turned half a turn: det J = (1 - 2w)^2, 0 on the plane w = 1/2 (pinched).
  BSpline<R> twist = unit_box({0, 0, 0}, {1, 1, 1});
  for (int i = 4; i < 8; ++i) {
    twist.points[3 * i] = R(1) - twist.points[3 * i];
    twist.points[3 * i + 1] = R(1) - twist.points[3 * i + 1];
  }
  CHECK(certify_regularity(twist).verdict.is_refuted());
  CHECK_THAT(refusal({twist}), Catch::Contains("not regular inside"));
  BSpline<R> flat = unit_box({0, 0, 0}, {1, 1, 1});
  for (std::size_t i = 0; i < flat.size(); ++i) flat.points[3 * i + 2] = R(0);
  CHECK_THAT(refusal({flat}), Catch::Contains("is flat"));
  // Figure 8's cylinder: det J = 0 on its axis, a collapsed face of the domain: valid, degenerate.
  const auto rep = validate_cells({singular_cylinder<R>(R(1), R(2))}, {}, "vmodel");
  CHECK(rep.degenerate.size() + rep.undecided.size() == 1);
}

TEST_CASE("vmodel validation: T-junctions and partial edge contacts are refused, primitives pass") {
  // Three boxes: the big one's face y = 1 is half glued to nothing (a T-junction).
  const auto t0 = unit_box({0, 0, 0}, {2, 1, 1}), t1 = unit_box({0, 1, 0}, {1, 2, 1}), t2 = unit_box({1, 1, 0}, {2, 2, 1});
  try {
    validate_vmodel(glue<R>({t0, t1, t2}), "vmodel");
    FAIL("a T-junction passed");
  } catch (const ValidationError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("T-junction") && Catch::Contains("vmodel.cells[0]"));
  }
  // A parallelepiped touching the unit box at one point where an edge of each crosses the other's
  // (no corner there): a vertex contact, found exactly.
  {
    BSpline<R> b = unit_box({0, 0, 0}, {1, 1, 1});
    const std::array<std::array<R, 3>, 3> e{{{0, 1, -1}, {0, 1, 1}, {1, 1, 1}}};
    for (int i = 0; i < 8; ++i)
      for (int c = 0; c < 3; ++c) {
        R x = c == 0 ? R(1, 2) : c == 1 ? R(1, 2) : R(3, 2);
        for (int d = 0; d < 3; ++d)
          if ((i >> d) & 1) x += e[d][c];
        b.points[3 * i + c] = x;
      }
    CHECK_THAT(refusal({unit_box({0, 0, 0}, {1, 1, 1}), b}), Catch::Contains("crosses an edge of"));
  }
  // Boxes touching along part of an edge.
  CHECK_THAT(refusal({unit_box({0, 0, 0}, {1, 1, 1}), unit_box({1, 1, R(1, 2)}, {2, 2, 2})}), Catch::Contains("inside an edge"));
  // The primitives are valid; the cylinder's and sphere's cells are separated by their planar
  // faces, the torus's (revolved) are not decided and say so.
  const auto cyl = validate_vmodel(glue(cylinder_cells<R>(R(2), R(3))), "vmodel");
  CHECK(cyl.decided());
  CHECK(validate_vmodel(glue(sphere_cells<R>(R(3))), "vmodel").decided());
  const auto tor = validate_vmodel(glue(torus_cells<R>(R(3), R(1))), "vmodel");
  CHECK_FALSE(tor.decided());
  CHECK_THAT(tor.verdict(), Catch::StartsWith("undecided: overlap of"));
  // A 3 x 3 x 3 grid: conforming, valid.
  std::vector<BSpline<R>> grid;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) grid.push_back(unit_box({R(i), R(j), R(k)}, {R(i + 1), R(j + 1), R(k + 1)}));
  CHECK(validate_vmodel(glue(grid), "vmodel").verdict() == "valid");
}

TEST_CASE("vmodel validation: trimmed models, categories and duplicated cells") {
  const auto M = glue(box_cells<R>({0, 0, 0}, {1, 1, 1}));
  auto T = as_trimmed(M, box_region<R>({0, 0, 0}, {1, 1, 1}));
  CHECK(validate_trimmed(T, "model").verdict() == "valid");
  for (const char* ok : {"A", "both", "B", ""}) {
    T.cells[0].category = ok;
    CHECK_NOTHROW(validate_trimmed(T, "model"));
  }
  T.cells[0].category = "Z";
  try {
    validate_trimmed(T, "model");
    FAIL("category Z passed");
  } catch (const ValidationError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("model.cells[0]") && Catch::Contains(".category: is \"Z\""));
  }
  T.cells[0].category = "A";
  T.cells.push_back(T.cells[0]);
  CHECK_THROWS_WITH(validate_trimmed(T, "model"), Catch::Contains("is the same cell as model.cells[0]"));
  T.cells[1].trim = region_not(T.cells[1].trim);  // the same trivariate, another trim: overlap not decided, said
  const auto rep = validate_trimmed(T, "model");
  CHECK_THAT(rep.verdict(), Catch::Contains("not checked: overlap of trimmed cells"));
}
