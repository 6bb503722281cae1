// Degree elevation of B-splines (not only Bezier) by any amount t in any direction, by two
// independent algorithms that must agree exactly in exact arithmetic:
//  - ElevationMethod::bezier_pieces: NURBS Book A5.9 (DegreeElevateCurve): extract Bezier pieces
//    by insertion, elevate each, remove the surplus knots again, in one sweep;
//  - ElevationMethod::blossom: the blossom (polar form) of the Cohen-Lyche-Schumaker theorem:
//    the elevated coefficient Q_j is the symmetrized degree-(p+1) blossom of the piece it belongs
//    to, Q_j = 1/(p+1) sum_k f(u_{j+1}, .., u_{j+k}^, .., u_{j+p+1}) on the elevated knots,
//    evaluated by de Boor's algorithm with a different argument at each level; t steps of one.
//  - ElevationMethod::automatic (the default): A5.9 in exact arithmetic (the same result as the
//    blossom, 2-4x faster there on mpq; the fraction-free kernel, exact/ffnet.hpp, elevates by one
//    at p >= 3 through its own integer blossom, which is faster on its integers), the blossom in
//    floating point, where A5.9's knot removal
//    extrapolates and loses bits (measured in the report's elevation-accuracy section: up to about
//    20 bits at degree 7 on random curves, the blossom 1-2) at about the same speed as SISL's s1750.
// Each distinct knot's multiplicity grows by t. Unclamped directions are clamped first (the
// function on the domain is unchanged; the representation outside it is dropped).
#pragma once
#include "spline/bspline.hpp"

namespace splinex {

enum class ElevationMethod { bezier_pieces, blossom, automatic };

/// The method `automatic` stands for in arithmetic T.
template <class T>
constexpr ElevationMethod resolve_elevation_method(ElevationMethod m) {
  if (m != ElevationMethod::automatic) return m;
  return ArithTraits<T>::exact ? ElevationMethod::bezier_pieces : ElevationMethod::blossom;
}

template <class T>
BSpline<T> elevate_degree(const BSpline<T>& S, int d, int t, ElevationMethod method = ElevationMethod::automatic,
                          const Limits& limits = {});

/// The control-point count after elevating direction d by t (for size checks before the work).
template <class T>
std::size_t elevated_count(const BSpline<T>& S, int d, int t);

}  // namespace splinex
