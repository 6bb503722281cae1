// The gluing of trimmed V-models (issue 18, trimmed_glue): Figure 3's counts through the trimmed
// path, a box united with a cylinder through it (counted by hand below), the same operands
// intersected and subtracted, double against exact, and contacts it cannot match said so.
#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "spline/errors.hpp"
#include "vrep/boolean.hpp"
#include "vrep/primitives.hpp"
#include "vrep/trimmed.hpp"
#include "vrep/vmodel.hpp"

using namespace splinex;
using R = Rational;

namespace {

TrimmedModel<R> box(std::vector<R> lo, std::vector<R> hi) { return as_trimmed(glue(box_cells<R>(lo, hi)), box_region<R>(lo, hi)); }

TrimmedModel<R> cylinder(const R& r, const R& h, int axis, std::vector<R> at) {
  return placed_primitive(cylinder_cells<R>(r, h), cylinder_region<R>(r, h), axis, at);
}

template <class T>
std::size_t twins_of(const TrimmedGluing<T>& G, const std::string& how_prefix) {
  std::size_t n = 0;
  for (const auto& t : G.twins) n += t.how.rfind(how_prefix, 0) == 0 && t.decided ? t.pieces : 0;
  return n;
}

TrimmedGlueOptions options(std::size_t boxes = 2048) {
  TrimmedGlueOptions o;
  o.max_boxes = boxes;
  return o;
}

}  // namespace

TEST_CASE("vrep trimmed glue: Figure 3 through the trimmed path has the paper's 18 half-V-surfaces, 14 boundary and 2 internal V-surfaces") {
  // O1 = [0,2]x[0,1]x[0,1], O2 = [1,2]x[0,2]x[0,1]: the middle cell is O1's trivariate restricted to
  // O2, the others O1 minus O2 and O2 minus O1 (each one trivariate: no parameter cuts here).
  const auto U = trimmed_boolean(box({R(0), R(0), R(0)}, {R(2), R(1), R(1)}), box({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), BooleanOp::unite,
                                 Blend::sum_clipped, TrimOptions{}, R(0));
  REQUIRE(U.cells.size() == 3);
  const auto G = trimmed_glue(U, options());
  CHECK(G.decided);
  CHECK(G.half_v_surfaces == 18);
  CHECK(G.part_pieces == 18);
  CHECK(G.boundary_v_surfaces == 14);
  CHECK(G.internal_v_surfaces == 2);
  // x = 1 between O1's two parts: one trivariate, the two sides of O2's plane, exact.
  CHECK(twins_of(G, "one trivariate") == 1);
  // y = 1 between the middle cell's face and O2 minus O1's trimming plane: a contact.
  CHECK(twins_of(G, "contact") == 1);
  CHECK(G.contacts == 1);
  CHECK(G.witness_points >= 1);
  // The L-shaped prism's 8 faces are split by the cells into 14 pieces: the end cells have 5
  // boundary pieces and 1 internal one each, the middle cell 4 and 2.
  std::vector<std::size_t> boundary(3, 0), internal(3, 0);
  for (const auto& h : G.halves) {
    boundary[h.cell] += h.boundary;
    internal[h.cell] += h.internal;
  }
  CHECK(boundary == std::vector<std::size_t>{4, 5, 5});
  CHECK(internal == std::vector<std::size_t>{2, 1, 1});

  const auto D = trimmed_glue(trimmed_to_double(U), options());
  CHECK(D.decided);
  CHECK(D.boundary_v_surfaces == 14);
  CHECK(D.internal_v_surfaces == 2);
}

TEST_CASE("vrep trimmed glue: boxes touching on faces that overlap in part are matched face to face") {
  // A = [0,1]^3, B = [1,2]x[0,2]x[0,1]: the faces x = 1 overlap in [0,1]^2 only, so exact face
  // gluing does not pair them; witness points of A's face are located on B's face exactly.
  const auto U = trimmed_boolean(box({R(0), R(0), R(0)}, {R(1), R(1), R(1)}), box({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), BooleanOp::unite,
                                 Blend::sum_clipped, TrimOptions{}, R(0));
  const auto G = trimmed_glue(U, options());
  CHECK(G.decided);
  // A's five other faces; B's face x = 1 above y = 1, and its five other faces.
  CHECK(G.boundary_v_surfaces == 11);
  CHECK(G.internal_v_surfaces == 1);
  CHECK(G.half_v_surfaces == 13);
  CHECK(twins_of(G, "contact") == 1);
  // A gap of 2^-40 between them: nothing internal, every face on the boundary (12), exactly.
  const R gap = R(1) / R(1099511627776LL);
  const auto Gap = trimmed_glue(trimmed_boolean(box({R(0), R(0), R(0)}, {R(1), R(1), R(1)}), box({R(1) + gap, R(0), R(0)}, {R(2), R(2), R(1)}),
                                                BooleanOp::unite, Blend::sum_clipped, TrimOptions{}, R(0)),
                                options());
  CHECK(Gap.decided);
  CHECK(Gap.boundary_v_surfaces == 12);
  CHECK(Gap.internal_v_surfaces == 0);
}

TEST_CASE("vrep trimmed glue: a box united with a cylinder through it, counted by hand") {
  // A = [0,2]x[0,1]x[0,1]; B = the cylinder r = 1/3 along x from -1/2 to 5/2 about (y, z) = (1/2, 1/2)
  // (five cells: a square and four sectors). A u B: A n B (A's trivariate), A - B, and the five
  // cells of B - A, each in two parts (x < 0 and x > 2).
  const auto A = box({R(0), R(0), R(0)}, {R(2), R(1), R(1)});
  const auto B = cylinder(R(1, 3), R(3), 0, {R(-1, 2), R(1, 2), R(1, 2)});
  const auto U = trimmed_boolean(A, B, BooleanOp::unite, Blend::sum_clipped, TrimOptions{}, R(0));
  REQUIRE(U.cells.size() == 7);
  const auto G = trimmed_glue(U, options());
  CHECK(G.decided);
  // Boundary: A - B's six faces (two with a hole) and the tube is internal; the square cell's two
  // ends; each sector's outer face in two parts and its two ends: 6 + 2 + 4 * 4 = 24.
  CHECK(G.boundary_v_surfaces == 24);
  // Internal: the tube inside A (A n B against A - B: one trivariate, exact) 1; B's glued faces
  // (square-sector and sector-sector, 8 pairs, each in two parts outside A) 16; the disks x = 0 and
  // x = 2 of A n B against the five cells' sections: 2 * 5 contacts.
  CHECK(twins_of(G, "one trivariate") == 1);
  CHECK(twins_of(G, "faces of the trivariates") == 16);
  CHECK(twins_of(G, "contact") == 10);
  CHECK(G.internal_v_surfaces == 27);

  // (In double the cylinder's faces leave its rounded quadric by rounding errors, and the counts
  // come out wrong: the report measures it; nothing to assert here.)

  // The same operands intersected: A n B alone, its two disks and the tube are boundary now.
  const auto I = trimmed_glue(trimmed_boolean(A, B, BooleanOp::intersect, Blend::sum_clipped, TrimOptions{}, R(0)), options());
  CHECK(I.decided);
  CHECK(I.boundary_v_surfaces == 3);
  CHECK(I.internal_v_surfaces == 0);
  // Subtracted: the box with a hole, six faces and the tube.
  const auto S = trimmed_glue(trimmed_boolean(A, B, BooleanOp::subtract, Blend::sum_clipped, TrimOptions{}, R(0)), options());
  CHECK(S.decided);
  CHECK(S.boundary_v_surfaces == 7);
  CHECK(S.internal_v_surfaces == 0);
}

TEST_CASE("vrep trimmed glue: contacts it cannot match are said so, bad input refused") {
  // Figure 4's kind: a cone united with a cylinder across it. A face of a cone cell inside the
  // cylinder meets the sections of several cylinder cells, which meet several cone cells' faces:
  // no one-to-one match, undecided with the reason; the exact twins are still counted.
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = cylinder(R(1, 3), R(3), 0, {R(-3, 2), R(0), R(1)});
  const auto U = trimmed_boolean(cone, cyl, BooleanOp::unite, Blend::sum_clipped, TrimOptions{}, R(0));
  const auto G = trimmed_glue(U, options(1024));
  CHECK_FALSE(G.decided);
  std::size_t undecided = 0;
  for (const auto& t : G.twins)
    if (!t.decided) {
      ++undecided;
      CHECK(t.how.rfind("contact", 0) == 0);
      CHECK_FALSE(t.undecided_reason.empty());
    }
  CHECK(undecided > 0);
  CHECK(twins_of(G, "one trivariate") > 0);
  CHECK(twins_of(G, "faces of the trivariates") > 0);

  CHECK_THROWS_AS(trimmed_glue(U, options(4)), ValidationError);
  auto bad = U;
  bad.cells.front().trivariate = 1000;
  CHECK_THROWS_AS(trimmed_glue(bad, options()), ValidationError);
}
