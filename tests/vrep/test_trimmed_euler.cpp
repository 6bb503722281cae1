// The Euler characteristic of trimmed cells (issue 18: Euler characteristic after Booleans on
// trimmed cells), against solids whose topology is known in closed form: a box with cavities (1 +
// k), with a tunnel (0), cut in two (2), a solid torus (0), a thin set (duality fails), cells of
// closed trivariates (the image's identifications), and random disjoint balls (k, 1 + k).
#include <catch2/catch.hpp>
#include <map>
#include <random>

#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "spline/evaluate.hpp"
#include "spline/insert.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_euler.hpp"

using namespace splinex;
using R = Rational;

namespace {

BSpline<R> box(R a, R b) { return box_cells<R>({a, a, a}, {b, b, b}).front(); }

using test::ball;

/// r^2 - (x_a - ca)^2 - (x_b - cb)^2 >= 0: the solid cylinder about a line parallel to the third
/// axis (a, b = 0, 1: along z).
Region<R> rod(R ca, R cb, R r, int a = 0, int b = 1) {
  Poly3<R> g;
  std::array<int, 3> a2{}, b2{}, a1{}, b1{};
  a2[a] = 2;
  b2[b] = 2;
  a1[a] = 1;
  b1[b] = 1;
  g.terms[a2] = R(-1);
  g.terms[b2] = R(-1);
  g.terms[a1] = R(2) * ca;
  g.terms[b1] = R(2) * cb;
  g.terms[{0, 0, 0}] = r * r - ca * ca - cb * cb;
  return region_leaf(g, "rod");
}

/// c0 + c . x >= 0.
Region<R> half(R c0, R cx, R cy, R cz) {
  Poly3<R> g;
  g.terms[{0, 0, 0}] = c0;
  g.terms[{1, 0, 0}] = cx;
  g.terms[{0, 1, 0}] = cy;
  g.terms[{0, 0, 1}] = cz;
  return region_leaf(g, "plane");
}

void require_decided(const TrimmedEuler<R>& e, long chi) {
  INFO(e.undecided_reason);
  INFO("chi " << e.chi << ", image " << e.image_chi << ", interior " << e.interior_chi_c << ", expected " << chi);
  REQUIRE(e.decided);
  CHECK(e.chi == chi);
  CHECK(e.image_chi == chi);  // a box trivariate identifies nothing
  CHECK(e.interior_chi_c == -chi);
  CHECK(e.duality);
}

}  // namespace

TEST_CASE("vrep trimmed euler: a box, with a cavity, two cavities, a tunnel, cut in two") {
  const auto V = box(R(0), R(2));
  require_decided(trimmed_euler(V, region_and<R>({})), 1);
  require_decided(trimmed_euler(V, ball({R(1), R(1), R(1)}, R(1, 2))), 1);
  require_decided(trimmed_euler(V, region_not(ball({R(1), R(1), R(1)}, R(1, 2)))), 2);  // a spherical cavity: b0 = 1, b2 = 1
  require_decided(trimmed_euler(V, region_and<R>({region_not(ball({R(1, 2), R(1, 2), R(1, 2)}, R(1, 3))),
                                                  region_not(ball({R(3, 2), R(4, 3), R(7, 5)}, R(2, 7)))})),
                  3);
  require_decided(trimmed_euler(V, region_not(rod(R(1), R(1), R(1, 2)))), 0);  // a tunnel through: a solid torus
  require_decided(trimmed_euler(V, region_not(rod(R(2, 3), R(5, 4), R(1, 3)))), 0);
  // A slab removed across the whole box: two pieces.
  require_decided(trimmed_euler(V, region_not(region_and<R>({half(R(-1, 2), R(1), R(0), R(0)), half(R(3, 2), R(-1), R(0), R(0))}))), 2);
  // A slanted slab.
  require_decided(trimmed_euler(V, region_not(region_and<R>({half(R(-1, 2), R(1), R(1, 3), R(1, 5)), half(R(3, 2), R(-1), R(-1, 3), R(-1, 5))}))), 2);
  // A ball and a rod overlapping, removed together: a tunnel with a chamber (still one hole).
  require_decided(trimmed_euler(V, region_not(region_or<R>({rod(R(1), R(1), R(1, 3)), ball({R(1), R(1), R(1)}, R(2, 3))}))), 0);
}

TEST_CASE("vrep trimmed euler: each budget names itself, per attempt and in all") {
  // A ball strictly inside the first octant of every split fraction (1/2, 7/16, 13/32 of [0, 2]):
  // one halving per direction cannot make every leaf monotone on the cell holding its centre.
  const auto V = box(R(0), R(2));
  const auto trim = ball({R(2, 3), R(2, 3), R(2, 3)}, R(1, 4));
  require_decided(trimmed_euler(V, trim), 1);
  EulerOptions shallow;
  shallow.max_level = 1;
  const auto e = trimmed_euler(V, trim, shallow);
  CHECK_FALSE(e.decided);
  CHECK(e.undecided_reason.rfind("no monotone direction within 1 halvings near (u, v, w) = (", 0) == 0);
  // The cell budget: each of the three attempts examines max_cells cells and meets one more.
  EulerOptions few;
  few.max_cells = 5;
  const auto f = trimmed_euler(V, trim, few);
  CHECK_FALSE(f.decided);
  CHECK(f.undecided_reason.rfind("the budget of 5 cells is spent near (u, v, w) = (", 0) == 0);
  CHECK(f.cells == 3 * 6);
}

TEST_CASE("vrep trimmed euler: genus by tunnels, exactly") {
  const auto V = box(R(0), R(2));
  // Two parallel tunnels along z: genus 2, chi = 1 - 2.
  require_decided(trimmed_euler(V, region_and<R>({region_not(rod(R(1, 2), R(1), R(1, 4))), region_not(rod(R(3, 2), R(1), R(1, 4)))})), -1);
  // Two tunnels that cross (along z and along x, radii 1/2 and 1/3, crossing transversally): one
  // tunnel system with four openings, genus 3.
  require_decided(trimmed_euler(V, region_and<R>({region_not(rod(R(1), R(1), R(1, 2))), region_not(rod(R(1), R(1), R(1, 3), 1, 2))})), -2);
  // A torus region (R = 3/4, r = 1/5 about the box's centre axis) inside the box: a solid torus.
  auto T = place_region(torus_region<R>(R(3, 4), R(1, 5)), 2, {R(1), R(1), R(1)});
  require_decided(trimmed_euler(V, T), 0);
  // The box minus that torus: chi(B) - chi(T) + chi(bd T) = 1 - 0 + 0.
  require_decided(trimmed_euler(V, region_not(T)), 1);
}

TEST_CASE("vrep trimmed euler: a thin set fails the duality check, tangency is undecided or right") {
  const auto V = box(R(0), R(2));
  // x >= 1 and x <= 1: the closed set is the square x = 1 (chi 1), the interior is empty.
  const auto thin = trimmed_euler(V, region_and<R>({half(R(-1), R(1), R(0), R(0)), region_not(half(R(-1), R(1), R(0), R(0)))}));
  REQUIRE(thin.decided);
  CHECK(thin.chi == 1);
  CHECK(thin.interior_chi_c == 0);
  CHECK_FALSE(thin.duality);
  // The box minus a torus (R + r = 1) that touches four of its faces at one point each: chi = 1
  // (additivity), but the interior, the open box minus the closed torus, has chi_c = -1 - (0 - 4) =
  // 3: not a manifold, and the duality check says so.
  const auto touching = trimmed_euler(V, region_not(place_region(torus_region<R>(R(3, 4), R(1, 4)), 2, {R(1), R(1), R(1)})));
  REQUIRE(touching.decided);
  CHECK(touching.chi == 1);
  CHECK(touching.interior_chi_c == 3);
  CHECK_FALSE(touching.duality);
  // A ball touching the face z = 0 from inside at a non-dyadic point of the face: no monotone
  // direction there on the face, so undecided, and said where.
  const auto touch = trimmed_euler(V, ball({R(2, 3), R(2, 3), R(1, 2)}, R(1, 2)), EulerOptions{20000, 16});
  CHECK_FALSE(touch.decided);
  CHECK(touch.undecided_reason.find("near (u, v, w)") != std::string::npos);
  // A ball tangent to the split plane u = 1/2 at a non-dyadic point: the retried split fraction
  // moves the plane away, and the answer is decided and right.
  const auto tangent_split = trimmed_euler(V, ball({R(3, 5), R(3, 5), R(2, 3)}, R(2, 5)));
  INFO(tangent_split.undecided_reason);
  REQUIRE(tangent_split.decided);
  CHECK(tangent_split.chi == 1);
}

TEST_CASE("vrep trimmed euler: closed trivariates, identifications counted once in the image") {
  // A torus cell (a disk cell revolved, glued to itself at 0 = 360 degrees): a box in its
  // parameters (chi 1), a solid torus in space (chi 0).
  const auto cells = torus_cells<R>(R(3), R(1));
  for (const auto& c : cells) {
    const auto e = trimmed_euler(c, region_and<R>({}));
    REQUIRE(e.decided);
    CHECK(e.chi == 1);
    CHECK(e.image_chi == 0);
    CHECK(e.duality);
    CHECK(e.identified_faces >= 1);
  }
  // The singular cylinder (a rectangle revolved about z: an axis face collapsed, a seam): a solid
  // cylinder (chi 1); minus a coaxial rod it is a tube (a solid torus: chi 0) while its parameter
  // set stays a box (chi 1).
  const auto S = singular_cylinder<R>(R(1), R(1));
  const auto whole = trimmed_euler(S, region_and<R>({}));
  REQUIRE(whole.decided);
  CHECK(whole.chi == 1);
  CHECK(whole.image_chi == 1);
  const auto tube = trimmed_euler(S, region_not(rod(R(0), R(0), R(1, 2))));
  INFO(tube.undecided_reason);
  REQUIRE(tube.decided);
  CHECK(tube.chi == 1);
  CHECK(tube.image_chi == 0);
  // Cut by a plane through the axis instead: half a cylinder, a ball (chi 1) in space; in the
  // parameters the plane's two sides (two angular ranges) are two pieces.
  const auto halfcyl = trimmed_euler(S, half(R(0), R(0), R(1), R(0)));
  INFO(halfcyl.undecided_reason);
  REQUIRE(halfcyl.decided);
  CHECK(halfcyl.image_chi == 1);
}

TEST_CASE("vrep trimmed euler: random disjoint balls, cavities and islands") {
  std::mt19937 rng(20261203);
  const auto V = box(R(0), R(4));
  for (int trial = 0; trial < 6; ++trial) {
    // Balls in distinct cells of a 4 x 4 x 4 grid of unit cells, radius < 1/2 about a point at least
    // the radius from the cell's sides: disjoint, inside the box, off its faces.
    std::vector<Region<R>> holes, islands;
    std::vector<int> used;
    const int k = 1 + static_cast<int>(rng() % 3);
    while (static_cast<int>(used.size()) < k) {
      const int cell = static_cast<int>(rng() % 64);
      if (std::find(used.begin(), used.end(), cell) != used.end()) continue;
      used.push_back(cell);
      const R r(1 + static_cast<long>(rng() % 6), 17);  // 1/17 .. 6/17 < 1/2
      std::array<R, 3> c;
      for (int d = 0; d < 3; ++d) {
        const int at = (cell >> (2 * d)) & 3;
        const R lo = R(at) + r, span = R(1) - R(2) * r;
        c[d] = lo + span * R(1 + static_cast<long>(rng() % 29), 31);
      }
      holes.push_back(region_not(ball(c, r)));
      islands.push_back(ball(c, r));
    }
    INFO("trial " << trial << ", " << k << " balls");
    require_decided(trimmed_euler(V, region_and(holes)), 1 + k);
    require_decided(trimmed_euler(V, region_or(islands)), k);
  }
}

TEST_CASE("vrep trimmed euler: hostile input refused before the work") {
  const auto V = box(R(0), R(2));
  CHECK_THROWS_AS(trimmed_euler(V, region_and<R>({}), EulerOptions{0, 24}), ValidationError);
  CHECK_THROWS_AS(trimmed_euler(V, region_and<R>({}), EulerOptions{100, 0}), ValidationError);
  // A degree-9 leaf.
  Poly3<R> g;
  g.terms[{9, 0, 0}] = R(1);
  CHECK_THROWS_AS(trimmed_euler(V, region_leaf(g)), SizeLimitError);
  // A tiny budget is undecided, not wrong.
  const auto e = trimmed_euler(V, ball({R(1), R(1), R(1)}, R(1, 2)), EulerOptions{5, 24});
  CHECK_FALSE(e.decided);
  CHECK(e.undecided_reason.find("budget") != std::string::npos);
  // A model without cells, and one whose cell names a trivariate it does not hold.
  TrimmedModel<R> M;
  CHECK_THROWS_AS(model_euler(M), ValidationError);
  M.cells.emplace_back();
  M.cells.back().trivariate = 0;
  CHECK_THROWS_AS(model_euler(M), ValidationError);
  M.trivariates.push_back(V);
  M.cells.back().trivariate = 1;
  CHECK_THROWS_AS(model_euler(M), ValidationError);
}

namespace {

/// An independent estimate: the Euler characteristic V - E + F - C of the union of the closed
/// parameter voxels (n per direction) whose centres lie in the cell (double evaluation and
/// classification), which equals the cell's once the voxels resolve its features.
long voxel_chi(const BSpline<double>& V, const Region<double>& trim, int n) {
  std::vector<char> in(static_cast<std::size_t>(n) * n * n, 0);
  auto at = [&](int i, int j, int k) -> bool {
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n) return false;
    return in[(static_cast<std::size_t>(k) * n + j) * n + i] != 0;
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::vector<double> u(3);
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) u[d] = V.domain_lo(d) + (ijk[d] + 0.5) / n * (V.domain_hi(d) - V.domain_lo(d));
        auto p = evaluate(V, u);
        p.resize(3);
        in[(static_cast<std::size_t>(k) * n + j) * n + i] = classify_point(trim, p) == Truth::in;
      }
  long chi = 0;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        // The vertex (i, j, k), the edges, faces and cube starting there: each is in the complex
        // when a voxel around it is.
        bool v = false;
        for (int c = 0; c < 8; ++c) v = v || at(i - (c & 1), j - ((c >> 1) & 1), k - (c >> 2));
        chi += v;
        for (int d = 0; d < 3; ++d) {  // edge along d
          bool e = false;
          for (int c = 0; c < 4; ++c) {
            int o[3] = {0, 0, 0}, b = 0;
            for (int x = 0; x < 3; ++x)
              if (x != d) o[x] = -((c >> b++) & 1);
            e = e || at(i + o[0], j + o[1], k + o[2]);
          }
          chi -= e;
          bool f = false;  // face normal to d
          f = at(i, j, k) || at(i - (d == 0), j - (d == 1), k - (d == 2));
          chi += f;
        }
        chi -= at(i, j, k);
      }
  return chi;
}

}  // namespace

TEST_CASE("vrep trimmed euler: the cells of Figures 4 and 15 agree with their voxel complexes") {
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-3, 2), R(0), R(1)});
  const auto base = placed_primitive(box_cells<R>({R(-2), R(-2), R(0)}, {R(2), R(2), R(1)}), box_region<R>({R(-2), R(-2), R(0)}, {R(2), R(2), R(1)}), 2, {R(0), R(0), R(0)});
  const auto post = placed_primitive(cylinder_cells<R>(R(1), R(3)), cylinder_region<R>(R(1), R(3)), 2, {R(0), R(0), R(0)});
  const auto hole1 = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(3, 2), R(3, 2), R(-1)});
  const auto hole2 = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(-3, 2), R(-3, 2), R(-1)});
  const std::vector<TrimmedModel<R>> models{
      trimmed_boolean(cone, cyl, BooleanOp::unite),
      trimmed_boolean(trimmed_boolean(trimmed_boolean(base, post, BooleanOp::unite), hole1, BooleanOp::subtract), hole2, BooleanOp::subtract)};
  std::map<long, int> seen;
  for (const auto& M : models) {
    const auto D = trimmed_to_double(M);
    for (std::size_t k = 0; k < M.cells.size(); ++k) {
      const auto e = trimmed_euler(M.trivariates[M.cells[k].trivariate], M.cells[k].trim);
      INFO("cell " << k << " (" << M.cells[k].category << "): " << e.undecided_reason);
      REQUIRE(e.decided);
      CHECK(e.duality);
      CHECK(e.chi == voxel_chi(D.trivariates[D.cells[k].trivariate], D.cells[k].trim, 40));
      ++seen[e.chi];
    }
  }
  // Not all alike: cells of one piece (1), two pieces (2), a tunnel (0), three holes (-2).
  CHECK(seen.size() >= 4);
}

TEST_CASE("vrep trimmed euler: the model after a Boolean, with inclusion-exclusion") {
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-3, 2), R(0), R(1)});
  auto chi = [](const TrimmedModel<R>& M) {
    const auto e = model_euler(M);
    INFO(e.undecided_reason);
    REQUIRE(e.decided);
    CHECK(e.duality);
    return e.image_chi;
  };
  const long a = chi(cone), b = chi(cyl);
  const long u = chi(trimmed_boolean(cone, cyl, BooleanOp::unite)), i = chi(trimmed_boolean(cone, cyl, BooleanOp::intersect));
  const long amb = chi(trimmed_boolean(cone, cyl, BooleanOp::subtract));
  CHECK(a == 1);
  CHECK(b == 1);
  CHECK(i == 1);  // the rod's part inside the cone
  CHECK(u == a + b - i);
  CHECK(u == 1);
  CHECK(amb == 0);  // the cone with a tunnel
  // Figure 15's kind: two through-holes, genus 2.
  const auto base = placed_primitive(box_cells<R>({R(-2), R(-2), R(0)}, {R(2), R(2), R(1)}), box_region<R>({R(-2), R(-2), R(0)}, {R(2), R(2), R(1)}), 2, {R(0), R(0), R(0)});
  const auto post = placed_primitive(cylinder_cells<R>(R(1), R(3)), cylinder_region<R>(R(1), R(3)), 2, {R(0), R(0), R(0)});
  const auto hole = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(3, 2), R(3, 2), R(-1)});
  const auto hole2 = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(-3, 2), R(-3, 2), R(-1)});
  const auto P = trimmed_boolean(base, post, BooleanOp::unite);
  CHECK(chi(P) == 1);
  const auto P1 = trimmed_boolean(P, hole, BooleanOp::subtract);
  CHECK(chi(P1) == 0);
  CHECK(chi(trimmed_boolean(P1, hole2, BooleanOp::subtract)) == -1);
  // Figure 3's L: O1 = [0,2]x[0,1]x[0,1], O2 = [1,2]x[0,2]x[0,1], faces partly coplanar.
  const auto O1 = placed_primitive(box_cells<R>({R(0), R(0), R(0)}, {R(2), R(1), R(1)}), box_region<R>({R(0), R(0), R(0)}, {R(2), R(1), R(1)}), 2, {R(0), R(0), R(0)});
  const auto O2 = placed_primitive(box_cells<R>({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), box_region<R>({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), 2, {R(0), R(0), R(0)});
  CHECK(chi(trimmed_boolean(O1, O2, BooleanOp::unite)) == 1);
  CHECK(chi(trimmed_boolean(O1, O2, BooleanOp::intersect)) == 1);
}

TEST_CASE("vrep trimmed euler: touching solids, where the closed reading is not the regularized one") {
  // Two boxes sharing the face x = 1: the closed intersection is that square (chi 1), the
  // regularized one is empty; the open set is empty, so duality fails and says so.
  const auto A = box_region<R>({R(0), R(0), R(0)}, {R(1), R(1), R(1)});
  const auto B = box_region<R>({R(1), R(0), R(0)}, {R(2), R(1), R(1)});
  const std::vector<R> lo{R(-1), R(-1), R(-1)}, hi{R(3), R(3), R(3)};
  const auto meet = region_euler(region_and<R>({A, B}), lo, hi);
  REQUIRE(meet.decided);
  CHECK(meet.chi == 1);
  CHECK(meet.interior_chi_c == 0);
  CHECK_FALSE(meet.duality);
  // Their union is one box (chi 1): the open reading has a crack along the shared face (two open
  // boxes, chi_c -2), so duality fails here too: the closed reading is right, but not proved.
  const auto join = region_euler(region_or<R>({A, B}), lo, hi);
  REQUIRE(join.decided);
  CHECK(join.chi == 1);
  CHECK(join.interior_chi_c == -2);
  CHECK_FALSE(join.duality);
  // Inclusion-exclusion holds for the closed readings exactly: 1 + 1 - 1.
  CHECK(join.chi == region_euler(A, lo, hi).chi + region_euler(B, lo, hi).chi - meet.chi);
  // Two balls touching at a point: chi 1 + 1 - 1.
  const auto b1 = ball({R(0), R(0), R(0)}, R(1)), b2 = ball({R(2), R(0), R(0)}, R(1));
  const std::vector<R> lo2{R(-3, 2), R(-3, 2), R(-3, 2)}, hi2{R(7, 2), R(3, 2), R(3, 2)};
  const auto touch = region_euler(region_or<R>({b1, b2}), lo2, hi2), point = region_euler(region_and<R>({b1, b2}), lo2, hi2);
  INFO(touch.undecided_reason << " / " << point.undecided_reason);
  REQUIRE(touch.decided);
  REQUIRE(point.decided);
  CHECK(point.chi == 1);
  CHECK(touch.chi == 1);
  CHECK_FALSE(point.duality);
}

TEST_CASE("vrep trimmed euler: random balls and rods, overlapping, against the voxel complex") {
  // Random unions and differences of balls and rods (crossing each other and the box's faces),
  // kept only when no two surfaces come within a few voxels of tangency, so the voxel complex at
  // 48^3 resolves them; chi exact against chi of the voxels (checked at 48^3 points).
  std::mt19937 rng(77);
  const auto V = box(R(0), R(1));
  const auto Vd = box_cells<double>({0, 0, 0}, {1, 1, 1}).front();
  const int n = 48;
  const double margin = 3.0 / n;
  int checked = 0;
  int undecided = 0;
  for (int trial = 0; trial < 400 && checked < 16; ++trial) {
    struct Shape {
      bool is_ball;
      int axis;  // rods: the axis direction
      double c[3], r;
      std::array<R, 3> ce;
      R re;
    };
    std::vector<Shape> shapes;
    const int k = 2 + static_cast<int>(rng() % 3);
    for (int s = 0; s < k; ++s) {
      Shape x;
      x.is_ball = rng() % 2;
      x.axis = static_cast<int>(rng() % 3);
      for (int d = 0; d < 3; ++d) {
        x.ce[d] = R(static_cast<long>(rng() % 41), 40);
        x.c[d] = to_double(x.ce[d]);
      }
      x.re = R(4 + static_cast<long>(rng() % 12), 40);
      x.r = to_double(x.re);
      shapes.push_back(x);
    }
    // Distance between the surfaces' defining centres (balls) or axes (rods) against the radii:
    // refuse near-tangencies between two shapes and between a shape and a face of the box.
    bool clear = true;
    for (std::size_t i = 0; i < shapes.size() && clear; ++i) {
      const auto& a = shapes[i];
      for (int d = 0; d < 3 && clear; ++d) {
        if (!a.is_ball && d == a.axis) continue;
        for (double face : {0.0, 1.0}) clear = clear && std::abs(std::abs(a.c[d] - face) - a.r) > margin;
      }
      for (std::size_t j = i + 1; j < shapes.size() && clear; ++j) {
        const auto& b = shapes[j];
        // The distance whose equality with r_a + r_b or |r_a - r_b| is tangency: between centres
        // (two balls), from a centre to an axis, between parallel axes (in the plane across), or
        // between skew axes (along the third direction).
        double d2 = 0;
        if (!a.is_ball && !b.is_ball && a.axis != b.axis) {
          const int third = 3 - a.axis - b.axis;
          d2 = (a.c[third] - b.c[third]) * (a.c[third] - b.c[third]);
        } else
          for (int d = 0; d < 3; ++d)
            if ((a.is_ball || d != a.axis) && (b.is_ball || d != b.axis)) d2 += (a.c[d] - b.c[d]) * (a.c[d] - b.c[d]);
        const double dist = std::sqrt(d2);
        clear = clear && std::abs(dist - a.r - b.r) > margin && std::abs(dist - std::abs(a.r - b.r)) > margin;
      }
    }
    if (!clear) continue;
    std::vector<Region<R>> parts;
    for (const auto& x : shapes)
      parts.push_back(x.is_ball ? ball(x.ce, x.re) : rod(x.ce[(x.axis + 1) % 3], x.ce[(x.axis + 2) % 3], x.re, (x.axis + 1) % 3, (x.axis + 2) % 3));
    const bool subtract = trial % 2;
    const auto reg = subtract ? region_not(region_or(parts)) : region_or(parts);
    const auto e = trimmed_euler(V, reg);
    INFO("trial " << trial << ": " << k << " shapes, " << (subtract ? "box minus their union" : "their union in the box") << "; " << e.undecided_reason);
    if (!e.decided && ++undecided) continue;  // near a singular point of the voxel-level-clear configuration: said, not wrong
    CHECK(e.chi == voxel_chi(Vd, region_to_double(reg), n));
    ++checked;
  }
  INFO("undecided " << undecided);
  CHECK(checked >= 12);
}

TEST_CASE("vrep trimmed euler: coplanar contact read from inside, across inner knots too") {
  // A post B = [1/2, 3/2]^2 x [0, 2] standing in a plate A = [0, 2]^2 x [0, 1], their bottom faces
  // coplanar: B - A is the post's upper part (chi 1), not that plus a sheet at z = 0. With an inner
  // knot in the post's trivariate the bottom face is split by a knot line, which must not count
  // either.
  auto B = box_cells<R>({R(1, 2), R(1, 2), R(0)}, {R(3, 2), R(3, 2), R(2)}).front();
  const auto A = box_region<R>({R(0), R(0), R(0)}, {R(2), R(2), R(1)});
  for (const auto& V : {B, refine_knots(B, 0, std::vector<R>{R(1, 3)}), refine_knots(refine_knots(B, 0, std::vector<R>{R(1, 3)}), 1, std::vector<R>{R(3, 4)})}) {
    const auto e = trimmed_euler(V, region_not(A));
    REQUIRE(e.decided);
    CHECK(e.chi == 1);
    CHECK(e.interior_chi_c == -1);
    CHECK(e.duality);
    CHECK(e.resolved_contacts > 0);
    CHECK(e.unresolved_contacts == 0);
  }
}
