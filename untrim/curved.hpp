// Exact untrimming of trimmed domains whose loops have polynomial curved edges (papers/000
// Section 2.2: "quads whose sides may be freeform curves (trimming curves included)").
//
// A curved edge is a polynomial graph y = f(x) over [x_0, x_1], x_0 != x_1: a Bezier curve whose
// control points have x evenly spaced between its end points (x affine in the curve parameter).
// Why graphs: the vertical line sweep cuts every edge at the x of every vertex and of every
// crossing; on a graph the cut is at a rational parameter, so the cut pieces have rational control
// points (de Casteljau). A general polynomial curve would have to be split at its x-extremes and at
// x = const, roots of its x(t): algebraic numbers, not rationals. Curves that are not graphs are
// rejected with the fix (split them into graphs, x-monotone in an affine parametrization).
//
// The sweep (untrim_curved): every non-vertical edge is a graph arc, the box's bottom and top edges
// and the horizontal knot lines y = k are arcs of degree 0. Slab boundaries are the x of all end
// points, vertical edges, vertical knot lines and of every point where an arc meets a horizontal
// line (roots of f - k: exact when rational, found by classify_real_roots; an irrational crossing
// is a DomainError, since no tile with rational control points could end there). Loop arcs never
// meet except at vertices (validated), so inside a slab the arcs are ordered by their value at the
// slab's middle; arcs equal there are the same polynomial (a loop edge lying on a knot line) and
// are merged. Between consecutive arcs lies a curved trapezoid; it is inside when an odd number of
// loop arcs lie at or below its bottom (even-odd rule). Trapezoids continue tiles of the same
// region across slab boundaries as in untrim/sweep.hpp. Every tile's chains are piecewise
// polynomial; its Coons patch has degree (d, 1).
//
// certify_cover proves, exactly and independently of the sweep's bookkeeping, that tiles cover
// the region: tiles pairwise interior-disjoint, no loop edge enters a tile's interior and a sample
// point of each connected part of every tile is inside the region (so every tile is in it), and
// the tiles' areas add up to the region's area (Green's theorem), so there is no gap.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "untrim/loops.hpp"

namespace splinex {

/// Typed errors for curved loops: a curved edge that is not a graph y = f(x), a degree above
/// 100, an edge leaving the box, loops crossing/touching (exact root isolation), zero area.
void validate_curved_domain(const TrimmedDomain& D);

/// Signed area oint x dy of one loop (positive counter-clockwise), exact.
Rational loop_signed_area(const TrimmedDomain& D, std::size_t l);
/// p strictly inside loop l (p must not lie on it): parity of the loop's graph arcs above p.
bool inside_loop(const TrimmedDomain& D, std::size_t l, const Point2<Rational>& p);
// ValidationError for the loop edges (loop l, loop m, edge i, edge j) that meet: "is
// self-intersecting" when l == m, else "meets loops[l]" (first_meeting_edges finds them).
[[noreturn]] void throw_meeting_edges(const std::array<std::size_t, 4>& pair);

/// The exact tiles of a validated curved (or straight) domain; labels 0. approx_bits = 0: an
/// irrational crossing with a horizontal line is a DomainError. approx_bits > 0 (the float
/// arithmetics): the tiles end at a rational within 2^-approx_bits of the crossing instead, so the
/// tiles there cross the knot line by up to that much (a sliver of area O(4^-approx_bits); the
/// composition evaluates the knot cell's polynomial beyond its cell, Step 7 of Algorithm 2).
std::vector<Tile<Rational>> untrim_curved(const TrimmedDomain& D, const std::array<std::vector<Rational>, 2>& knot_lines = {},
                                          int approx_bits = 0);

struct CoverCertificate {
  bool ok = true;
  std::string failure;            // first failed check, exact
  std::size_t tiles = 0;
  std::size_t pair_checks = 0;    // (tile piece, tile piece) sign questions answered
  std::size_t edge_checks = 0;    // (loop edge, tile piece) sign questions answered
  std::size_t samples = 0;        // interior points tested against the loops
  Rational tile_area_sum = 0, region_area = 0;
};
CoverCertificate certify_cover(const TrimmedDomain& D, const std::vector<Tile<Rational>>& tiles);

}  // namespace splinex
