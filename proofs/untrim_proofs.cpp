// Untrimming's proofs (papers/000, Algorithm 2): the tiles cover the trimmed region exactly and
// every tile patch equals T(S(Q)); the same for curved tile sides.
#include <algorithm>
#include <random>

#include "compose/trimmed_compose.hpp"
#include "fixtures/random_spline.hpp"
#include "proofs/suite_detail.hpp"
#include "spline/kernel.hpp"
#include "untrim/algorithm2.hpp"
#include "untrim/curved.hpp"
#include "untrim/polygon.hpp"
#include "untrim/tile_integrals.hpp"

namespace splinex::proof_detail {

namespace {

void untrim_cover(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  auto frac = [&](int lo, int hi, int den) { return Rational(pick(lo, hi), den); };
  RandomSplineSpec outer_spec;
  outer_spec.degrees = {pick(1, 3), pick(1, 3)};
  outer_spec.counts = {static_cast<std::size_t>(outer_spec.degrees[0] + 1 + pick(1, 3)), static_cast<std::size_t>(outer_spec.degrees[1] + 1 + pick(1, 3))};
  outer_spec.q = 3;
  const auto T = random_spline(outer_spec, rng);
  // S(r, t) = c + r e1 + t e2, its image inside (0, 1)^2.
  const Rational c[2] = {frac(100, 250, 1000), frac(100, 250, 1000)};
  const Rational e1[2] = {frac(300, 600, 1000), frac(-50, 50, 1000)}, e2[2] = {frac(-50, 50, 1000), frac(300, 600, 1000)};
  const auto S = affine_map<Rational>({c[0], c[1]}, {{e1[0], e1[1]}, {e2[0], e2[1]}});
  auto A = compose_tensor(T, S);
  for (auto& tile : A.tiles) tile.R.net = planted(tile.R.net);
  if (A.curved_boundaries != 0) acc.fail("a curved trimming curve for affine S", i);
  // Cover: per inner piece.
  std::vector<std::vector<Polygon>> polys(A.trimmed.inner_pieces.size());
  std::vector<Rational> sums(A.trimmed.inner_pieces.size(), Rational(0)), per_patch(A.trimmed.patches.size(), Rational(0));
  for (const auto& t : A.tiles) {
    const std::size_t piece = A.trimmed.patches[t.patch].inner_piece;
    polys[piece].push_back(tile_polygon(t.tile));
    sums[piece] += t.area;
    per_patch[t.patch] += t.area;
  }
  for (std::size_t k = 0; k < polys.size(); ++k) {
    const auto& box = A.trimmed.inner_pieces[k].box;
    const Rational area = (box[0].second - box[0].first) * (box[1].second - box[1].first);
    const Rational u = polygon_union_area(polys[k]);
    if (u != area) acc.fail("inner piece " + std::to_string(k) + ": gap of area " + to_fraction_string(Rational(area - u)), i);
    if (sums[k] != u) acc.fail("inner piece " + std::to_string(k) + ": overlap of area " + to_fraction_string(Rational(sums[k] - u)), i);
    acc.rep.points += polys[k].size();
  }
  // Regions: the box clipped by the region's half-planes s_c >= lo, s_c < hi.
  for (std::size_t k = 0; k < A.trimmed.patches.size(); ++k) {
    const auto& p = A.trimmed.patches[k];
    const Polygon poly = affine_region_polygon(A.trimmed.inner_pieces[p.inner_piece].box, p.region, c, e1, e2);
    if (per_patch[k] != polygon_area(poly))
      acc.fail("region " + std::to_string(k) + ": tiles " + to_fraction_string(per_patch[k]) + " vs clipped polygon " +
                   to_fraction_string(polygon_area(poly)), i);
  }
  // R = T(S(Q)) on every tile, by identity on its cells.
  const int dT = T.degrees[0] + T.degrees[1];
  for (std::size_t k = 0; k < A.tiles.size(); ++k) {
    const auto& t = A.tiles[k];
    // Both sides: T(S(Q)) (Q's cells, degree dT) and R (its own cells and degrees).
    PiecewiseShape tsq{{t.tile.x, {Rational(0), Rational(1)}}, {dT, dT}, {0, 0}};
    const auto cuts = union_cuts(tsq, shape_of(t.R.net), {{t.tile.x.front(), t.tile.x.back()}, {Rational(0), Rational(1)}});
    acc.add(prove_by_samples(cuts, identity_bound(tsq, shape_of(t.R.net)),
                             [&](const std::vector<Rational>& xl) -> std::string {
                               const auto a = A.evaluate_tile(k, xl);
                               const auto b = evaluate(T, evaluate(S, evaluate(t.Q, xl)));
                               if (a == b) return "";
                               return "tile " + std::to_string(k) + " at (" + to_fraction_string(xl[0]) + ", " +
                                      to_fraction_string(xl[1]) + ")";
                             },
                             "R = T(S(Q))"),
            i);
  }
}

void untrim_curved_cover(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  const Rational h(1, 2);
  const Rational a(pick(1, 3), 20), b(pick(17, 19), 20);
  // Top arc (right to left) above y = 1/2, bottom arc (left to right) below: interior ordinates
  // in [3/4, 19/20] and [1/20, 1/4], so they meet only at their shared end points.
  const int dt = pick(2, 4), db = pick(2, 4);
  TrimmedDomain D{{0, 0}, {1, 1}, {{{a, h}, {b, h}}}};
  Polygon bottom, top;
  for (int j = 1; j < db; ++j) bottom.push_back({a + (b - a) * Rational(j, db), Rational(pick(1, 5), 20)});
  for (int j = 1; j < dt; ++j) top.push_back({b - (b - a) * Rational(j, dt), Rational(pick(15, 19), 20)});
  const Rational e(pick(0, 4), 100), f(pick(0, 4), 100);
  D.loops.push_back({{Rational(2, 5) + e, Rational(9, 20)}, {Rational(3, 5), Rational(9, 20) + f}, {h, Rational(11, 20)}});
  D.controls = {{bottom, top}, {{}, {}, {}}};
  validate_domain(D);
  std::vector<Rational> kx;
  for (int k = pick(0, 3); k > 0; --k) kx.push_back(Rational(pick(3, 17), 20));
  std::sort(kx.begin(), kx.end());
  kx.erase(std::unique(kx.begin(), kx.end()), kx.end());
  const auto tiles = untrim_curved(D, {kx, {h}});
  const auto cc = certify_cover(D, tiles);
  if (!cc.ok) acc.fail("cover: " + cc.failure, i);
  acc.rep.points += cc.samples + cc.pair_checks + cc.edge_checks;
  for (int ea = 0; ea <= 2; ++ea)
    for (int eb = 0; eb <= 2; ++eb) {
      const auto dens = monomial_density(ea, eb, D);
      Rational sum = 0;
      for (const auto& t : tiles) sum += integrate_over_tile(dens, t)[0];
      if (sum != green_integral(D, dens))
        acc.fail("integral of x^" + std::to_string(ea) + " y^" + std::to_string(eb) + ": tiles " + to_fraction_string(sum) +
                     ", Green " + to_fraction_string(green_integral(D, dens)), i);
    }
  // T with the knot lines, random small integer control points.
  const int p0 = pick(1, 3), p1 = pick(1, 2);
  const auto T = spline_from<Rational>({p0, p1}, {clamped_knots(p0, Rational(0), Rational(1), kx), clamped_knots(p1, Rational(0), Rational(1), {h})},
                                       3, [&](const std::vector<std::size_t>&) {
                                         std::vector<Rational> v;
                                         for (int d = 0; d < 3; ++d) v.push_back(Rational(pick(-9, 9), 4));
                                         return v;
                                       });
  CompositionOptions co;
  co.expand = true;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto Q = tile_spline(tiles[k]);
    const auto R = planted(compose(T, Q, co));
    const int dT = p0 + p1;
    // Both sides: T(Q) (Q's cells, degree (dT deg_x Q, dT)) and R (its own).
    PiecewiseShape tq{{tiles[k].x, {Rational(0), Rational(1)}}, {dT * Q.degrees[0], dT}, {0, 0}};
    const auto cuts = union_cuts(tq, shape_of(R), {{tiles[k].x.front(), tiles[k].x.back()}, {Rational(0), Rational(1)}});
    acc.add(prove_by_samples(cuts, identity_bound(tq, shape_of(R)),
                             [&](const std::vector<Rational>& xl) -> std::string {
                               if (evaluate(R, xl) == evaluate(T, evaluate(Q, xl))) return "";
                               return "tile " + std::to_string(k) + " at (" + to_fraction_string(xl[0]) + ", " +
                                      to_fraction_string(xl[1]) + ")";
                             },
                             "R = T(Q)"),
            i);
  }
}

}  // namespace

std::vector<ProofEntry> untrimming_proofs() {
  return {
      entry("untrim-cover",
            "Algorithm 2, exact, for affine S in T: the tiles of each inner piece cover its box with no gap and "
            "no overlap (exact union area by CGAL = box area = sum of tile areas), each region's tiles have the "
            "area of the region's polygon (the box clipped independently by the region's half-planes), and "
            "every tile patch R equals T(S(Q)) on its tile",
            "per tile cell (chain piece x [0, 1]): max(deg R, p_0 + p_1 of T) per direction",
            untrim_cover, own_inputs),
      entry("untrim-curved-cover",
            "exact untrimming of a random lens of two polynomial graph arcs (degrees 2-4) with a triangular "
            "hole, split by random vertical knot lines and y = 1/2: certify_cover proves the curved tiles cover "
            "the region (pairwise interior-disjoint, inside, areas add up to Green's area); the tile integrals of "
            "x^a y^b (a, b <= 2) equal Green's theorem on the loops; every tile patch R equals T(Q) on its tile",
            "per tile cell (chain piece x [0, 1]): max(deg R, (p_0 + p_1) (d, 1)) per direction",
            untrim_curved_cover, own_inputs),
  };
}

}  // namespace splinex::proof_detail
