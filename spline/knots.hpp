// Knot vectors (NURBS Book ch. 2): validation, span search (A2.1), multiplicities.
// Generic over the scalar T; only comparisons are used, and they are exact in exact arithmetic.
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "base/errors.hpp"

namespace splinex {

/// Validates a knot vector of degree p for n control points. Rules: p >= 0, n >= p+1,
/// size == n+p+1, non-decreasing, every multiplicity <= p+1, non-empty domain [U[p], U[n]].
template <class T>
void validate_knots(const std::vector<T>& U, int p, std::size_t n, const std::string& field) {
  if (p < 0) throw ValidationError(field, "degree " + std::to_string(p) + " is negative", "use a degree >= 0");
  if (n < static_cast<std::size_t>(p) + 1)
    throw ValidationError(field,
                          std::to_string(n) + " control points are too few for degree " + std::to_string(p),
                          "give at least degree+1 = " + std::to_string(p + 1) + " control points");
  if (U.size() != n + p + 1)
    throw ValidationError(field,
                          "has " + std::to_string(U.size()) + " knots but degree " + std::to_string(p) +
                              " with " + std::to_string(n) + " control points needs n+p+1 = " +
                              std::to_string(n + p + 1),
                          "give exactly n+p+1 knots, or n = #knots-p-1 control points");
  std::size_t run = 1;
  for (std::size_t i = 1; i < U.size(); ++i) {
    if (U[i] < U[i - 1])
      throw ValidationError(field + "[" + std::to_string(i) + "]",
                            "knots decrease at index " + std::to_string(i),
                            "knot vectors must be non-decreasing; sort them");
    run = (U[i] == U[i - 1]) ? run + 1 : 1;
    if (run > static_cast<std::size_t>(p) + 1)
      throw ValidationError(field + "[" + std::to_string(i) + "]",
                            "a knot has multiplicity " + std::to_string(run) + " above degree+1 = " +
                                std::to_string(p + 1),
                            "remove repeated knots so none occurs more than degree+1 times");
  }
  if (!(U[p] < U[n]))
    throw DomainError(field, "the domain [U[p], U[n]] is empty", "make U[p] < U[n]");
}

/// A2.1 FindSpan: the index s with U[s] <= x < U[s+1], p <= s <= n-1; x == U[n] gives the last
/// non-empty span. Assumes x inside [U[p], U[n]] (callers check the domain first).
template <class T>
std::size_t find_span(const std::vector<T>& U, int p, std::size_t n, const T& x) {
  if (!(x < U[n])) {  // right end: the last span with U[s] < U[s+1]
    std::size_t s = n - 1;
    while (s > static_cast<std::size_t>(p) && !(U[s] < U[s + 1])) --s;
    return s;
  }
  std::size_t lo = p, hi = n;  // U[lo] <= x < U[hi]
  while (hi - lo > 1) {
    std::size_t mid = lo + (hi - lo) / 2;
    if (x < U[mid]) hi = mid; else lo = mid;
  }
  return lo;
}

/// How often x occurs in the (sorted) knot vector U: O(log n).
template <class T>
std::size_t multiplicity(const std::vector<T>& U, const T& x) {
  const auto less = [](const T& a, const T& b) { return a < b; };
  const auto r = std::equal_range(U.begin(), U.end(), x, less);
  return static_cast<std::size_t>(r.second - r.first);
}

/// Whether x is a knot of multiplicity p+1: the spline may jump there (C^-1; at degree 0 every
/// breakpoint is one).
template <class T>
bool is_full_multiplicity(const std::vector<T>& U, int p, const T& x) {
  return multiplicity(U, x) == static_cast<std::size_t>(p) + 1;
}

/// The distinct knot values inside the domain [U[p], U[n]], ends included: the breakpoints.
template <class T>
std::vector<T> breakpoints(const std::vector<T>& U, int p, std::size_t n) {
  std::vector<T> b;
  b.reserve(n + 1 - static_cast<std::size_t>(p));  // at most one per knot of the domain
  for (std::size_t i = p; i <= n; ++i)
    if (b.empty() || b.back() < U[i]) b.push_back(U[i]);
  return b;
}

template <class T>
bool is_clamped(const std::vector<T>& U, int p, std::size_t n) {
  for (int i = 0; i < p; ++i)
    if (!(U[i] == U[p]) || !(U[n + 1 + i] == U[n])) return false;
  return true;
}

}  // namespace splinex
