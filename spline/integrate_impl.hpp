#pragma once
#include <algorithm>

#include "base/errors.hpp"
#include "spline/bezier.hpp"
#include "spline/elevate.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"
#include "spline/knots.hpp"

namespace splinex {

template <class T>
std::vector<T> integrate(const BSpline<T>& f) {
  validate(f);
  if (f.is_rational())
    throw ValidationError("weights", "integrate needs a polynomial spline", "integrate the numerator and denominator "
                                                                             "separately or use a quadrature");
  const int k = f.dim();
  std::vector<T> out(f.q, T(0));
  std::vector<std::size_t> idx(k, 0);
  for (std::size_t flat = 0; flat < f.size(); ++flat) {
    T basis(1);
    for (int d = 0; d < k; ++d) {
      const auto& U = f.knots[d];
      const int p = f.degrees[d];
      basis = basis * (U[idx[d] + p + 1] - U[idx[d]]) / T(p + 1);
    }
    for (int c = 0; c < f.q; ++c) out[c] = out[c] + basis * f.points[flat * f.q + c];
    for (int d = 0; d < k; ++d) {
      if (++idx[d] < f.count(d)) break;
      idx[d] = 0;
    }
  }
  return out;
}

template <class T>
std::pair<BSpline<T>, BSpline<T>> make_compatible(const BSpline<T>& A0, const BSpline<T>& B0, const Limits& limits) {
  validate(A0, limits);
  validate(B0, limits);
  if (A0.dim() != B0.dim() || A0.q != B0.q)
    throw ValidationError("degrees", "the two splines differ in dimension or point size", "compare like with like");
  BSpline<T> A = clamp_all(A0, limits), B = clamp_all(B0, limits);
  for (int d = 0; d < A.dim(); ++d) {
    if (!(A.domain_lo(d) == B.domain_lo(d)) || !(A.domain_hi(d) == B.domain_hi(d)))
      throw DomainError("knots[" + std::to_string(d) + "]", "the two splines have different domains",
                        "reparametrize one of them first");
    if (A.degrees[d] < B.degrees[d]) A = elevate_degree(A, d, B.degrees[d] - A.degrees[d], ElevationMethod::automatic, limits);
    if (B.degrees[d] < A.degrees[d]) B = elevate_degree(B, d, A.degrees[d] - B.degrees[d], ElevationMethod::automatic, limits);
    /// Insert into each what the other has more of.
    auto missing = [](const std::vector<T>& from, const std::vector<T>& into) {
      std::vector<T> out;
      for (std::size_t i = 0; i < from.size();) {
        std::size_t j = i;
        while (j < from.size() && from[j] == from[i]) ++j;
        const std::size_t have = multiplicity(into, from[i]);
        for (std::size_t c = have; c < j - i; ++c) out.push_back(from[i]);
        i = j;
      }
      return out;
    };
    const auto toA = missing(B.knots[d], A.knots[d]), toB = missing(A.knots[d], B.knots[d]);
    if (!toA.empty()) A = refine_knots(A, d, toA, limits);
    if (!toB.empty()) B = refine_knots(B, d, toB, limits);
  }
  return {std::move(A), std::move(B)};
}

template <class T>
BSpline<T> difference(const BSpline<T>& A0, const BSpline<T>& B0, const Limits& limits) {
  if (A0.is_rational() || B0.is_rational())
    throw ValidationError("weights", "difference needs polynomial splines", "subtract homogeneous forms instead");
  std::pair<BSpline<T>, BSpline<T>> AB = make_compatible(A0, B0, limits);
  BSpline<T>& A = AB.first;
  const BSpline<T>& B = AB.second;
  for (std::size_t i = 0; i < A.points.size(); ++i) A.points[i] -= B.points[i];
  return std::move(A);
}

namespace detail {

/// Curves: where the control polygon first crosses zero, as a fraction of the cell in (0, 1),
/// rounded to 20 bits (comparisons only, so exact denominators stay small). Near a simple root
/// this converges fast (Bezier-clipping-like), where the midpoint would gain one bit per level.
template <class T>
T polygon_crossing(const std::vector<T>& b) {
  const int p = static_cast<int>(b.size()) - 1;
  T x = T(1) / T(2);
  for (int i = 0; i < p; ++i) {
    const bool change = (b[i] < T(0) && !(b[i + 1] < T(0))) || (T(0) < b[i] && !(T(0) < b[i + 1]));
    if (change) {
      x = (T(i) + b[i] / (b[i] - b[i + 1])) / T(p);
      break;
    }
  }
  constexpr int bits = 20;
  T lo(0), hi(1);
  for (int k = 0; k < bits; ++k) {
    const T m = (lo + hi) / T(2);
    (!(x < m) ? lo : hi) = m;
  }
  if (lo == T(0)) return hi;  // keep the split point strictly inside the cell
  return lo;
}

template <class T>
void integrate_abs_cell(const BSpline<T>& cell, int depth, const T& budget_per_volume, AbsIntegral<T>& acc) {
  ++acc.cells;
  bool pos = false, neg = false;
  T sum(0), sum_abs(0);
  for (const T& b : cell.points) {
    if (T(0) < b) pos = true;
    if (b < T(0)) neg = true;
    sum = sum + b;
    sum_abs = sum_abs + (b < T(0) ? T(-b) : b);
  }
  T vol(1);
  for (int d = 0; d < cell.dim(); ++d) vol = vol * (cell.domain_hi(d) - cell.domain_lo(d));
  const T n(static_cast<long>(cell.points.size()));
  const T integral = vol * sum / n;  // Bezier: every Bernstein polynomial integrates to vol / n
  const T abs_integral = integral < T(0) ? T(-integral) : integral;
  if (!(pos && neg)) {
    acc.lower = acc.lower + abs_integral;
    acc.upper = acc.upper + abs_integral;
    return;
  }
  if (depth == 0 || !(budget_per_volume * vol < vol * (sum_abs - (sum < T(0) ? T(-sum) : sum)) / n)) {
    ++acc.undecided;
    acc.lower = acc.lower + abs_integral;
    acc.upper = acc.upper + vol * sum_abs / n;
    return;
  }
  int dir = 0;  // halve the longest side
  for (int d = 1; d < cell.dim(); ++d)
    if (cell.domain_hi(dir) - cell.domain_lo(dir) < cell.domain_hi(d) - cell.domain_lo(d)) dir = d;
  T frac = T(1) / T(2);
  if (cell.dim() == 1) frac = polygon_crossing(cell.points);
  const T mid = cell.domain_lo(dir) + (cell.domain_hi(dir) - cell.domain_lo(dir)) * frac;
  const auto halves = split_at(cell, dir, mid);
  integrate_abs_cell(halves.first, depth - 1, budget_per_volume, acc);
  integrate_abs_cell(halves.second, depth - 1, budget_per_volume, acc);
}

}  // namespace detail

template <class T>
AbsIntegral<T> integrate_abs(const BSpline<T>& f, int max_depth, const T& rel_width) {
  validate(f);
  if (f.q != 1 || f.is_rational())
    throw ValidationError("points", "integrate_abs needs a scalar polynomial spline (q = 1, no weights)",
                          "integrate one coordinate at a time");
  if (max_depth < 0 || max_depth > 60)
    throw ValidationError("max_depth", "must be in 0..60", "use a subdivision depth like 10");
  if (rel_width < T(0)) throw ValidationError("rel_width", "is negative", "use 0 (depth only) or a small positive value");
  const auto pieces = extract_bezier(f);
  /// Without a relative target the budget is -1: no cell stops early. Else a first pass at depth 0
  /// gives the lower bound the budget is relative to.
  T budget_per_volume(-1);
  if (T(0) < rel_width) {
    AbsIntegral<T> first;
    first.lower = first.upper = T(0);
    for (const auto& piece : pieces) detail::integrate_abs_cell(piece.spline, 0, T(-1), first);
    T vol(1);
    for (int d = 0; d < f.dim(); ++d) vol = vol * (f.domain_hi(d) - f.domain_lo(d));
    budget_per_volume = rel_width * (T(0) < first.lower ? first.lower : first.upper) / vol;
  }
  AbsIntegral<T> acc;
  acc.lower = T(0);
  acc.upper = T(0);
  for (const auto& piece : pieces) detail::integrate_abs_cell(piece.spline, max_depth, budget_per_volume, acc);
  return acc;
}

}  // namespace splinex
