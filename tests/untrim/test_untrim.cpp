#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/sweep.hpp"
#include "untrim/algorithm2.hpp"
#include "untrim/interval_join.hpp"
#include "untrim/loops.hpp"
#include "untrim/polygon.hpp"
#include "untrim/tile_integrals.hpp"

using namespace splinex;

namespace {
using V = Point2<Rational>;
std::vector<Segment2<Rational>> square_edges(const Rational& a, const Rational& b) {
  return {{{a, a}, {b, a}}, {{b, a}, {b, b}}, {{a, b}, {b, b}}, {{a, a}, {a, b}}};
}
// Affine S (degree (1, 1), a parallelogram net) into a T with knots that S crosses obliquely.
BSpline<Rational> affine_inner() {
  // S(r, t) = (1/10 + 7/10 r + 3/20 t, 1/20 + 1/10 r + 4/5 t)
  return affine_map<Rational>({Rational(1, 10), Rational(1, 20)}, {{Rational(7, 10), Rational(1, 10)}, {Rational(3, 20), Rational(4, 5)}});
}
BSpline<Rational> outer_surface() {
  return spline_from<Rational>({2, 3},
                               {clamped_knots(2, Rational(0), Rational(1), {Rational(1, 3), Rational(1, 2), Rational(1, 2)}),
                                clamped_knots(3, Rational(0), Rational(1), {Rational(2, 5)})},
                               3, [](const std::vector<std::size_t>& ij) {
                                 const std::size_t i = ij[0], j = ij[1];
                                 return std::vector<Rational>{Rational(static_cast<long>(i), 5), Rational(static_cast<long>(j), 4),
                                                              Rational(static_cast<long>((i * 7 + j * 3) % 11), 5)};
                               });
}
}  // namespace

TEST_CASE("sweep: a square cut by its diagonal gives two triangles of area 1/2") {
  auto segs = square_edges(0, 1);
  segs.push_back({{0, 0}, {1, 1}});
  const auto sub = planar_subdivision(segs);
  CHECK(sub.size() == 5);
  const auto traps = vertical_decomposition(sub);
  REQUIRE(traps.size() == 2);
  const auto tiles = merge_trapezoids(traps, {0, 1});
  REQUIRE(tiles.size() == 2);
  for (const auto& t : tiles) {
    CHECK(tile_area(t) == Rational(1, 2));
    CHECK(polygon_area(tile_polygon(t)) == Rational(1, 2));  // CGAL, independent
    CHECK(polygon_is_simple(tile_polygon(t)));
  }
}

TEST_CASE("sweep: crossing segments are split exactly, a hole is tiled around") {
  // Two crossing diagonals: four triangles meeting at (1/2, 1/2).
  auto segs = square_edges(0, 1);
  segs.push_back({{0, 0}, {1, 1}});
  segs.push_back({{0, 1}, {1, 0}});
  const auto sub = planar_subdivision(segs);
  CHECK(sub.size() == 8);
  const auto traps = vertical_decomposition(sub);
  Rational total(0);
  for (const auto& z : traps) total += (z.x1 - z.x0) * ((z.yt0 - z.yb0) + (z.yt1 - z.yb1)) / 2;
  CHECK(total == 1);
  // A square hole [1/3, 2/3]^2 in [0, 1]^2, labelled by the trapezoid's centre.
  auto h = square_edges(0, 1);
  for (const auto& s : square_edges(Rational(1, 3), Rational(2, 3))) h.push_back(s);
  const auto tz = vertical_decomposition(planar_subdivision(h));
  std::vector<int> labels;
  for (const auto& z : tz) {
    const Rational mx = (z.x0 + z.x1) / 2, my = (z.yb0 + z.yb1 + z.yt0 + z.yt1) / 4;
    const bool in_hole = Rational(1, 3) < mx && mx < Rational(2, 3) && Rational(1, 3) < my && my < Rational(2, 3);
    labels.push_back(in_hole ? -1 : 0);
  }
  const auto tiles = merge_trapezoids(tz, labels);
  Rational a(0);
  for (const auto& t : tiles) {
    a += tile_area(t);
    CHECK(polygon_area(tile_polygon(t)) == tile_area(t));
  }
  CHECK(a == Rational(8, 9));
  CHECK(tiles.size() == 4);  // left, below, above, right: the sweep splits at the hole's extremes
}

TEST_CASE("Algorithm 2, exact: affine S crossing knot lines obliquely") {
  const auto T = outer_surface();
  for (int elevate = 0; elevate <= 1; ++elevate) {
    auto S = affine_inner();
    if (elevate) S = elevate_degree(S, 0, 1);  // still affine, in a degree (2, 1) form
    validate(S);
    const auto A = compose_tensor(T, S);
    REQUIRE(!A.tiles.empty());
    CHECK(A.curved_boundaries == 0);
    CHECK(A.straight_boundaries > 0);
    CHECK(A.gap_area == 0);
    CHECK(A.overlap_area == 0);
    // Areas: all tiles fill S's domain; each region's tiles fill the region, whose polygon is
    // computed independently by clipping the box with the half-planes of its conditions (CGAL area).
    Rational total(0);
    std::vector<Rational> per_patch(A.trimmed.patches.size(), Rational(0));
    for (const auto& t : A.tiles) {
      total += t.area;
      per_patch[t.patch] += t.area;
      CHECK(polygon_area(tile_polygon(t.tile)) == t.area);
    }
    CHECK(total == 1);
    // S(r, t) = (al_c + be_c r + ga_c t) for c = 0, 1.
    const Rational al[2] = {Rational(1, 10), Rational(1, 20)}, be[2] = {Rational(7, 10), Rational(1, 10)},
                   ga[2] = {Rational(3, 20), Rational(4, 5)};
    for (std::size_t k = 0; k < A.trimmed.patches.size(); ++k) {
      const auto& p = A.trimmed.patches[k];
      const Polygon poly = affine_region_polygon(A.trimmed.inner_pieces[p.inner_piece].box, p.region, al, be, ga);
      INFO("patch " << k);
      CHECK(per_patch[k] == polygon_area(poly));
      // Integrals of a density over the region: tiles (f(Q) det J) against Green's theorem on the
      // independently clipped polygon.
      TrimmedDomain D{{0, 0}, {1, 1}, {poly}};
      const auto f = monomial_density(2, 1, D);
      Rational by_tiles(0);
      for (const auto& t : A.tiles)
        if (t.patch == k) by_tiles += integrate_over_tile(f, t.tile)[0];
      CHECK(by_tiles == green_integral(D, f));
    }
    // Tiles reproduce T(S) exactly inside (the tile's own parametrization, not S's).
    for (std::size_t k = 0; k < A.tiles.size(); ++k) {
      const auto& t = A.tiles[k];
      const auto deg = A.trimmed.patches[t.patch].patch.net.degrees;
      CHECK(t.R.net.degrees == std::vector<int>{deg[0] + deg[1], deg[0] + deg[1]});
      for (int a = 1; a <= 3; ++a)
        for (int b = 1; b <= 3; ++b) {
          const Rational x = t.tile.x.front() + (t.tile.x.back() - t.tile.x.front()) * Rational(a, 4);
          const std::vector<Rational> xl{x, Rational(b, 4)};
          const auto rt = evaluate(t.Q, xl);
          CHECK(A.evaluate_tile(k, xl) == evaluate(T, evaluate(S, rt)));
        }
    }
  }
}

TEST_CASE("Algorithm 2: curved trimming needs a tolerance, with polylines the error is small") {
  const auto T = outer_surface();
  const auto S = bezier_from<Rational>({2, 1}, 2, [](const std::vector<std::size_t>& ij) {
    const long i = static_cast<long>(ij[0]), j = static_cast<long>(ij[1]);
    return std::vector<Rational>{Rational(1, 10) + Rational(2, 5) * i + (i == 1 ? Rational(1, 10) : Rational(0)) + Rational(j, 10),
                                 Rational(1, 10) + Rational(7, 10) * j + Rational(i, 20)};
  });
  CHECK_THROWS_AS(compose_tensor(T, S), DomainError);
  TensorOptions o;
  o.boundary = TrimBoundary::polyline;
  o.eps = 1e-3;
  o.grid = 4;
  const auto A = compose_tensor(T, S, o);
  CHECK(A.curved_boundaries > 0);
  Rational total(0), worst(0);
  for (std::size_t k = 0; k < A.tiles.size(); ++k) {
    total += A.tiles[k].area;
    const auto& t = A.tiles[k];
    for (int a = 1; a <= 3; ++a) {
      const std::vector<Rational> xl{t.tile.x.front() + (t.tile.x.back() - t.tile.x.front()) * Rational(a, 4), Rational(1, 2)};
      const auto d = A.evaluate_tile(k, xl), e = evaluate(T, evaluate(S, evaluate(t.Q, xl)));
      for (int c = 0; c < 3; ++c) worst = std::max(worst, abs(Rational(d[c] - e[c])));
    }
  }
  CHECK(total + A.gap_area - A.overlap_area == 1);
  CHECK(worst < Rational(1, 1000));  // T is C^1 / C^0 at the crossed knots; within eps the error is tiny
}

TEST_CASE("Algorithm 2: the tiles' nets together are within max_total_control_points, checked before composing") {
  const auto T = outer_surface();
  const auto S = bezier_from<Rational>({2, 1}, 2, [](const std::vector<std::size_t>& ij) {
    const long i = static_cast<long>(ij[0]), j = static_cast<long>(ij[1]);
    return std::vector<Rational>{Rational(1, 10) + Rational(2, 5) * i + (i == 1 ? Rational(1, 10) : Rational(0)) + Rational(j, 10),
                                 Rational(1, 10) + Rational(7, 10) * j + Rational(i, 20)};
  });
  TensorOptions o;
  o.boundary = TrimBoundary::polyline;
  o.eps = 1e-3;
  o.grid = 4;
  const auto A = compose_tensor(T, S, o);
  REQUIRE(A.tiles.size() > 1);
  std::size_t total = 0, least = 0, largest = 0;
  for (const auto& t : A.tiles) {
    total += t.R.net.size();
    largest = std::max(largest, t.R.net.size());
    least += compose_least_size(A.trimmed.patches[t.patch].patch.net, t.Q);
  }
  // Each tile is one polynomial patch composed with a C^0 Coons tile: no join may jump, so the
  // bound before the work is the exact size.
  CHECK(least == total);
  Limits at;
  at.max_total_control_points = total;
  CHECK(compose_tensor(T, S, o, at).tiles.size() == A.tiles.size());
  Limits below = at;
  below.max_total_control_points = total - 1;
  below.max_control_points = largest;  // every tile alone fits: only the sum is refused
  try {
    compose_tensor(T, S, o, below);
    FAIL("no SizeLimitError");
  } catch (const SizeLimitError& e) {
    CHECK(e.field() == "eps");
    CHECK(std::string(e.what()).find(std::to_string(total)) != std::string::npos);  // the bound reached: all tiles
  }
}

namespace {
TrimmedDomain holed_domain() {
  // A quadrilateral with a triangular hole in [0, 2] x [0, 1] (the hole touches no edge).
  return TrimmedDomain{{0, 0},
                       {2, 1},
                       {{{Rational(1, 10), Rational(1, 10)}, {Rational(19, 10), Rational(1, 5)}, {Rational(3, 2), Rational(9, 10)},
                         {Rational(1, 5), Rational(4, 5)}},
                        {{Rational(1, 2), Rational(3, 10)}, {1, Rational(2, 5)}, {Rational(7, 10), Rational(2, 3)}}}};
}
}  // namespace

TEST_CASE("untrim a domain with a hole: exact areas and integrals against CGAL and Green's theorem") {
  const auto D = holed_domain();
  validate_domain(D);
  const auto tiles = untrim_domain<Rational>(D);
  REQUIRE(tiles.size() >= 3);
  Rational area(0);
  std::vector<Polygon> polys;
  for (const auto& t : tiles) {
    area += tile_area(t);
    polys.push_back(tile_polygon(t));
    CHECK(polygon_is_simple(polys.back()));
    // f = 1: the integral is the area.
    CHECK(integrate_over_tile(monomial_density(0, 0, D), t)[0] == tile_area(t));
  }
  CHECK(area == region_area(D));
  CHECK(region_area(D) == polygon_area(D.loops[0]) + polygon_area(D.loops[1]) * (polygon_area(D.loops[1]) > 0 ? -1 : 1));
  CHECK(polygon_union_area(polys) == area);  // no overlap between tiles
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; b <= 3; ++b) {
      const auto f = monomial_density(a, b, D);
      Rational sum(0);
      for (const auto& t : tiles) sum += integrate_over_tile(f, t)[0];
      INFO("x^" << a << " y^" << b);
      CHECK(sum == green_integral(D, f));
    }
  // A general density (not a monomial): Green's theorem converts it to monomials itself.
  const auto f = make_spline<Rational>({2, 1}, {{-1, -1, -1, 3, 3, 3}, {0, 0, 1, 1}}, 1,
                                      {Rational(1, 3), -2, 5, Rational(7, 2), 0, Rational(-1, 9)});
  Rational sum(0);
  for (const auto& t : tiles) sum += integrate_over_tile(f, t)[0];
  CHECK(sum == green_integral(D, f));
}

TEST_CASE("untrim in double: the rounded tiles' area and integrals measured exactly") {
  const auto D = holed_domain();
  const auto tiles = untrim_domain<double>(D);
  const auto f = monomial_density(2, 1, D);
  const auto fd = convert<double>(f, [](const Rational& x) { return to_double(x); });
  double area = 0, integral = 0;
  for (const auto& t : tiles) {
    area += tile_area(t);
    integral += integrate_over_tile(fd, t)[0];
  }
  CHECK(abs(Rational(exact_from_double(area) - region_area(D))) < Rational(1, 1000000000000000LL));
  CHECK(abs(Rational(exact_from_double(integral) - green_integral(D, f))) < Rational(1, 1000000000000000LL));
}

TEST_CASE("trimmed domain validation: typed errors naming the loop") {
  auto expect = [](const TrimmedDomain& D, const std::string& what) {
    try {
      validate_domain(D);
      FAIL("accepted: " << what);
    } catch (const Error& e) {
      CHECK_THAT(std::string(e.what()), Catch::Contains(what));
    }
  };
  const Rational h(1, 2);
  expect({{0, 0}, {1, 1}, {{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}}, "loops[0]: is self-intersecting");
  expect({{0, 0}, {1, 1}, {{{0, 0}, {h, h}, {1, 1}}}}, "loops[0]: is degenerate: all vertices on one line");
  expect({{0, 0}, {1, 1}, {{{0, 0}, {1, 0}}}}, "loops[0]: is degenerate: 2 vertices");
  expect({{0, 0}, {1, 1}, {{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}}, "loops[0][1]: is degenerate: repeats the next vertex");
  expect({{0, 0}, {1, 1}, {{{0, 0}, {2, 0}, {0, 1}}}}, "loops[0][1]: leaves the domain");
  expect({{0, 0}, {1, 0}, {}}, "domain[1]: is empty");
  expect({{0, 0}, {1, 1}, {{{0, 0}, {1, 0}, {0, 1}}, {{h, 0}, {1, h}, {1, 1}}}}, "loops[1]: meets loops[0]");
  try {
    validate_domain(TrimmedDomain{{0, 0}, {1, 1}, {{{0, 0}, {1, 0}, {0, 1}}, {{Rational(1, 10), Rational(1, 10)}, {Rational(1, 5), Rational(1, 10)}, {Rational(1, 10), Rational(1, 5)}}}});
  } catch (...) {
    FAIL("a hole inside a loop was rejected");
  }
}

// Issue 47: the meeting test was quadratic when many edges overlap in x (16,000 copies of two loops:
// minutes before the error). Above a pair budget the loops are found by CGAL's sweep, bisected over
// prefixes; the answer is the first loop that meets an earlier one.
TEST_CASE("trimmed domain validation: many equal or nested loops in near-linear time") {
  // 2,000 nested squares (a vertical line crosses every one: 8,000 edges, about 8 10^6 pairs
  // overlapping in x): pairwise disjoint, so valid as far as meeting goes.
  TrimmedDomain nested{{0, 0}, {1, 1}, {}};
  for (int k = 1; k <= 2000; ++k) {
    const Rational a(k, 4001 * 2), b = 1 - a;
    nested.loops.push_back({{a, a}, {b, a}, {b, b}, {a, b}});
  }
  CHECK(count_overlapping_pairs(std::vector<std::pair<Rational, Rational>>{{0, 1}, {0, 1}, {2, 3}}, 100) == 1);
  CHECK_FALSE(first_meeting_loops(nested.loops).has_value());
  // The same with one more square that touches square 700 at its corner from outside (between
  // squares 699 and 700): found, and named with the least loop it meets.
  const Rational a7(700, 4001 * 2);
  auto touching = nested;
  touching.loops.push_back({{a7 - Rational(1, 100000), a7 - Rational(1, 100000)}, {a7, a7 - Rational(1, 100000)}, {a7, a7}, {a7 - Rational(1, 100000), a7}});
  const auto t = first_meeting_loops(touching.loops);
  REQUIRE(t.has_value());
  CHECK((*t)[0] == 699);
  CHECK((*t)[1] == 2000);
  try {
    validate_domain(touching);
    FAIL("a loop touching square 700 was accepted");
  } catch (const Error& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("loops[2000]: meets loops[699]"));
  }
  // Copies of one loop: the copy meets the original (overlapping edges, no crossing).
  TrimmedDomain copies{{0, 0}, {1, 1}, {}};
  for (int k = 0; k < 3000; ++k) copies.loops.push_back({{Rational(1, 4), Rational(1, 4)}, {Rational(3, 4), Rational(1, 4)}, {Rational(1, 2), Rational(3, 4)}});
  try {
    validate_domain(copies);
    FAIL("copies of a loop were accepted");
  } catch (const Error& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("loops[1]: meets loops[0]"));
  }
}
