// Untrimming a user-given trimmed domain: a parameter box and polygonal trimming loops with
// rational vertices (`splinex untrim`). The trimmed region is the set of points of the box inside
// an odd number of loops (even-odd rule: an outer loop with holes needs no orientation).
//
// Validation (typed errors naming the loop and vertex): a loop needs >= 3 vertices, no repeated
// consecutive vertex, non-zero area (degenerate loops); no self-intersection (CGAL is_simple);
// every vertex in the closed box (loops leaving the domain); no two loops crossing or touching.
//
// Tiles come from the line sweep of untrim/sweep.hpp (exact in rationals, or in double from the
// rounded vertices). Cross-checks, independent of the sweep: the region's area by CGAL's exact
// polygon areas with nesting parity, and integrals of polynomial densities by Green's theorem on
// the loops (the density in monomials, int_region f dA = sum over loops of +-oint F dy with
// F = int f dx).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "untrim/sweep.hpp"
#include "untrim/polygon.hpp"

namespace splinex {

/// The document field naming loop l ("loops[l]"), for errors.
inline std::string loop_field(std::size_t l) { return "loops[" + std::to_string(l) + "]"; }
/// The document field naming vertex i of loop l ("loops[l][i]"), for errors.
inline std::string vertex_field(std::size_t l, std::size_t i) {
  return loop_field(l) + "[" + std::to_string(i) + "]";
}
/// The field naming edge i of loop l (from vertex i to vertex i + 1), for errors.
inline std::string edge_field(std::size_t l, std::size_t i) {
  return loop_field(l) + " edge " + std::to_string(i);
}

struct TrimmedDomain {
  std::array<Rational, 2> lo, hi;  // the box [lo_0, hi_0] x [lo_1, hi_1]
  std::vector<Polygon> loops;      // the loops' vertices; edge i runs from vertex i to vertex i + 1 (cyclic)
  /// Curved edges (untrim/curved.hpp): controls[l][i] holds the inner Bezier control points of edge
  /// i of loop l (empty: straight). controls is empty or has one entry per loop, each one per edge.
  std::vector<std::vector<Polygon>> controls{};

  bool curved() const {
    for (const auto& c : controls)
      for (const auto& e : c)
        if (!e.empty()) return true;
    return false;
  }
  /// Edge i of loop l as its Bezier control polygon (a straight edge: its two end points).
  Polygon edge(std::size_t l, std::size_t i) const;
};

void validate_domain(const TrimmedDomain& D);
/// The per-vertex rules both validations share: no vertex repeating the next (zero-length edge),
/// every vertex in the closed box (DomainError "leaves the domain").
void validate_loop_vertices(const TrimmedDomain& D, std::size_t l);

/// The tiles of the trimmed region (labels 0), in arithmetic T (double: vertices rounded). Curved
/// domains are tiled exactly (untrim_curved) and the exact tiles rounded to T.
/// knot_lines: x values of vertical and y values of horizontal lines that also split the tiles
/// (the knot lines of a surface the tiles are composed into: isoparametric splits).
template <class T>
std::vector<Tile<T>> untrim_domain(const TrimmedDomain& D, const std::array<std::vector<Rational>, 2>& knot_lines = {});

/// +1 for loops at even nesting depth (outer boundaries), -1 at odd depth (holes).
std::vector<int> loop_signs(const TrimmedDomain& D);
/// The region's exact area: sum of sign * |CGAL polygon area| (curved loops: Green's theorem,
/// the area oint x dy of each loop's Bezier edges).
Rational region_area(const TrimmedDomain& D);
/// Green's theorem: the integral of the polynomial f (one Bezier piece, q = 1) over the region,
/// through f's monomial form and the loops' edges (straight or Bezier); exact.
Rational green_integral(const TrimmedDomain& D, const BSpline<Rational>& f);

/// The density x^a y^b as a Bezier patch of degrees (a, b) on the box (coefficients
/// lo^(a-i) hi^i, the monomial's blossom at the end points).
BSpline<Rational> monomial_density(int a, int b, const TrimmedDomain& D);

}  // namespace splinex
