// The hybrid multi-sided patch with B-spline boundaries (papers/003: Salvi's patch as studied by
// Wang and Zhu, Definition 2.4, Eq. 2.4-2.12), generic over the arithmetic T.
//
// Numbering (0-based, unlike the paper): the domain is a strictly convex polygon V_0..V_{n-1},
// counter-clockwise; side i runs from V_i to V_{i+1}. The paper's side e_i runs from v_{i-1} to
// v_i, so its Definition 2.3 (w_i from the normals of e_{i-1} and e_i) attaches the weight of
// vertex v_{i-1} to index i; here lambda_k is the coordinate of vertex V_k, from its two incident
// sides k-1 and k (the indexing CGAL uses; the test compares the two exactly).
//
// Exactness. With N_i the outward (not unit) normal of side i and phi_i(x) = (V_i - x) . N_i,
// w_k = <N_{k-1}, N_k> / (phi_{k-1} phi_k) is the paper's w_k: scaling a normal scales one phi
// and the cross product alike. So Wachspress coordinates are rational functions with rational
// coefficients. They are evaluated in product form, lambda_k ~ <N_{k-1}, N_k> prod_{j != k-1, k}
// phi_j, which has no pole on the closed polygon (the sum is positive there), so sides and
// corners need no special case. s_i in the continuous form of Eq. 2.9: sin(theta) phi / (...) with
// unit normals equals, after multiplying numerator and denominator by |N_{i-1}| |N_i| |N_{i+1}|,
//     s_i = c_{i+1} phi_{i-1} / (c_{i+1} phi_{i-1} + c_i phi_{i+1}),   c_k = <N_{k-1}, N_k>,
// rational again, and equal to lambda_{i+1} / (lambda_i + lambda_{i+1}) (Eq. 2.5) wherever both are
// defined (a test checks it exactly).
//
// Limits (points where a formula reads 0/0), each documented and tested exactly:
//  - s_i (Eq. 2.9) is 0/0 only where phi_{i-1} = phi_{i+1} = 0: for a triangle, the vertex
//    opposite side i. There h_i = 1 and every term of side i carries B_k^d(h_i), k <= l-1 < d,
//    which vanishes; s_i = 1/2 is used and the value does not depend on it.
//  - alpha_i = h_{i-1}^2 / (h_{i-1}^2 + h_i^2) is 0/0 at the corner V_i, beta_{i-1} likewise. Off
//    the corner alpha_i + beta_{i-1} = 1; at V_i only the (0,0) term of side i and the (d,0) term
//    of side i-1 survive, weighted alpha_i and beta_{i-1}, and both multiply the shared corner
//    point P_i(0) = P_{i-1}(1). Any split with alpha_i + beta_{i-1} = 1 gives the limit; 1/2 each.
//  - Eq. 2.11's factor p / (U_{p+j} - U_j) is p/0 at j = 0 for every clamped knot vector (the
//    paper's own Example 2.1). RibbonFactor::eq_2_11 reproduces it literally and throws there;
//    the default RibbonFactor::side_interpolant uses the h-derivative of the paper's side
//    interpolant I_i (Section 3.1) at h = 0, the constant p / (U_{p+1} - U_1): the cross
//    derivative the ribbon is meant to carry (for Bezier sides it is Salvi's factor d).
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "spline/arith.hpp"
#include "spline/bspline.hpp"

namespace splinex {

enum class RibbonFactor { side_interpolant, eq_2_11 };

template <class T>
struct HybridPatch {
  std::vector<Point2<T>> vertices;  // strictly convex, counter-clockwise, n >= 3
  int d = 0;                               // Bernstein degree of the patch, d >= 3
  std::vector<int> p;                      // B-spline degree of side i's boundary, 1 <= p_i <= d
  std::vector<std::vector<T>> knots;       // side i: d + p_i + 2 knots, clamped on [0, 1]
  int q = 3;                               // coordinates of a control point
  /// Control point C^i_{j,k} (side i, column j = 0..d, layer k = 0..l-1) at
  /// ((i * l + k) * (d + 1) + j) * q; corners shared: C^i_{a,b} = C^{i-1}_{d-b,a} for a, b < l.
  std::vector<T> points;
  RibbonFactor ribbon = RibbonFactor::side_interpolant;

  std::size_t sides() const { return vertices.size(); }
  int layers() const { return (d + 1) / 2; }  // l = ceil(d / 2)
  std::size_t index(std::size_t i, int j, int k) const {
    return ((i * static_cast<std::size_t>(layers()) + k) * (d + 1) + j) * q;
  }
};

/// The patch with every number converted by conv (e.g. the exact patch rounded to double).
template <class B, class A, class F>
HybridPatch<B> convert_hybrid(const HybridPatch<A>& P, F&& conv) {
  HybridPatch<B> Q;
  for (const auto& v : P.vertices) Q.vertices.push_back({conv(v[0]), conv(v[1])});
  Q.d = P.d;
  Q.p = P.p;
  Q.q = P.q;
  Q.ribbon = P.ribbon;
  for (const auto& U : P.knots) {
    Q.knots.emplace_back();
    for (const auto& u : U) Q.knots.back().push_back(conv(u));
  }
  for (const auto& c : P.points) Q.points.push_back(conv(c));
  return Q;
}

/// Everything the patch needs at one domain point.
template <class T>
struct HybridLocal {
  std::vector<T> lambda;  // Wachspress coordinates, one per vertex
  std::vector<T> s, h;    // per side
};

template <class T>
HybridLocal<T> hybrid_local(const HybridPatch<T>& P, const Point2<T>& x);

/// The patch's point at x (q coordinates). x must lie in the closed domain (DomainError).
template <class T>
std::vector<T> hybrid_evaluate(const HybridPatch<T>& P, const Point2<T>& x);

/// The boundary curve P_i(s) and the ribbon's cross-derivative function T_i(s) (Eq. 2.11).
template <class T>
std::vector<T> hybrid_boundary(const HybridPatch<T>& P, std::size_t i, const T& s);
template <class T>
std::vector<T> hybrid_cross_tangent(const HybridPatch<T>& P, std::size_t i, const T& s);

/// First derivatives (exact in exact arithmetic: forward mode with Dual<T>, spline/dual.hpp).
/// The patch is differentiable on the closed domain except at the corners, where alpha_i and
/// beta_{i-1} have no limit (a 0/0 whose value depends on the direction of approach); there the
/// functions below throw DomainError. On knots of a side the one-sided derivative of the knot span
/// A2.1 picks is returned.
template <class T>
struct HybridJet {
  std::vector<T> point, derivative;  // S(x) and d/dtau S(x + tau w) at tau = 0
  HybridLocal<T> local, local_derivative;  // lambda, s, h and their derivatives along w
};
template <class T>
HybridJet<T> hybrid_jet(const HybridPatch<T>& P, const Point2<T>& x, const Point2<T>& w);

template <class T>
struct HybridDerivatives {
  std::vector<T> point, du, dv;
};
template <class T>
HybridDerivatives<T> hybrid_derivatives(const HybridPatch<T>& P, const Point2<T>& x);

/// Theorem 3.2's derivative: dS/dh_i at fixed s_i. The level sets of s_i (Eq. 2.9) are the lines
/// through O_i, the intersection of the lines of sides i-1 and i+1 (parallel to them when those
/// sides are parallel), so the derivative is taken along w = O_i - x:
///     dS/dh_i |_{s_i} = (d/dtau S) / (d/dtau h_i),
/// and d/dtau s_i = 0 exactly (tests check it). Returned with the direction w used.
template <class T>
struct HybridCrossDerivative {
  std::vector<T> value;     // dS/dh_i at fixed s_i
  Point2<T> direction;  // w, tangent to the iso-line of s_i through x
};
template <class T>
HybridCrossDerivative<T> hybrid_cross_derivative(const HybridPatch<T>& P, std::size_t i, const Point2<T>& x);

/// Side i's boundary P_i as a kernel B-spline curve (degree p_i, side i's knots, row C^i_{j,0}),
/// e.g. for its derivatives.
template <class T>
BSpline<T> hybrid_boundary_spline(const HybridPatch<T>& P, std::size_t i) {
  BSpline<T> C;
  C.degrees = {P.p[i]};
  C.knots = {P.knots[i]};
  C.q = P.q;
  for (int j = 0; j <= P.d; ++j)
    for (int c = 0; c < P.q; ++c) C.points.push_back(P.points[P.index(i, j, 0) + c]);
  return C;
}

/// Structural checks with typed errors naming the field: n >= 3, strictly convex and
/// counter-clockwise, d >= 3, p_i in [1, d], knot counts d + p_i + 2, clamped on [0, 1],
/// non-decreasing, control point count, shared corner points equal.
template <class T>
void validate(const HybridPatch<T>& P);

}  // namespace splinex
