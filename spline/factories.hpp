/// @file
/// Factories for the splines that code and tests build by hand: clamped knot vectors, a validated
/// spline from its parts, control points from a function of the multi-index, Bezier pieces and
/// affine maps. Each result passes validate(), so a hand-built input can no longer be malformed
/// silently.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/limits.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// The clamped (open, nonperiodic: The NURBS Book Eq. 2.13) knot vector of degree p on [lo, hi]:
/// p+1 copies of lo, the interior knots as given (sorted, repeats allowed), p+1 copies of hi.
template <class T>
std::vector<T> clamped_knots(int p, const T& lo, const T& hi, const std::vector<T>& interior = {}) {
  std::vector<T> U(static_cast<std::size_t>(p) + 1, lo);
  U.insert(U.end(), interior.begin(), interior.end());
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, hi);
  return U;
}

/// The spline with these degrees, knot vectors and control points (q values per point, direction 0
/// fastest; `weights` empty for a polynomial spline), validated against `limits`.
template <class T>
BSpline<T> make_spline(std::vector<int> degrees, std::vector<std::vector<T>> knots, int q, std::vector<T> points,
                       std::vector<T> weights = {}, const Limits& limits = {}) {
  BSpline<T> S;
  S.degrees = std::move(degrees);
  S.knots = std::move(knots);
  S.q = q;
  S.points = std::move(points);
  S.weights = std::move(weights);
  validate(S, limits);
  return S;
}

/// The polynomial spline whose control point with multi-index idx (direction 0 fastest) is
/// point(idx), a vector of q values.
template <class T, class F>
BSpline<T> spline_from(std::vector<int> degrees, std::vector<std::vector<T>> knots, int q, F&& point) {
  const std::size_t k = degrees.size();
  if (knots.size() != k) throw ValidationError("knots", "has " + std::to_string(knots.size()) + " vectors for " + std::to_string(k) + " directions", "give one knot vector per direction");
  std::vector<std::size_t> n(k);
  std::size_t total = 1;
  for (std::size_t l = 0; l < k; ++l) {
    if (knots[l].size() < static_cast<std::size_t>(degrees[l]) + 2)
      throw ValidationError("knots[" + std::to_string(l) + "]", "is too short for degree " + std::to_string(degrees[l]), "give at least 2 (p + 1) knots");
    n[l] = knots[l].size() - static_cast<std::size_t>(degrees[l]) - 1;
    total *= n[l];
  }
  std::vector<T> points;
  points.reserve(total * static_cast<std::size_t>(q));
  std::vector<std::size_t> idx(k, 0);
  for (std::size_t i = 0; i < total; ++i) {
    const std::vector<T> v = point(static_cast<const std::vector<std::size_t>&>(idx));
    if (v.size() != static_cast<std::size_t>(q))
      throw ValidationError("points", "a control point has " + std::to_string(v.size()) + " values, not q = " + std::to_string(q), "return q values per point");
    points.insert(points.end(), v.begin(), v.end());
    for (std::size_t l = 0; l < k && ++idx[l] == n[l]; ++l) idx[l] = 0;
  }
  return make_spline<T>(std::move(degrees), std::move(knots), q, std::move(points));
}

/// The knot vectors of a Bezier piece of these degrees on [0, 1]^k.
template <class T>
std::vector<std::vector<T>> unit_bezier_knots(const std::vector<int>& degrees) {
  std::vector<std::vector<T>> knots;
  for (int p : degrees) knots.push_back(clamped_knots(p, T(0), T(1)));
  return knots;
}

/// The polynomial Bezier piece of these degrees on [0, 1]^k (control points direction 0 fastest).
template <class T>
BSpline<T> bezier(std::vector<int> degrees, int q, std::vector<T> points) {
  auto knots = unit_bezier_knots<T>(degrees);
  return make_spline<T>(std::move(degrees), std::move(knots), q, std::move(points));
}

/// The polynomial Bezier piece of these degrees on [0, 1]^k whose control point idx is point(idx).
template <class T, class F>
BSpline<T> bezier_from(std::vector<int> degrees, int q, F&& point) {
  auto knots = unit_bezier_knots<T>(degrees);
  return spline_from<T>(std::move(degrees), std::move(knots), q, std::forward<F>(point));
}

/// The affine map r -> c + sum_l r_l E[l] on [0, 1]^k as a degree-1 Bezier piece (k = E.size(),
/// q = c.size()).
template <class T>
BSpline<T> affine_map(const std::vector<T>& c, const std::vector<std::vector<T>>& E) {
  const std::size_t k = E.size();
  return spline_from<T>(std::vector<int>(k, 1), std::vector<std::vector<T>>(k, clamped_knots(1, T(0), T(1))),
                        static_cast<int>(c.size()), [&](const std::vector<std::size_t>& idx) {
                          std::vector<T> v = c;
                          for (std::size_t l = 0; l < k; ++l)
                            if (idx[l] == 1)
                              for (std::size_t d = 0; d < c.size(); ++d) v[d] = v[d] + E[l][d];
                          return v;
                        });
}

}  // namespace splinex
