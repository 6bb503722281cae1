// Trivariate constructors of papers/002 Section 3.2.2, generic over the arithmetic and exact for
// exact input: extrusion, ruled volume, volume of revolution with exact rational circles,
// volumetric Boolean sum (trivariate Coons) and volumetric sweep (interpolation, solved exactly).
//
// Every constructor returns a clamped B-spline trivariate T(u, v, w) (dim 3) whose points have the
// input surfaces' coordinates (q >= 3: geometry first, attribute coordinates after it are carried
// along, Section 3.1.2). Faces: face(T, d, side) is the surface at the start (side 0) or end (side
// 1) of direction d, read off the boundary layer of the clamped net.
//
//  - extrude(S, V): T = S(u, v) + V w, w in [0, 1]; degree 1 in w.
//  - ruled(S1, S2): T = S1 (1 - w) + S2 w after S1 and S2 are made compatible (common degrees by
//    elevation, common knots by insertion, exactly). Rational surfaces are interpolated in
//    homogeneous coordinates: the rulings are still the straight segments from S1(u, v) to S2(u,
//    v), parametrized rationally when the weights differ.
//  - revolve(S, axis, quarters): S rotated about a coordinate axis by quarters x 90 degrees. The
//    circle is exact with rational coefficients: each quarter arc is the rational quadratic with
//    points e_a, e_a + e_{a+1}, e_{a+1} (e_a the unit vectors at a x 90 degrees) and weights
//    (1, 1, 2) or (2, 1, 1) alternately (the conic with shape factor w1^2 / (w0 w2) = 1/2, the same
//    circle as the usual (1, sqrt(2)/2, 1), parametrized differently; no square root). Control
//    point (P, c) -> P rotated by the complex number c, weight w_P w_c: T(u, v, w) = rotation of
//    S(u, v) by the angle of C(w), exactly.
//  - boolean_sum(F): the trivariate Coons volume of six faces F[d][side] (F[0][*] in (v, w),
//    F[1][*] in (u, w), F[2][*] in (u, v)), polynomial, made compatible per direction; the faces
//    must share their edges exactly. T = P_u + P_v + P_w - P_uv - P_vw - P_wu + P_uvw in control
//    points, the linear blends represented exactly through the Greville abscissae (linear
//    precision).
//  - coons_surface(C): the bilinearly blended Coons surface of four boundary curves C[0][s] (at u =
//    s, curves in v) and C[1][s] (at v = s, curves in u), polynomial, made compatible per direction;
//    the curves must meet exactly at the four corners. S = P_u + P_v - P_uv in control points, the
//    linear blends exact through the Greville abscissae, as boolean_sum's (the caps and the faces
//    that boolean_sum's volumes are built from, papers/002 Figure 13).
//  - tube_boolean_sum(S): papers/002's "volumetric Boolean sum version of the B-rep surface" (the
//    teapot's handle, Figure 14; the duck, Figure 13) for a closed polynomial tube S(u, v) (u once
//    around, S(lo, v) = S(hi, v) exactly; v along the tube): u cut at its quarters into four strips,
//    the side faces v = 0, u = 1, v = 1, u = 0 of the volume (the last two reversed), both domains
//    mapped to [0, 1]; the end caps w = 0, 1 the Coons surfaces of the strips' end curves; then
//    boolean_sum. Not closed, rational or not a surface: ValidationError naming `surface`.
//  - sweep(S_k, w_k, degree): T interpolating the surfaces S_k at w_k (increasing, w_0 = 0, last =
//    1), knots by averaging (NURBS Book 9.8), one linear system per control point solved by
//    Gaussian elimination (exact in exact arithmetic); rational surfaces interpolated in
//    homogeneous coordinates (an interpolated weight that is not positive is an error).
// Bad input (not surfaces, point sizes that differ, edges that do not meet, w_k not increasing) is
// a ValidationError naming the input and the fix.
#pragma once
#include <array>
#include <vector>

#include "base/limits.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
BSpline<T> extrude(const BSpline<T>& S, const std::vector<T>& V, const Limits& limits = {});

template <class T>
BSpline<T> ruled(const BSpline<T>& S1, const BSpline<T>& S2, const Limits& limits = {});

/// axis: 0, 1, 2 (x, y, z); quarters: 1..4 (90 to 360 degrees, counter-clockwise about the axis).
template <class T>
BSpline<T> revolve(const BSpline<T>& S, int axis = 2, int quarters = 4, const Limits& limits = {});

/// The rational quadratic circle arc of `quarters` x 90 degrees used by revolve: points in R^2 on
/// the unit circle, domain [0, 1].
template <class T>
BSpline<T> rational_circle(int quarters = 4);

template <class T>
BSpline<T> boolean_sum(const std::array<std::array<BSpline<T>, 2>, 3>& faces, const Limits& limits = {});

/// curves[0][s]: the boundary at u = s (a curve in v); curves[1][s]: at v = s (a curve in u).
template <class T>
BSpline<T> coons_surface(const std::array<std::array<BSpline<T>, 2>, 2>& curves, const Limits& limits = {});

template <class T>
BSpline<T> tube_boolean_sum(const BSpline<T>& S, const Limits& limits = {});

template <class T>
BSpline<T> sweep(const std::vector<BSpline<T>>& surfaces, const std::vector<T>& at, int degree = 3, const Limits& limits = {});

/// The boundary surface of a clamped trivariate at the start (side 0) or end (side 1) of direction
/// d, in the remaining two directions in order.
template <class T>
BSpline<T> face(const BSpline<T>& V, int d, int side);

}  // namespace splinex
