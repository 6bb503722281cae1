// One run of `splinex untrim` as a value: a trimmed domain tiled with Coons patches, each tile's
// area, its patch composed into a surface and its integral of a density, the totals against the
// exact references (CGAL's or Green's area, Green's integral) and, in exact arithmetic, the cover
// certificate. io/trimmed_domain_io.hpp writes it as a document.
#pragma once
#include <array>
#include <optional>
#include <type_traits>
#include <vector>

#include "compose/compose.hpp"
#include "float/rounding.hpp"
#include "untrim/curved.hpp"
#include "untrim/loops.hpp"
#include "untrim/tile_integrals.hpp"

namespace splinex {

/// The knot lines of S inside its domain, per direction (they split the tiles). S must be a
/// surface whose domain contains D's box (ValidationError, DomainError naming "surface").
inline std::array<std::vector<Rational>, 2> surface_knot_lines(const BSpline<Rational>& S, const TrimmedDomain& D) {
  std::array<std::vector<Rational>, 2> knot_lines;
  if (S.dim() != 2) throw ValidationError("surface", "has " + std::to_string(S.dim()) + " parameters", "give a surface");
  for (int d = 0; d < 2; ++d) {
    if (D.lo[d] < S.domain_lo(d) || S.domain_hi(d) < D.hi[d])
      throw DomainError("surface", "its domain in direction " + std::to_string(d) + " does not contain the trimmed domain's box",
                        "give a box inside the surface's parameter domain");
    for (const auto& k : S.knots[d])
      if (S.domain_lo(d) < k && k < S.domain_hi(d) && (knot_lines[d].empty() || !(knot_lines[d].back() == k)))
        knot_lines[d].push_back(k);
  }
  return knot_lines;
}

template <class F>
struct UntrimmedTile {
  Tile<F> tile;
  F area;
  BSpline<F> coons;                   // Q(x, l) on [x_0, x_m] x [0, 1]
  std::optional<BSpline<F>> patch;    // surface(Q), with a surface
  std::optional<F> integral;          // of the density over the tile, with a density
};

template <class F>
struct UntrimRun {
  std::vector<UntrimmedTile<F>> tiles;
  F area = F(0);
  Rational exact_area;                        // CGAL's (straight edges) or Green's (curved)
  bool curved = false;                        // the domain has curved edges
  std::optional<F> integral;                  // with a density
  std::optional<Rational> exact_integral;     // Green's, with a density
  std::optional<CoverCertificate> cover;      // exact runs only
};

/// Tiles D (split at knot_lines) in the arithmetic F; with S each tile's patch is S(Q), with f
/// its integral of f (a scalar polynomial density).
template <class F>
UntrimRun<F> untrim_run(const TrimmedDomain& D, const std::optional<BSpline<Rational>>& S, const std::optional<BSpline<Rational>>& f,
                        const std::array<std::vector<Rational>, 2>& knot_lines, const Limits& limits) {
  UntrimRun<F> run;
  const auto tiles = untrim_domain<F>(D, knot_lines);
  std::optional<BSpline<F>> Sf, ff;
  if (S) Sf = round_spline<F>(*S, "surface");
  if (f) ff = round_spline<F>(*f, "density");
  CompositionOptions co;
  co.expand = true;
  F integral(0);
  for (const auto& t : tiles) {
    UntrimmedTile<F> u{t, tile_area(t), tile_spline(t), std::nullopt, std::nullopt};
    run.area = run.area + u.area;
    if (Sf) u.patch = compose(*Sf, u.coons, co, limits);
    if (ff) {
      u.integral = integrate_over_tile(*ff, t, limits)[0];
      integral = integral + *u.integral;
    }
    run.tiles.push_back(std::move(u));
  }
  run.exact_area = region_area(D);
  run.curved = D.curved();
  if constexpr (std::is_same_v<F, Rational>) run.cover = certify_cover(D, tiles);
  if (ff) {
    run.integral = integral;
    run.exact_integral = green_integral(D, *f);
  }
  return run;
}

}  // namespace splinex
