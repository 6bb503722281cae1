// Exact root brackets along a line (internal to vrep/): simple roots of univariate Bernstein
// polynomials isolated by Descartes' rule of signs, compared with rationals and with each other
// exactly (brackets bisected by exact sign evaluation; equal roots of one polynomial certified by
// one sign variation over the union of their brackets). Used by the certified region and surface
// graphs (region_graph.cpp, surface_graph.cpp).
#pragma once
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "bernstein/tensor.hpp"

namespace splinex::vrep_detail {


template <class T>
int sign_of(const T& v) {
  return T(0) < v ? 1 : v < T(0) ? -1 : 0;
}

/// Sign variations of a Bernstein polynomial's coefficients (zeros skipped): an upper bound on its
/// roots in the open interval, of the same parity.
template <class T>
int sign_variations(const Bernstein<T>& f) {
  int changes = 0, last = 0;
  for (const auto& c : f.c) {
    const int s = sign_of(c);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

/// A simple root of a leaf along one side of a box: the leaf on the side (univariate, on [L, H]),
/// an isolating bracket [lo, hi] with opposite strict signs at its ends, or lo == hi exactly.
template <class T>
struct Root {
  std::size_t leaf = 0;
  Bernstein<T> f;
  T L, H;
  T lo, hi;
  bool exact() const { return lo == hi; }
  T value(const T& t) const { return bern_value(f, {(t - L) / (H - L)}); }
  /// Narrows the bracket to one side of t (L <= t <= H), or to t itself when t is the root.
  void cut(const T& t) {
    if (exact() || !(lo < t && t < hi)) return;
    const int s = sign_of(value(t));
    if (s == 0) lo = hi = t;
    else if (s == sign_of(value(lo))) lo = t;
    else hi = t;
  }
};

/// One end of an interval along a side: a rational or a root.
template <class T>
struct Bound {
  Root<T>* root = nullptr;
  T at;
};

inline constexpr int kRefine = 200;  // bisections before two roots that overlap count as undecidable

/// -1, 0, +1: the order of a root and a rational.
template <class T>
int compare(Root<T>& r, const T& t) {
  for (int i = 0; i < 3; ++i) {
    if (r.hi < t) return -1;
    if (t < r.lo) return 1;
    if (r.exact()) return 0;
    if (t == r.lo) return 1;  // the root is not at a bracket end
    if (t == r.hi) return -1;
    r.cut(t);
  }
  return r.exact() ? 0 : r.hi < t ? -1 : 1;
}

/// The order of two roots; nullopt when their brackets cannot be separated and they are not
/// certified equal. Roots of the same leaf on one line (`same_line`) with overlapping brackets
/// are equal when the leaf has one root in the union of the brackets (one sign variation of its
/// Bernstein coefficients there: Descartes' rule).
template <class T>
std::optional<int> compare(Root<T>& a, Root<T>& b, bool same_line) {
  for (int i = 0; i < kRefine; ++i) {
    // A bracket that is not a point holds its root strictly inside (its ends have values != 0).
    if (a.hi < b.lo || (a.hi == b.lo && !a.exact() && !b.exact())) return -1;
    if (b.hi < a.lo || (b.hi == a.lo && !a.exact() && !b.exact())) return 1;
    if (a.exact()) return -compare(b, a.lo);
    if (b.exact()) return compare(a, b.lo);
    if (same_line && a.leaf == b.leaf) {
      const T u0 = std::min(a.lo, b.lo), u1 = std::max(a.hi, b.hi);
      if (a.L <= u0 && u1 <= a.H) {
        if (sign_variations(bern_restrict(a.f, 0, T((u0 - a.L) / (a.H - a.L)), T((u1 - a.L) / (a.H - a.L)))) == 1) return 0;
      }
    }
    const T m = (std::max(a.lo, b.lo) + std::min(a.hi, b.hi)) / 2;
    a.cut(m);
    b.cut(m);
  }
  return std::nullopt;
}

template <class T>
std::optional<int> compare(Bound<T>& a, Bound<T>& b, bool same_line) {
  if (a.root && b.root) return compare(*a.root, *b.root, same_line);
  if (a.root) return compare(*a.root, b.at);
  if (b.root) return -compare(*b.root, a.at);
  return a.at < b.at ? -1 : b.at < a.at ? 1 : 0;
}

/// The roots in (0, 1) of a univariate Bernstein polynomial with non-zero end values, isolated by
/// Descartes' rule on halves (one sign variation: exactly one root, simple); rational roots at a
/// split point are exact when simple. False when a root stays unisolated (a multiple root) by
/// `depth` halvings.
template <class T>
bool isolate(const Bernstein<T>& f, const T& a, const T& b, int depth, std::vector<std::pair<T, T>>& out) {
  const int changes = sign_variations(f);
  if (changes == 0) return true;
  if (changes == 1 && !(f.c.front() == T(0)) && !(f.c.back() == T(0))) {
    out.push_back({a, b});
    return true;
  }
  if (depth == 0) return false;
  const T half = T(1) / T(2), m = (a + b) / 2;
  auto [l, r] = bern_split(f, 0, half);
  if (!isolate(l, a, m, depth - 1, out)) return false;
  if (r.c.front() == T(0)) {  // a rational root at the split point: simple when the slope is not 0
    if (bern_derivative(r, 0).c.front() == T(0)) return false;
    out.push_back({m, m});
  }
  return isolate(r, m, b, depth - 1, out);
}


}  // namespace splinex::vrep_detail
