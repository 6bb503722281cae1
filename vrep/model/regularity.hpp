// Certified regularity of a trivariate (papers/002 Section 3.2.3, Figures 1 b, 8): the sign of the
// Jacobian determinant decided from exact Bernstein coefficients.
//
// Per Bezier piece, in the piece's local coordinates (which changes det J by a positive factor):
//  - polynomial T = (X, Y, Z): det J = det[T_u, T_v, T_w], a tensor Bernstein polynomial of degree
//    (3p-1, 3q-1, 3r-1);
//  - rational, homogeneous P = (W, X, Y, Z): det J = det[P, P_u, P_v, P_w] / W^4 (rows W, X, Y, Z),
//    numerator of degree (4p-1, 4q-1, 4r-1), W > 0.
// Products are exact Bernstein products; only the first three point coordinates are geometry.
// Decision: every box's corner coefficients are exact values of det J there (a corner value 0 is a
// singular point; corner values of both signs, in one piece or across pieces, a sign change:
// singular, with both points); a box whose coefficients all have the sign found is certified; the
// rest is subdivided at midpoints (de Casteljau, exact in exact arithmetic) up to `max_levels`,
// after which the verdict is "undecided" (also when the boxes alive would exceed the control-point
// limit in coefficients; the sizes of det J are checked against the limits before any work). In float arithmetic the same test runs in floats (what
// a float kernel would decide); the report compares it with the exact verdict.
#pragma once
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "base/verdict.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// The word of a regularity verdict in text and documents: "regular" (proved: det J has one sign),
/// "singular" (refuted: det J = 0 at `point`, or of both signs), "undecided".
const char* regularity_name(const Verdict& v);

template <class T>
struct RegularityReport {
  Verdict verdict;           // proved: regular; refuted: singular (the witness below); undecided (the reason says why)
  int sign = 0;              // regular: +1 (det J > 0 everywhere) or -1
  std::vector<T> point;      // singular: where det J = 0, or where its sign is the opposite of `other`'s
  std::vector<T> other;      // sign change: a parameter of the other sign (empty when det J = 0 at `point`)
  T value{0}, other_value{0};  // det J's numerator at point and other (local scaling, sign exact)
  int levels = 0;            // subdivision levels used
  std::size_t boxes = 0;     // boxes examined
};

/// The verdict on the whole domain (every coordinate beyond the third is an attribute).
template <class T>
RegularityReport<T> certify_regularity(const BSpline<T>& V, int max_levels = 6, const Limits& limits = {});

/// det J as an exact B-spline of degree (3p-1, 3q-1, 3r-1) (polynomial V) or its numerator
/// det J * W^4 of degree (4p-1, 4q-1, 4r-1) (rational V), C^-1 at V's breakpoints (knots of full
/// multiplicity), in V's parameters.
template <class T>
BSpline<T> jacobian_determinant(const BSpline<T>& V, const Limits& limits = {});

}  // namespace splinex
