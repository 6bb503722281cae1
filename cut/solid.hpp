// Planar solids bounded by B-spline curve facets and the cutting data of papers/004 Section 2
// (d = 2): the solid S is bounded by facets F_i, polynomial B-spline curves in the plane joined end
// to start in a closed counter-clockwise loop; the cutting data are two points on that loop, each
// with a tangent vector pointing into S. Everything is exact (Rational); a double run rounds the
// validated data.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/verdict.hpp"
#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// The cutting package's words for a verdict, as its documents and tables write them: a condition
/// "certified" (proved), "violated" (refuted by a witness) or undecided; the whole curve or surface
/// "valid", "invalid" or undecided.
inline const char* certificate_word(const Verdict& v) { return v.is_proved() ? "certified" : v.is_refuted() ? "violated" : status_name(v.status()); }
inline const char* validity_word(const Verdict& v) { return v.is_proved() ? "valid" : v.is_refuted() ? "invalid" : status_name(v.status()); }

template <class T>
struct Solid2 {
  std::vector<BSpline<T>> facets;  // curves (one parameter), q = 2, polynomial, clamped
};

/// A point of the cutting data: on facet `facet` at parameter `param` (a facet's end parameter is
/// the vertex it shares with the next facet), with the tangent t of the cutting curve there.
template <class T>
struct CutPoint2 {
  std::size_t facet = 0;
  T param = T(0);
  std::array<T, 2> tangent{T(0), T(0)};
};

/// The cutting data D = (L, t) for d = 2: the two end points of the cutting curve.
template <class T>
struct CutData2 {
  std::array<CutPoint2<T>, 2> ends;
};

/// Checks the solid: at least two facets; each a polynomial clamped curve of degree >= 1 in R^2;
/// each facet's end point equals the next one's start point exactly (the last joins the first);
/// no facet is a single point; the loop is simple (check_simple_loop); the loop's exact signed area
/// is positive (counter-clockwise: the solid on the left). ValidationError names the field and the fix.
void validate_solid(const Solid2<Rational>& S);

/// The loop of facets is simple: facets meet only where one ends and the next starts, and no
/// facet meets itself. Decided exactly: straight pieces by exact segment intersection; curved
/// ones by exact separation of their control polygons' convex hulls with subdivision, a crossing
/// proved by the intermediate value theorem (see solid.cpp). Near-linear in the number of pieces
/// when they do not pile up (a bounding-volume tree finds the pairs whose boxes meet). Throws
/// ValidationError naming the facets and the point when the loop is not simple, or when it could
/// not be decided within the budget (curves touching tangentially or closer than 2^-max_depth of
/// their size, a cusp at a vertex): then the loop is refused as not certified simple.
struct SimpleLoopOptions {
  int max_depth = 40;                // halvings of one Bezier piece
  std::size_t max_tests = 2000000;   // pair tests in all
};
void check_simple_loop(const Solid2<Rational>& S, const SimpleLoopOptions& options = {});

/// Checks the cutting data against the solid: facets and parameters in range, two distinct points,
/// non-zero tangents pointing strictly into the solid (exact orientation tests against the facets'
/// one-sided derivatives; at a vertex against both facets' directions: inside the corner's
/// angle). Returns the data with each end normalized: a facet's end parameter becomes the next
/// facet's start parameter.
CutData2<Rational> validate_cut(const Solid2<Rational>& S, const CutData2<Rational>& cut);

/// The exact signed area enclosed by the loop (1/2 of the integral of x dy - y dx).
Rational signed_area(const Solid2<Rational>& S);

/// The uniform scaling into the unit square used by papers/004 ("scaled such that the bounding box
/// fits into the unit cube"): normalized = (x - lo) / scale, scale the larger side of the control
/// points' bounding box.
struct Frame2 {
  std::array<Rational, 2> lo{Rational(0), Rational(0)};
  Rational scale{1};
};
Frame2 unit_frame(const Solid2<Rational>& S);
Solid2<Rational> to_frame(const Solid2<Rational>& S, const Frame2& f);

/// Position on the loop: true when facet/param lies strictly inside the counter-clockwise arc from
/// `from` to `to` (both normalized ends).
bool on_arc(std::size_t facet, const Rational& param, const CutPoint2<Rational>& from, const CutPoint2<Rational>& to);

/// A part of the boundary loop: facet `facet`'s curve between two of its cut points or ends.
struct BoundaryPiece {
  BSpline<Rational> curve;
  std::size_t facet = 0;
};
/// The boundary loop in order (facet 0 first), every facet split at the cut points inside it
/// (normalized ends: a cut point at a facet's start is already a vertex). Every piece lies
/// entirely on b or entirely on b-bar.
std::vector<BoundaryPiece> split_at_cut_points(const Solid2<Rational>& S, const CutData2<Rational>& cut);

}  // namespace splinex
