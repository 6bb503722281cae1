// The gluing of trimmed V-models (issue 18, trimmed_glue): Figure 3's counts through the trimmed
// path, a box united with a cylinder through it (counted by hand below), the same operands
// intersected and subtracted, double against exact, and contacts it cannot match said so.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <map>

#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "spline/evaluate.hpp"
#include "tests/helpers.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_glue.hpp"

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

TEST_CASE("vrep trimmed glue: two contact halves whose piece counts differ are not one set") {
  // A region written larger than its cells (documents must not be edited so; this one is built
  // here): A = [0,1]^3; B's trivariate [1/2,2] x [0,1]^2 trimmed to x >= 1, y <= 1/3; the region
  // A u [1,2]x[0,1/3]x[0,1] u [1,2]x[2/3,1]x[0,1]. A's face x = 1 has the model on its other side
  // in 2 pieces, B's surface x = 1 in 1 (against A), and they meet only each other: one set cannot
  // have 2 and 1 pieces, so the contact is undecided with the reason, and so is the gluing.
  TrimmedModel<R> M;
  M.trivariates = {box_cells<R>({0, 0, 0}, {1, 1, 1})[0], box_cells<R>({R(1, 2), 0, 0}, {2, 1, 1})[0]};
  TrimmedModel<R>::Cell a, b;
  a.trivariate = 0;
  a.trim = region_and<R>({});
  b.trivariate = 1;
  b.trim = region_and<R>({test::above(0, R(1)), region_not(test::above(1, R(1, 3)))});
  b.status = Truth::mixed;
  M.cells = {a, b};
  M.region = region_or<R>({box_region<R>({0, 0, 0}, {1, 1, 1}), box_region<R>({1, 0, 0}, {2, R(1, 3), 1}), box_region<R>({1, R(2, 3), 0}, {2, 1, 1})});
  const auto G = trimmed_glue(M, options());
  std::size_t a_face = 99, b_surface = 99, contacts = 0;
  for (const auto& h : G.halves) {
    if (h.cell == 0 && h.dir == 0 && h.side == 1) a_face = h.unmatched;
    if (h.cell == 1 && h.leaf >= 0 && h.internal > 0) b_surface = h.unmatched;
  }
  CHECK(a_face == 2);
  CHECK(b_surface == 1);
  for (const auto& t : G.twins)
    if (t.how.rfind("contact", 0) == 0) {
      ++contacts;
      CHECK_FALSE(t.decided);
      CHECK_THAT(t.undecided_reason, Catch::Contains("2 and 1 pieces"));
    }
  CHECK(contacts == 1);
  CHECK_FALSE(G.decided);
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

namespace {

/// 4-connected components of the marked squares of an n0 x n1 grid.
std::size_t components(const std::vector<std::vector<char>>& m) {
  const std::size_t n0 = m.size(), n1 = n0 ? m[0].size() : 0;
  std::vector<std::vector<char>> seen(n0, std::vector<char>(n1, 0));
  std::size_t count = 0;
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t j = 0; j < n1; ++j) {
      if (!m[i][j] || seen[i][j]) continue;
      ++count;
      std::vector<std::pair<std::size_t, std::size_t>> stack{{i, j}};
      seen[i][j] = 1;
      while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        const std::pair<long, long> nb[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        for (const auto& [da, db] : nb) {
          const long x = static_cast<long>(a) + da, y = static_cast<long>(b) + db;
          if (x < 0 || y < 0 || x >= static_cast<long>(n0) || y >= static_cast<long>(n1)) continue;
          if (!m[static_cast<std::size_t>(x)][static_cast<std::size_t>(y)] || seen[static_cast<std::size_t>(x)][static_cast<std::size_t>(y)]) continue;
          seen[static_cast<std::size_t>(x)][static_cast<std::size_t>(y)] = 1;
          stack.push_back({static_cast<std::size_t>(x), static_cast<std::size_t>(y)});
        }
      }
    }
  return count;
}

}  // namespace

TEST_CASE("vrep trimmed glue: random Booleans of boxes against a grid oracle, per half-V-surface") {
  // Boxes with corners on the grid of halves in [0, 3]: every region boundary lies on that grid, so
  // classifying the centres of quarter-unit squares (1/8 off the surface on either side) is exact,
  // and their 4-connected components are the pieces (touching at corners counts apart, as in
  // count_region). Independent of the subdivision engines: exact point classification only.
  test::XorShift next{0x2545f4914f6cdd1dULL};
  auto random_corners = [&](std::vector<R>& lo, std::vector<R>& hi) {
    lo.clear();
    hi.clear();
    for (int d = 0; d < 3; ++d) {
      const int a = next(5), b = a + 1 + next(6 - a);
      lo.push_back(R(a, 2));
      hi.push_back(R(b, 2));
    }
  };
  const R h(1, 4), off(1, 8);
  std::size_t halves_compared = 0, undecided = 0, models = 0, decided_models = 0;
  for (int k = 0; k < 24; ++k) {
    std::vector<R> alo, ahi, blo, bhi;
    random_corners(alo, ahi);
    random_corners(blo, bhi);
    const BooleanOp op = k % 3 == 0 ? BooleanOp::intersect : k % 3 == 1 ? BooleanOp::subtract : BooleanOp::unite;
    TrimmedModel<R> M;
    try {
      M = trimmed_boolean(box(alo, ahi), box(blo, bhi), op, Blend::sum_clipped, TrimOptions{}, R(0));
    } catch (const Error&) {
      continue;  // an empty result
    }
    ++models;
    const auto G = trimmed_glue(M, options());
    decided_models += G.decided;
    std::size_t shared_twice = 0;  // V-surfaces seen from both sides: per half and cell across, components
    std::vector<std::array<R, 6>> boxes;  // every cell's box, for the cell across
    for (const auto& c : M.cells) {
      const auto& V = M.trivariates[c.trivariate];
      const auto a = evaluate(V, {V.domain_lo(0), V.domain_lo(1), V.domain_lo(2)}), b = evaluate(V, {V.domain_hi(0), V.domain_hi(1), V.domain_hi(2)});
      boxes.push_back({a[0], a[1], a[2], b[0], b[1], b[2]});
    }
    auto in = [](const Region<R>& r, const std::array<R, 3>& x) { return classify_point(r, std::vector<R>(x.begin(), x.end())) == Truth::in; };
    for (const auto& half : G.halves) {
      const auto& cell = M.cells[half.cell];
      const auto& V = M.trivariates[cell.trivariate];
      std::array<R, 3> lo, hi;  // the cell's box: its trivariate's corners
      {
        const auto a = evaluate(V, {V.domain_lo(0), V.domain_lo(1), V.domain_lo(2)}), b = evaluate(V, {V.domain_hi(0), V.domain_hi(1), V.domain_hi(2)});
        for (int d = 0; d < 3; ++d) {
          lo[static_cast<std::size_t>(d)] = a[static_cast<std::size_t>(d)];
          hi[static_cast<std::size_t>(d)] = b[static_cast<std::size_t>(d)];
        }
      }
      // The plane of the half: a face of the box, or the trimming plane (leaf linear in one coordinate).
      int axis = 0;
      R at(0);
      bool face = half.leaf < 0;
      if (face) {
        axis = half.dir;  // box_cells: parameter d runs along coordinate d
        at = half.side ? hi[static_cast<std::size_t>(axis)] : lo[static_cast<std::size_t>(axis)];
      } else {
        std::vector<const Poly3<R>*> leaves;
        vrep_detail::collect_leaves(cell.trim, leaves);
        const auto& g = *leaves.at(static_cast<std::size_t>(half.leaf));
        R coef(0), cst(0);
        for (const auto& [e, c] : g.terms) {
          if (e == std::array<int, 3>{0, 0, 0}) cst = c;
          else {
            axis = e[0] ? 0 : e[1] ? 1 : 2;
            coef = c;
          }
        }
        at = -cst / coef;
        // On or beyond the box's faces the open domain holds none of it.
        if (!(lo[static_cast<std::size_t>(axis)] < at && at < hi[static_cast<std::size_t>(axis)])) {
          if (half.decided) {
            CHECK(half.internal == 0);
            CHECK(half.boundary == 0);
          }
          continue;
        }
      }
      const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
      const auto na = static_cast<std::size_t>(((hi[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)]) / h).convert_to<double>() + 0.5);
      const auto nb = static_cast<std::size_t>(((hi[static_cast<std::size_t>(b)] - lo[static_cast<std::size_t>(b)]) / h).convert_to<double>() + 0.5);
      std::vector<std::vector<char>> internal(na, std::vector<char>(nb, 0)), boundary = internal;
      std::map<std::size_t, std::vector<std::vector<char>>> across;  // cell on the other side -> its squares
      for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j < nb; ++j) {
          std::array<R, 3> p;
          p[static_cast<std::size_t>(axis)] = at;
          p[static_cast<std::size_t>(a)] = lo[static_cast<std::size_t>(a)] + (R(static_cast<long>(i)) + R(1, 2)) * h;
          p[static_cast<std::size_t>(b)] = lo[static_cast<std::size_t>(b)] + (R(static_cast<long>(j)) + R(1, 2)) * h;
          std::array<R, 3> plus = p, minus = p;
          plus[static_cast<std::size_t>(axis)] += off;
          minus[static_cast<std::size_t>(axis)] -= off;
          // The cell's side and the other side.
          std::array<R, 3> mine, other;
          if (face) {
            mine = half.side ? minus : plus;
            other = half.side ? plus : minus;
            if (!in(cell.trim, mine)) continue;
          } else {
            const bool ip = in(cell.trim, plus), im = in(cell.trim, minus);
            if (ip == im) continue;  // the trim does not change across the plane here
            mine = ip ? plus : minus;
            other = ip ? minus : plus;
          }
          (in(M.region, other) ? internal : boundary)[i][j] = 1;
          if (!in(M.region, other)) continue;
          std::size_t found = 0, which = 0;
          for (std::size_t c2 = 0; c2 < M.cells.size(); ++c2) {
            const auto& bx = boxes[c2];
            bool inside = true;
            for (int d = 0; d < 3; ++d) inside = inside && bx[static_cast<std::size_t>(d)] < other[static_cast<std::size_t>(d)] && other[static_cast<std::size_t>(d)] < bx[3 + static_cast<std::size_t>(d)];
            if (inside && in(M.cells[c2].trim, other)) {
              ++found;
              which = c2;
            }
          }
          REQUIRE(found == 1);  // the cells tile the model
          auto& m = across[which];
          if (m.empty()) m.assign(na, std::vector<char>(nb, 0));
          m[i][j] = 1;
        }
      for (const auto& [c2, m] : across) shared_twice += components(m);
      if (!half.decided) {
        ++undecided;
        continue;
      }
      ++halves_compared;
      INFO("model " << k << ", cell " << half.cell << " (" << cell.name << "), " << half.what);
      CHECK(half.internal == components(internal));
      CHECK(half.boundary == components(boundary));
    }
    // The V-model's internal V-surfaces: each seen once from each side.
    if (G.decided) CHECK(2 * G.internal_v_surfaces == shared_twice);
  }
  CHECK(models >= 15);
  CHECK(halves_compared >= 200);
  CHECK(undecided * 10 <= halves_compared);  // nearly all decided
  WARN("grid oracle: " << models << " models (" << decided_models << " glued decided), " << halves_compared << " halves compared, " << undecided
                       << " undecided");
}
