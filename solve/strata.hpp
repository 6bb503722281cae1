// The strata of a surface's parameter domain and the stationary-distance systems of pairs of
// strata (internal to solve/: point projection and surface distance share them).
//
// A stratum is a piece of the domain on which the surface is one polynomial (or rational) map:
// the closed Bezier pieces (two free parameters), the edges on the domain's boundary and on knot
// lines where the surface is not C^1 (one), and those edges' ends (none). The squared distance
// between two strata A and B (or a stratum and a point: a stratum with no free parameter) is
// stationary where its derivatives in their kA + kB free parameters vanish:
//   (X_A W_B - X_B W_A) . (d X_A W_A - X_A d W_A) = 0 for each of A's parameters, and the same
//   with B's;
// in the product of the strata's local boxes, polynomial in Bernstein form.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "bernstein/tensor.hpp"
#include "solve/contact.hpp"
#include "spline/bezier.hpp"
#include "spline/bspline.hpp"

namespace splinex::solve_detail {


template <class T>
struct Stratum {
  int dims = 2;           // the object's parameters: 2 a surface, 1 a curve, 0 a point
  int k = 0;              // free parameters: 2 a piece, 1 an edge, 0 a corner or a point
  Bernstein<T> X[3], W;        // homogeneous coordinates in the k local parameters (W = 1 of degree 0 when polynomial)
  bool rational = false;
  int var[2] = {-1, -1};  // per parameter of the object: its free local variable, or -1 when fixed
  T lo[2], hi[2];         // per parameter of the object: its range (lo == hi when fixed)
  std::size_t piece = 0;  // the Bezier piece it lies in
  std::string where;      // "interior", "edge", "corner", "point"
  std::string label;      // in words
  std::array<T, 6> hull;  // the box of its control points: it holds the stratum's points
};

/// What the stationary-distance equations need of a surface, checked before any work: valid, two
/// parametric directions with points in R^3, degree >= 1 in both (degree 0 has no tangent plane),
/// and equation degrees `degree_factor` * p (rational: 3/2 of that) within the degree limit.
/// ValidationError naming `name` (and `name.degrees[d]`).
template <class T>
void require_surface(const BSpline<T>& S, const std::string& name, const Limits& limits, int degree_factor);

/// All strata of S (dim 2, q >= 3, degree >= 1; checked by require_surface). Edges on C^0 knot lines
/// are taken once (from the piece below); at a C^-1 knot line both sides' edges are kept. Corners
/// are the edges' ends, each (parameter, point) once.
template <class T>
std::vector<Stratum<T>> surface_strata(const BSpline<T>& S, const Limits& limits);

/// The Bezier pieces of a curve C (dim 1, q >= 3) as strata with one free parameter (dims 1).
template <class T>
std::vector<Stratum<T>> curve_strata(const BSpline<T>& C, const Limits& limits);

/// The stratum s with its object parameter d fixed at its lower (side 0) or upper (side 1) end:
/// one free parameter fewer (a piece's edge, an edge's end).
template <class T>
Stratum<T> stratum_face(const Stratum<T>& s, int d, int side);

/// A point as a stratum with no free parameter.
template <class T>
Stratum<T> point_stratum(const std::vector<T>& P);

/// The stationary-distance system of a pair of strata in their kA + kB local parameters.
template <class T>
struct PairSystem {
  std::size_t n = 0;              // unknowns: A's free parameters, then B's
  std::vector<Bernstein<T>> equations;  // n of them
  Bernstein<T> D[3];                    // X_A W_B - X_B W_A
  Bernstein<T> W;                       // W_A W_B (positive): S_A - S_B = D / W
  Bernstein<T> D2, WW;                  // |D|^2 and W^2: the squared distance is D2 / WW
  std::vector<T> lo, hi;           // the unknowns' ranges (the strata's parameters)
};

template <class T>
PairSystem<T> pair_system(const Stratum<T>& A, const Stratum<T>& B);

/// The squared distance of the boxes of two strata's control points (a lower bound of the
/// squared distance of any two of their points).
template <class T>
T hull_distance2(const Stratum<T>& A, const Stratum<T>& B);

/// What the engine below searches: every stationary pair; only what can hold the minimum (branch
/// and bound, a common point when the objects meet); or every stationary pair away from where the
/// objects meet (boxes whose distance is surely below 2^-8 of the model's size are skipped: the
/// curve of zero distance of intersecting surfaces has no isolated stationary pairs).
enum class Search { all, minimum, away_from_contact };

/// The stationary pairs of |A - B|^2 over all pairs of strata (solve/contact.hpp's engine).
template <class T>
ContactResult<T> stationary_pairs(const std::vector<Stratum<T>>& A, const std::vector<Stratum<T>>& B, const SolveOptions& options,
                                  Search search);

/// The parameters of a stratum's surface point for a vector of its local unknowns x (offset: where
/// its unknowns start in x), in the surface's parameters; and its point (first three coordinates).
template <class T>
std::vector<T> surface_parameters(const Stratum<T>& A, const std::vector<T>& x, std::size_t offset);
template <class T>
std::vector<T> stratum_point(const Stratum<T>& A, const std::vector<T>& x, std::size_t offset);

/// Bounds of the squared distance |D|^2 / W^2 on a box from the Bernstein forms of D_0, D_1, D_2
/// and W there: below by the box of D's ranges' distance from 0 over max W^2, above by the
/// farthest corner of that box over min W^2.
template <class T>
std::pair<T, T> distance2_bounds(const Bernstein<T>* D, const Bernstein<T>& W);

/// The range [lo, hi] of the squared distance over the sub-box [a, b] of the system's box (global
/// coordinates), a <= b (sides of width 0 allowed): distance2_bounds, and D2 / WW's coefficient
/// range, the tighter of each.
template <class T>
std::pair<T, T> distance2_range(const PairSystem<T>& sys, const std::vector<T>& a, const std::vector<T>& b);

/// The squared distance of the strata A and B (their system sys) over the sub-box [a, b] (a <= b,
/// sides of width 0 allowed), enclosed and rounded outward: Rational, distance2_range widened to
/// 72 bits; a float arithmetic, computed exactly from the strata's (float) coefficients taken as
/// rationals (D and W only: no rounding error, no inverted or negative interval) and rounded
/// outward to T. Holds |S_A - S_B|^2 at every point of the box.
template <class T>
std::pair<T, T> distance2_enclosure(const Stratum<T>& A, const Stratum<T>& B, const PairSystem<T>& sys, const std::vector<T>& a,
                                    const std::vector<T>& b);

/// x rounded to T downward (up = false) or upward: the nearest T on that side (exact for Rational).
template <class T>
T round_directed(const Rational& x, bool up);

/// Whether the stratum's point does not move along its object parameters `dirs` when the others
/// are fixed at uv (the object's parameters): the segment of parameters maps to one point in
/// space (a collapsed edge, a pole). Exact arithmetic only (false in a float one).
template <class T>
bool constant_along(const Stratum<T>& A, const std::vector<int>& dirs, const std::vector<T>& uv);

/// D2 / WW at the point x of the system's box, exactly.
template <class T>
T distance2_at(const PairSystem<T>& sys, const std::vector<T>& x);

}  // namespace splinex::solve_detail
