// Booleans on V-models (issue 18, first part): exact cuts by parameter planes, Figure 3's counts,
// exact volumes and the union identity, coplanar and near contact decided exactly.
#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/boolean/nef_check.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/blend.hpp"
#include "vrep/primitives/primitives.hpp"

using namespace splinex;
using R = Rational;

namespace {

VModel<R> box(std::vector<R> lo, std::vector<R> hi) { return glue(box_cells<R>(lo, hi)); }

R volume(const VModel<R>& M) {
  R v(0);
  for (std::size_t c = 0; c < M.cells.size(); ++c) v += cell_volume(M, c);
  return v;
}

std::size_t point_at(const VModel<R>& M, const std::vector<R>& x) {
  for (std::size_t p = 0; p < M.points.size(); ++p)
    if (M.points[p].at == x) return p;
  FAIL("no V-point at the location");
  return 0;
}

std::size_t curve_between(const VModel<R>& M, std::size_t p, std::size_t q) {
  for (std::size_t c = 0; c < M.curves.size(); ++c) {
    const auto& e = M.curves[c].ends;
    if ((e[0] == p && e[1] == q) || (e[0] == q && e[1] == p)) return c;
  }
  FAIL("no V-curve between the points");
  return 0;
}

void check_ok(const VModel<R>& M, long euler) {
  const auto chk = check_invariants(M);
  INFO((chk.failures.empty() ? std::string() : chk.failures.front()));
  CHECK(chk.ok());
  CHECK(chk.euler == euler);
}

}  // namespace

TEST_CASE("vrep boolean: Figure 3, the union of two boxes, with the paper's counts") {
  // O1 = [0,2]x[0,1]x[0,1], O2 = [1,2]x[0,2]x[0,1]: faces partly coplanar (y = 0, z = 0, z = 1, x = 2).
  const auto O1 = box({0, 0, 0}, {2, 1, 1}), O2 = box({1, 0, 0}, {2, 2, 1});
  BooleanStats<R> st;
  const auto M = boolean_op(O1, O2, BooleanOp::unite, R(0), Blend::sum_clipped, {}, &st);
  CHECK(M.cells.size() == 3);
  CHECK(M.half_surfaces.size() == 18);
  CHECK(M.internal_surfaces() == 2);
  CHECK(M.boundary_surfaces() == 14);
  CHECK(M.points.size() == 16);
  CHECK(M.curves.size() == 28);
  check_ok(M, 1);
  // Category B holds both trivariates: its piece, O1's and O2's.
  std::size_t both = 0;
  for (const auto& c : M.cells)
    if (c.name == "A0*B0") {
      ++both;
      CHECK(c.trivariates.size() == 3);
    } else
      CHECK(c.trivariates.size() == 2);
  CHECK(both == 1);
  // V-curve 1 (x = 1, y = 1, along z): four V-surfaces, six half-V-surfaces; its V-points each
  // start or end five V-curves.
  const std::size_t p = point_at(M, {1, 1, 0}), q = point_at(M, {1, 1, 1});
  const std::size_t c1 = curve_between(M, p, q);
  CHECK(M.curves[c1].surfaces.size() == 4);
  std::size_t halves = 0;
  for (std::size_t s : M.curves[c1].surfaces) halves += M.surfaces[s].halves.size();
  CHECK(halves == 6);
  CHECK(M.points[p].curves.size() == 5);
  CHECK(M.points[q].curves.size() == 5);
  // V-curve 2 (an outer edge, x = 0, y = 0, along z): two V-surfaces; its V-points three V-curves.
  const std::size_t r = point_at(M, {0, 0, 0}), s = point_at(M, {0, 0, 1});
  const std::size_t c2 = curve_between(M, r, s);
  CHECK(M.curves[c2].surfaces.size() == 2);
  CHECK(M.points[r].curves.size() == 3);
  CHECK(M.points[s].curves.size() == 3);
  CHECK(st.cuts == 2);  // x = 1 in O1, y = 1 in O2
  CHECK(volume(M) == R(3));
}

TEST_CASE("vrep boolean: exact volumes, the union identity, and the three operations") {
  const auto A = box({0, 0, 0}, {R(7, 3), 1, R(5, 7)});
  const auto B = box({R(1, 3), R(1, 2), -1}, {3, 2, R(1, 2)});
  const R vA = volume(A), vB = volume(B);
  CHECK(vA == R(7, 3) * R(5, 7));
  CHECK(vB == (R(3) - R(1, 3)) * R(3, 2) * R(3, 2));
  const auto I = boolean_op(A, B, BooleanOp::intersect);
  const auto U = boolean_op(A, B, BooleanOp::unite);
  const auto S = boolean_op(A, B, BooleanOp::subtract);
  const auto S2 = boolean_op(B, A, BooleanOp::subtract);
  const R vI = (R(7, 3) - R(1, 3)) * R(1, 2) * R(1, 2);
  CHECK(volume(I) == vI);
  CHECK(volume(U) == vA + vB - vI);
  CHECK(volume(S) == vA - vI);
  CHECK(volume(S2) == vB - vI);
  CHECK(volume(U) == volume(S) + volume(S2) + volume(I));
  check_ok(I, 1);
  check_ok(U, 1);
  check_ok(S, 1);
  check_ok(S2, 1);
  // Membership: a point in the intersection lies in a cell holding both trivariates.
  const auto in = cells_containing(U, {R(1), R(3, 4), R(1, 4)});
  REQUIRE(in.size() == 1);
  CHECK(U.cells[in[0]].trivariates.size() == 3);
  CHECK(cells_containing(U, {R(10), R(0), R(0)}).empty());
}

TEST_CASE("vrep boolean: a hole through a slab is a solid torus (Euler 0), the same tiling exactly") {
  const auto slab = box({0, 0, 0}, {3, 3, 1}), post = box({1, 1, -1}, {2, 2, 2});
  const auto ring = boolean_op(slab, post, BooleanOp::subtract);
  CHECK(ring.cells.size() == 8);
  check_ok(ring, 0);
  CHECK(volume(ring) == R(8));
  // The union of the slab and the post: the post sticks out on both sides.
  const auto U = boolean_op(slab, post, BooleanOp::unite);
  check_ok(U, 1);
  CHECK(volume(U) == R(9) + R(1) + R(1));
}

TEST_CASE("vrep boolean: contact decided exactly, coplanar and 2^-40 apart") {
  const auto A = box({0, 0, 0}, {1, 1, 1});
  const auto touching = box({1, 0, 0}, {2, 1, 1});
  const auto U = boolean_op(A, touching, BooleanOp::unite);
  CHECK(U.cells.size() == 2);
  CHECK(U.internal_surfaces() == 1);  // glued at the shared face
  CHECK_THROWS_AS(boolean_op(A, touching, BooleanOp::intersect), DomainError);  // touching only: empty
  const R gap = R(1) / R(Integer(1) << 40);
  const auto apart = box({1 + gap, 0, 0}, {2, 1, 1});
  const auto U2 = boolean_op(A, apart, BooleanOp::unite);
  CHECK(U2.cells.size() == 2);
  CHECK(U2.internal_surfaces() == 0);  // exactly: not touching
  CHECK(check_invariants(U2).euler == 2);  // two balls
  // In double with an IRIT-style tolerance above the gap, the gap closes: a false glue.
  auto dbl = [](const VModel<R>& M) {
    std::vector<BSpline<double>> v;
    for (const auto& t : M.trivariates) v.push_back(convert<double>(t, [](const R& x) { return to_double(x); }));
    return glue(v);
  };
  const auto D = boolean_op(dbl(A), dbl(apart), BooleanOp::unite, 1e-9);
  CHECK(D.internal_surfaces() == 1);
  CHECK(boolean_op(dbl(A), dbl(apart), BooleanOp::unite, 1e-15).internal_surfaces() == 0);
}

TEST_CASE("vrep boolean: attributes by category and the summing blend of Figure 5") {
  auto A = box({0, 0, 0}, {2, 1, 1});
  auto B = box({1, 0, 0}, {3, 1, 1});
  A.cells[0].attributes.constants["colour"] = {R(1), R(0), R(3, 4)};
  B.cells[0].attributes.constants["colour"] = {R(0), R(1), R(1, 2)};
  const auto U = boolean_op(A, B, BooleanOp::unite);
  REQUIRE(U.cells.size() == 3);
  for (const auto& c : U.cells) {
    const auto& col = c.attributes.constants.at("colour");
    if (c.name == "A0") CHECK(col == std::vector<R>{1, 0, R(3, 4)});
    else if (c.name == "B0") CHECK(col == std::vector<R>{0, 1, R(1, 2)});
    else CHECK(col == std::vector<R>{1, 1, 1});  // 3/4 + 1/2 clipped to 1
  }
  const auto S = boolean_op(A, B, BooleanOp::unite, R(0), Blend::sum);
  for (const auto& c : S.cells)
    if (c.name == "A0*B0") CHECK(c.attributes.constants.at("colour") == std::vector<R>{1, 1, R(5, 4)});
}

TEST_CASE("vrep boolean: what is not built says so") {
  const auto cyl = glue(cylinder_cells<R>(R(1), R(2)));
  const auto B = box({0, 0, 0}, {1, 1, 1});
  CHECK_THROWS_AS(boolean_op(B, cyl, BooleanOp::unite), DomainError);  // curved cells
  // A box rotated about z by a Pythagorean angle cuts the axis-aligned box along planes that are
  // not parameter planes of it.
  auto rot = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  for (std::size_t i = 0; i < rot.size(); ++i) {
    const R x = rot.points[i * 3], y = rot.points[i * 3 + 1];
    rot.points[i * 3] = R(4, 5) * x - R(3, 5) * y + R(1, 2);
    rot.points[i * 3 + 1] = R(3, 5) * x + R(4, 5) * y;
  }
  CHECK_THROWS_AS(boolean_op(B, glue(std::vector<BSpline<R>>{rot}), BooleanOp::unite), DomainError);
  CHECK_THROWS_AS(cell_volume(cyl, 1), DomainError);  // rational: no enclosure yet
}

TEST_CASE("vrep boolean: a cut that would leave a T-junction is carried into the neighbour") {
  // A: two boxes side by side in x; b overlaps only the first, and its plane z = 1/2 splits the
  // first's face x = 1. The second box takes the cut too, so every face is glued to a whole face.
  auto cells = box_cells<R>({0, 0, 0}, {1, 1, 1});
  cells.push_back(box_cells<R>({1, 0, 0}, {2, 1, 1})[0]);
  const auto A = glue(cells);
  const auto b = box({R(1, 2), 0, 0}, {1, 1, R(1, 2)});
  BooleanStats<R> st;
  const auto U = boolean_op(A, b, BooleanOp::unite, R(0), Blend::sum_clipped, {}, &st);
  CHECK(st.rounds == 2);
  check_ok(U, 1);
  CHECK(U.cells.size() == 6);  // 4 pieces of the first box, 2 of the second
  CHECK(volume(U) == R(2));
  const auto S = boolean_op(A, b, BooleanOp::subtract);
  check_ok(S, 1);
  CHECK(volume(S) == R(2) - R(1, 4));
}

TEST_CASE("vrep boolean: CGAL's exact Nef polyhedra agree (volumes and boundary counts)") {
  // Figure 3's union: an L-shape of 12 vertices, 18 edges, 8 facets.
  const auto O1 = box({0, 0, 0}, {2, 1, 1}), O2 = box({1, 0, 0}, {2, 2, 1});
  const auto U = boolean_op(O1, O2, BooleanOp::unite);
  const auto n = nef_boolean(O1, O2, BooleanOp::unite), v = boundary_counts(U);
  CHECK(n.volume == R(3));
  CHECK(v.volume == n.volume);
  CHECK(n.vertices == 12);
  CHECK(n.edges == 18);
  CHECK(n.facets == 8);
  CHECK(v.vertices == n.vertices);
  CHECK(v.edges == n.edges);
  CHECK(v.facets == n.facets);
  // Random boxes with coordinates in {0, 1/2, ..., 3} (coplanar and touching faces are common):
  // every operation, volumes exactly, counts where both boundaries are manifold.
  test::XorShift next{0x9e3779b97f4a7c15ULL};
  auto random_box = [&]() {
    std::vector<R> lo, hi;
    for (int d = 0; d < 3; ++d) {
      const int a = next(6), b = a + 1 + next(6 - a);
      lo.push_back(R(a, 2));
      hi.push_back(R(b, 2));
    }
    return box(lo, hi);
  };
  int compared = 0, counted = 0, empty = 0;
  for (int k = 0; k < 100; ++k) {
    auto A = random_box();
    const auto B = random_box();
    if (k % 4 == 3) {  // a model of several cells: the union of two boxes
      try {
        A = boolean_op(A, random_box(), BooleanOp::unite);
      } catch (const DomainError&) {
        continue;
      }
    }
    for (BooleanOp op : {BooleanOp::intersect, BooleanOp::subtract, BooleanOp::unite}) {
      const auto n = nef_boolean(A, B, op);
      VModel<R> M;
      try {
        M = boolean_op(A, B, op);
      } catch (const DomainError& e) {
        INFO(e.what());
        CHECK(n.volume == R(0));  // only an empty result is refused
        ++empty;
        continue;
      }
      const auto v = boundary_counts(M);
      std::string desc;
      for (const VModel<R>* X : {static_cast<const VModel<R>*>(&A), &B})
        for (const auto& c : X->cells) {
          const auto& V = X->trivariates[c.trivariates.front()];
          desc += "[";
          for (std::size_t i : std::vector<std::size_t>{0, V.size() - 1})
            for (int d = 0; d < 3; ++d) desc += to_fraction_string(V.points[i * 3 + d]) + (d < 2 ? "," : i == 0 ? " .. " : "");
          desc += "] ";
        }
      INFO("case " << k << " op " << to_string(op) << ": " << desc << " cells " << M.cells.size());
      CHECK(v.volume == n.volume);
      CHECK(check_invariants(M).ok());
      ++compared;
      if (n.manifold && v.manifold) {
        CHECK(v.vertices == n.vertices);
        CHECK(v.edges == n.edges);
        CHECK(v.facets == n.facets);
        ++counted;
      }
    }
  }
  CHECK(compared > 150);
  CHECK(counted > 100);
  WARN("Nef comparisons: " << compared << " volumes, " << counted << " boundary counts, " << empty << " empty results");
}

TEST_CASE("vrep boolean: a grid of boxes with a box inside: union, and a cavity (Euler 2)") {
  std::vector<BSpline<R>> cells;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) cells.push_back(box_cells<R>({R(i), R(j), R(k)}, {R(i + 1), R(j + 1), R(k + 1)})[0]);
  const auto grid = glue(cells);
  const auto inner = box({R(1, 2), R(1, 2), R(1, 2)}, {R(5, 2), R(5, 2), R(5, 2)});
  const auto U = boolean_op(grid, inner, BooleanOp::unite);
  check_ok(U, 1);
  CHECK(volume(U) == R(27));
  const auto S = boolean_op(grid, inner, BooleanOp::subtract);
  check_ok(S, 2);  // a solid with a cavity: a thick sphere, Euler characteristic 2
  CHECK(volume(S) == R(27) - R(8));
  const auto n = nef_boolean(grid, inner, BooleanOp::subtract);
  CHECK(n.volume == volume(S));
  const auto I = boolean_op(grid, inner, BooleanOp::intersect);
  check_ok(I, 1);
  CHECK(volume(I) == R(8));
  CHECK(I.cells.size() == 27);  // each grid box contributes its corner cube of the inner box
}

TEST_CASE("vrep volume enclosures of rational cells: the cylinder contains pi r^2 h, the torus 2 pi^2 R r^2") {
  const R pi_lo(R(314159265358979LL, 100000000000000LL)), pi_hi(R(314159265358980LL, 100000000000000LL));
  const auto cyl = cylinder_cells<R>(R(1), R(2));
  R lo(0), hi(0);
  for (const auto& V : cyl) {
    const auto e = volume_enclosure(V, 64);
    CHECK(e.lower <= e.upper);
    lo += e.lower;
    hi += e.upper;
  }
  CHECK(lo <= pi_hi * 2);
  CHECK(pi_lo * 2 <= hi);
  CHECK(hi - lo < R(1, 10));  // 0.073 with 64 boxes per cell (0.009 with 512; the gap shrinks as 1 / boxes)
  WARN("cylinder r = 1, h = 2: volume in [" << to_double(lo) << ", " << to_double(hi) << "], 2 pi = 6.2831853");
  const auto tor = torus_cells<R>(R(3), R(1));
  lo = hi = R(0);
  for (const auto& V : tor) {
    const auto e = volume_enclosure(V, 64);
    lo += e.lower;
    hi += e.upper;
  }
  CHECK(lo <= 6 * pi_hi * pi_hi);
  CHECK(6 * pi_lo * pi_lo <= hi);
  // Polynomial cells: exact, equal to cell_volume.
  const auto B = box({0, 0, 0}, {R(1, 3), 2, R(5, 7)});
  const auto e = volume_enclosure(B.trivariates[0]);
  CHECK(e.lower == e.upper);
  CHECK(e.lower == cell_volume(B, 0));
  // Degree 0 in a direction: det J is 0, refused as jacobian_determinant refuses it (it divided
  // by zero before).
  auto flat = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  flat.degrees[0] = 0;
  flat.knots[0] = {0, 1};
  flat.points.resize(flat.points.size() / 2);
  for (std::size_t i = 0; i < flat.size(); ++i) flat.points[i * 3] = R(0);
  CHECK_THROWS_AS(volume_enclosure(flat), ValidationError);
}

TEST_CASE("vrep distance blend (Eq. 2): certified enclosures, exact at the interfaces, singular at r") {
  // V1 = [0,2]^2 x [0,1]; V2 = a square turned 45 degrees (diamond (1,0), (2,1), (1,2), (0,1))
  // extruded over z in [-1, 2]: a parallelepiped with planar faces, inside V1's square.
  const auto V1 = box({0, 0, 0}, {2, 2, 1});
  auto P = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  for (std::size_t i = 0; i < P.size(); ++i) {
    const R u = P.points[i * 3], v = P.points[i * 3 + 1], w = P.points[i * 3 + 2];
    P.points[i * 3] = 1 + u - v;
    P.points[i * 3 + 1] = u + v;
    P.points[i * 3 + 2] = -1 + 3 * w;
  }
  const auto V2 = glue(std::vector<BSpline<R>>{P});
  const DistanceBlend blend(V1, V2);
  const std::vector<R> red{1}, blue{0};
  // The centre: d1 = 1/2 (V1's top and bottom inside V2), d2 = 1/sqrt 2 (the diamond's sides):
  // A = (1/2) / (1/2 + 1/sqrt 2) = sqrt 2 - 1, irrational; the enclosure holds it.
  const auto c = blend.at({1, 1, R(1, 2)}, red, blue);
  REQUIRE(c.value.size() == 1);
  CHECK(c.d1_squared == R(1, 4));
  CHECK(c.d2_squared == R(1, 2));
  const auto& e = c.value[0];
  CHECK(e.lo < e.hi);
  CHECK((e.lo + 1) * (e.lo + 1) <= 2);
  CHECK(2 <= (e.hi + 1) * (e.hi + 1));
  CHECK(e.hi - e.lo < R(1) / R(Integer(1) << 100));
  // k = 2: (1/4) / (1/4 + 1/2) = 1/3 exactly inside the enclosure.
  const auto c2 = blend.at({1, 1, R(1, 2)}, red, blue, 2);
  CHECK(c2.value[0].lo <= R(1, 3));
  CHECK(R(1, 3) <= c2.value[0].hi);
  // On the diamond's side inside V1 (x + y = 1, z = 1/2): d2 = 0, A = A1 exactly; V1 alone there
  // gives A1 too: C^0 across that interface (and within 2^-j of it the value is within a bound).
  const auto on = blend.at({R(1, 2), R(1, 2), R(1, 2)}, red, blue);
  REQUIRE(on.value.size() == 1);
  CHECK(on.value[0].exact());
  CHECK(on.value[0].lo == 1);
  const auto out = blend.at({R(1, 4), R(1, 4), R(1, 2)}, red, blue);  // V1 only
  CHECK(out.value[0].lo == 1);
  for (int j = 4; j <= 40; j += 4) {
    const R t = R(1) / R(Integer(1) << j);
    const auto near = blend.at({R(1, 2) + t, R(1, 2) + t, R(1, 2)}, red, blue);  // 2^-j sqrt 2 inside
    CHECK(1 - near.value[0].lo <= 6 * t);  // A1 - A <= d2 / (d1 + d2) <= sqrt 2 t / (1/2 - ...) < 6 t
  }
  // The point r of Figure 6: on V1's top face inside V2 and on the diamond's side: both zero.
  const auto r = blend.at({R(1, 2), R(1, 2), R(1)}, red, blue);
  CHECK(r.singular);
  CHECK(r.value.empty());
  CHECK_THROWS_AS(blend.at({R(5), R(5), R(5)}, red, blue), ValidationError);
}

TEST_CASE("vrep boolean: a curved model cut by a slab along parameter planes (the cylinder's cells)") {
  const R pi_lo(R(314159265358979LL, 100000000000000LL)), pi_hi(R(314159265358980LL, 100000000000000LL));
  const auto cyl = glue(cylinder_cells<R>(R(1), R(2)));
  const auto slab = box({-5, -5, R(1, 2)}, {5, 5, 1});
  const auto I = boolean_op(cyl, slab, BooleanOp::intersect);
  check_ok(I, 1);
  CHECK(I.cells.size() == 5);
  R lo(0), hi(0);
  for (const auto& c : I.cells) {
    const auto e = volume_enclosure(I.trivariates[c.trivariates.front()], 32);
    lo += e.lower;
    hi += e.upper;
  }
  CHECK(lo <= pi_hi / 2);
  CHECK(pi_lo / 2 <= hi);
  const auto S = boolean_op(cyl, slab, BooleanOp::subtract);
  CHECK(S.cells.size() == 10);
  check_ok(S, 2);  // two disks apart
  CHECK(S.internal_surfaces() == 16);
  CHECK_THROWS_AS(boolean_op(cyl, slab, BooleanOp::unite), DomainError);  // B's pieces need A's planes
  CHECK_THROWS_AS(boolean_op(cyl, box({0, -5, 0}, {5, 5, 1}), BooleanOp::intersect), DomainError);  // x = 0: curved
  // A plane touching the cylinder (x = 1 at (1, 0, z)): tangential contact with a curved cell is not
  // decided by control points (the arc's middle control point lies beyond the plane): refused.
  CHECK_THROWS_AS(boolean_op(cyl, box({1, -5, -5}, {5, 5, 5}), BooleanOp::subtract), DomainError);
  // A plane beyond it (x = 2): nothing cut, the cylinder is kept whole.
  const auto apart = boolean_op(cyl, box({2, -5, -5}, {5, 5, 5}), BooleanOp::subtract);
  CHECK(apart.cells.size() == 5);
}

TEST_CASE("vrep boolean: hostile inputs give a typed error or a valid model") {
  const auto unit = box({0, 0, 0}, {1, 1, 1});
  auto from = [](BSpline<R> V) { return glue(std::vector<BSpline<R>>{std::move(V)}); };
  auto attempt = [&](const VModel<R>& A, const VModel<R>& B) {
    for (BooleanOp op : {BooleanOp::intersect, BooleanOp::subtract, BooleanOp::unite}) {
      try {
        const auto M = boolean_op(A, B, op);
        CHECK(check_invariants(M).ok());
      } catch (const Error&) {
        // the typed answer
      }
    }
  };
  // A mirrored box (negative det J): the planes are oriented by the cell's centre, not its sign.
  auto mirrored = box_cells<R>({R(1, 2), 0, 0}, {2, 1, 1})[0];
  for (std::size_t i = 0; i < mirrored.size(); ++i) mirrored.points[i * 3] = R(5, 2) - mirrored.points[i * 3];
  const auto M1 = boolean_op(unit, from(mirrored), BooleanOp::unite);
  CHECK(check_invariants(M1).ok());
  CHECK(volume(M1) == R(2));
  // A flat box (zero thickness): no planes, and as A it lies in a plane of B's cell.
  auto flat = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  for (std::size_t i = 0; i < flat.size(); ++i) flat.points[i * 3 + 2] = R(1, 2);
  CHECK_THROWS_AS(boolean_op(unit, from(flat), BooleanOp::unite), DomainError);
  attempt(from(flat), unit);
  // B with overlapping cells.
  auto two = box_cells<R>({0, 0, 0}, {1, 1, 1});
  two.push_back(box_cells<R>({R(1, 2), 0, 0}, {R(3, 2), 1, 1})[0]);
  CHECK_THROWS_AS(boolean_op(box({R(1, 4), 0, 0}, {R(5, 4), 1, 1}), glue(two), BooleanOp::intersect), DomainError);
  // A non-convex hexahedron with planar faces is not possible; one with a face bent is not planar.
  auto bent = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  bent.points[7 * 3 + 2] = R(3, 2);  // corner (1,1,1) pulled up: the top face is no longer planar
  CHECK_FALSE(convex_planes(bent).has_value());
  CHECK_THROWS_AS(boolean_op(unit, from(bent), BooleanOp::unite), DomainError);
  attempt(from(bent), box({R(1, 4), R(1, 4), R(1, 4)}, {R(3, 4), R(3, 4), R(3, 4)}));
  // A box in a refined cubic space (knots 1/3, 2/3): the planes still cut along parameter planes.
  auto fine = elevate_degree(box_cells<R>({0, 0, 0}, {3, 1, 1})[0], 0, 2);
  fine = refine_knots(fine, 0, {R(1, 3), R(2, 3)});
  const auto F = from(fine);
  CHECK(volume(boolean_op(F, box({1, 0, 0}, {R(5, 2), 2, 2}), BooleanOp::subtract)) == R(3, 2));
  // A box whose x is not linear in u (middle control points moved along x): the plane x = 1 meets
  // it at an irrational parameter in general: refused, not approximated.
  auto skew = elevate_degree(box_cells<R>({0, 0, 0}, {2, 1, 1})[0], 0, 1);
  for (std::size_t i = 0; i < skew.size(); ++i)
    if (i % 3 == 1) skew.points[i * 3] = R(3, 2);
  CHECK_THROWS_AS(boolean_op(from(skew), box({1, 0, 0}, {3, 1, 1}), BooleanOp::subtract), DomainError);
  // Coordinates far apart in scale: exact all the same.
  const R big = R(Integer(1) << 60), tiny = R(1) / R(Integer(1) << 60);
  const auto A = box({0, 0, 0}, {big, 1, 1}), B = box({big - tiny, 0, 0}, {big + 1, 1, 1});
  const auto U = boolean_op(A, B, BooleanOp::unite);
  CHECK(volume(U) == big + 1);
  CHECK(U.cells.size() == 3);
  attempt(A, B);
}

namespace {

// Every cell's field `name` against the function of position `expect(category, x)` at the
// parameter corners and centre of the cell.
template <class F>
void check_field(const VModel<R>& M, const std::string& name, F&& expect) {
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    REQUIRE(M.cells[c].attributes.fields.count(name) == 1);
    const auto& G = M.cells[c].attributes.fields.at(name);
    for (int s = 0; s < 9; ++s) {
      std::vector<R> u(3);
      for (int d = 0; d < 3; ++d) u[d] = s == 8 ? (V.domain_lo(d) + V.domain_hi(d)) / 2 : ((s >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d));
      const auto x = evaluate(V, u);
      INFO(M.cells[c].name << " at " << s);
      CHECK(evaluate(G, u)[0] == expect(M.cells[c].name, x));
    }
  }
}

}  // namespace

TEST_CASE("vrep boolean: attribute fields through Booleans, restricted and pulled back exactly") {
  auto A = box({0, 0, 0}, {2, 1, 1});
  auto B = box({1, 0, 0}, {3, 2, 1});
  attach_field(A, 0, "f", test::affine_field(A.trivariates[0], {R(1), R(0), R(0)}, R(0)));       // f = x on A
  attach_field(B, 0, "f", test::affine_field(B.trivariates[0], {R(2), R(1), R(0)}, R(1)));       // f = 2x + y + 1 on B
  attach_field(B, 0, "g", test::affine_field(B.trivariates[0], {R(0), R(0), R(1)}, R(-1, 3)));  // g = z - 1/3 on B
  const auto fa = [](const std::vector<R>& x) { return x[0]; };
  const auto fb = [](const std::vector<R>& x) { return 2 * x[0] + x[1] + 1; };
  auto is_both = [](const std::string& n) { return n.find('*') != std::string::npos; };
  // Union, summed: A only x, B only 2x + y + 1, both 3x + y + 1; g only where B is.
  const auto U = boolean_op(A, B, BooleanOp::unite, R(0), Blend::sum);
  check_field(U, "f", [&](const std::string& n, const std::vector<R>& x) {
    return is_both(n) ? fa(x) + fb(x) : n[0] == 'A' ? fa(x) : fb(x);
  });
  for (const auto& c : U.cells) {
    CHECK(c.attributes.not_carried.empty());
    CHECK(c.attributes.fields.count("g") == (c.name[0] == 'B' || is_both(c.name) ? 1u : 0u));
  }
  // First: the first model's field where both are.
  const auto F = boolean_op(A, B, BooleanOp::intersect, R(0), Blend::first);
  check_field(F, "f", [&](const std::string&, const std::vector<R>& x) { return fa(x); });
  check_field(F, "g", [&](const std::string&, const std::vector<R>& x) { return x[2] - R(1, 3); });
  // The clipped sum of two fields is no spline: refused, naming the field.
  CHECK_THROWS_AS(boolean_op(A, B, BooleanOp::unite, R(0), Blend::sum_clipped), ValidationError);
  // Subtraction keeps A's field restricted to the pieces.
  const auto S = boolean_op(A, B, BooleanOp::subtract);
  check_field(S, "f", [&](const std::string&, const std::vector<R>& x) { return fa(x); });
  // B with a parametrization that is not affine (degree 2 along z with an uneven middle layer, z
  // = 0, 1/3, 1): its field cannot be pulled back as a spline, and the cells in both say so. (In
  // the intersection only A's cells are cut; a union would need B's pieces glued to A's on faces
  // parametrized differently, which gluing refuses.)
  auto Bn = B;
  {
    auto V = elevate_degree(B.trivariates[0], 2, 1);
    for (std::size_t i = 0; i < V.size(); ++i)
      if (i / 4 == 1) V.points[i * V.q + 2] = R(1, 3);
    Bn = glue(std::vector<BSpline<R>>{V});
    attach_field(Bn, 0, "f", test::affine_field(V, {R(2), R(1), R(0)}, R(1)));
  }
  const auto N = boolean_op(A, Bn, BooleanOp::intersect, R(0), Blend::sum);
  REQUIRE(!N.cells.empty());
  check_field(N, "f", [&](const std::string&, const std::vector<R>& x) { return fa(x); });  // its own (A's)
  for (const auto& c : N.cells) {
    REQUIRE(c.attributes.not_carried.size() == 1);
    CHECK(c.attributes.not_carried[0] == "f");
  }
}

TEST_CASE("vrep distance blend: attributes at points, fields on affine cells evaluated exactly") {
  auto A = box({0, 0, 0}, {2, 1, 1});
  auto B = box({1, 0, 0}, {3, 1, 1});
  attach_field(A, 0, "f", test::affine_field(A.trivariates[0], {R(1), R(-2), R(3)}, R(1, 7)));  // f = x - 2y + 3z + 1/7
  B.cells[0].attributes.constants["f"] = {R(5)};
  std::size_t cell = 99;
  for (const auto& x : std::vector<std::vector<R>>{{R(1, 3), R(2, 5), R(5, 7)}, {R(2), R(1), R(0)}, {R(0), R(0), R(0)}}) {
    CHECK(attribute_at(A, x, "f", &cell) == std::vector<R>{x[0] - 2 * x[1] + 3 * x[2] + R(1, 7)});
    CHECK(cell == 0);
  }
  CHECK(attribute_at(B, {R(2), R(1, 2), R(1, 2)}, "f") == std::vector<R>{R(5)});
  CHECK_THROWS_AS(attribute_at(A, {R(5), R(0), R(0)}, "f"), ValidationError);  // outside
  CHECK_THROWS_AS(attribute_at(A, {R(1), R(0), R(0)}, "g"), ValidationError);  // no such attribute
  // Eq. 2 is C^0 across the interfaces: on A's face x = 2 inside B the blend is B's value exactly,
  // on B's face x = 1 inside A it is A's field there.
  const DistanceBlend D(A, B);
  for (const R& y : {R(1, 5), R(1, 2), R(4, 5)}) {
    const std::vector<R> p{R(2), y, R(1, 2)}, q{R(1), y, R(1, 2)};
    const auto a = D.at(p, attribute_at(A, p, "f"), attribute_at(B, p, "f"));
    REQUIRE(a.value.size() == 1);
    CHECK(a.value[0].lo == R(5));
    CHECK(a.value[0].hi == R(5));
    const auto b = D.at(q, attribute_at(A, q, "f"), attribute_at(B, q, "f"));
    CHECK(b.value[0].lo == R(1) - 2 * y + R(3, 2) + R(1, 7));
    CHECK(b.value[0].exact());
  }
  // A field on a cell that is not affine: its parameters at a point are not rational in general.
  auto V = elevate_degree(A.trivariates[0], 2, 1);
  for (std::size_t i = 0; i < V.size(); ++i)
    if (i / 4 == 1) V.points[i * V.q + 2] = R(1, 3);
  auto N = glue(std::vector<BSpline<R>>{V});
  attach_field(N, 0, "f", test::affine_field(V, {R(1), R(0), R(0)}, R(0)));
  CHECK_THROWS_AS(attribute_at(N, {R(1), R(1, 2), R(1, 2)}, "f"), DomainError);
}

TEST_CASE("vrep boolean: partial edge contacts are glued like partial face contacts (issue 47, vrep 1)") {
  // Two boxes touching along the segment x = y = 1, 1/2 <= z <= 1 (part of an edge of each): the
  // union's point set has Euler characteristic 1 + 1 - 1 = 1 (two balls glued along a segment).
  const auto A = box({0, 0, 0}, {1, 1, 1}), B = box({1, 1, R(1, 2)}, {2, 2, 2});
  BooleanStats<R> stats;
  const auto U = boolean_op(A, B, BooleanOp::unite, R(0), Blend::sum_clipped, {}, &stats);
  check_ok(U, 1);
  CHECK(stats.rounds == 2);  // the contact found, both cells cut at the other's planes
  CHECK(volume(U) == R(1) + R(3, 2));
  // The segment is one V-curve of both pieces that touch there.
  const auto p = point_at(U, {1, 1, R(1, 2)}), q = point_at(U, {1, 1, 1});
  CHECK(U.cells_of_curve(curve_between(U, p, q)).size() == 2);
  // A whole common edge needs no cut; boxes apart are not touched.
  const auto W = boolean_op(A, box({1, 1, 0}, {2, 2, 1}), BooleanOp::unite, R(0), Blend::sum_clipped, {}, &stats);
  check_ok(W, 1);
  CHECK(stats.rounds == 1);
  check_ok(boolean_op(A, box({2, 2, 2}, {3, 3, 3}), BooleanOp::unite), 2);
  // A parallelepiped touching A at one point where an edge of each crosses the other's: the planar
  // path cannot cut A there (a plane that is no parameter plane) and says so, no longer returning
  // the two cells unglued (chi 2).
  BSpline<R> P = box_cells<R>({0, 0, 0}, {1, 1, 1})[0];
  const std::array<std::array<R, 3>, 3> e{{{0, 1, -1}, {0, 1, 1}, {1, 1, 1}}};
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) {
      R x = c == 2 ? R(3, 2) : R(1, 2);
      for (int d = 0; d < 3; ++d)
        if ((i >> d) & 1) x += e[d][c];
      P.points[3 * i + c] = x;
    }
  CHECK_THROWS_AS(boolean_op(A, glue<R>({P}), BooleanOp::unite), NotPlanarError);
}
