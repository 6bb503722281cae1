#pragma once
#include <algorithm>
#include <string>

#include "spline/insert.hpp"

namespace splinex {
namespace detail {

/// A5.1 CurveKnotIns on a block of n points of m coordinates: insert x r times into span k where
/// x already has multiplicity s. Each new point is P_{i-1} + alpha (P_i - P_{i-1}): one
/// multiplication per coordinate, alpha computed once per point.
template <class T>
CurveBlock<T> curve_knot_ins(int p, const std::vector<T>& UP, const T* P, std::size_t n, std::size_t m, const T& x,
                             std::size_t k, int s, int r) {
  const std::size_t np = n - 1, mp = np + p + 1;
  CurveBlock<T> out;
  out.p = p;
  /// Built in order with block copies (no zero fill of what is copied next): knots U[0..k], r
  /// copies of x, U[k+1..]; points Q_i = P_i (i <= k-p), the p-s+r-1 new ones, Q_{i+r} = P_i (i >= k-s).
  out.U.reserve(UP.size() + r);
  out.U.insert(out.U.end(), UP.begin(), UP.begin() + k + 1);
  out.U.insert(out.U.end(), static_cast<std::size_t>(r), x);
  out.U.insert(out.U.end(), UP.begin() + k + 1, UP.begin() + mp + 1);
  out.P.reserve((n + r) * m);
  out.P.insert(out.P.end(), P, P + (k - p + 1) * m);
  out.P.resize((k - s + r) * m);
  out.P.insert(out.P.end(), P + (k - s) * m, P + (np + 1) * m);
  T* Q = out.P.data();
  // Raising multiplicity p to p+1 (outside A5.1, which assumes s + r <= p; r = 1 here): the curve
  // passes through P_{k-p} at x, and the new net repeats that point (Q_{k-p+1} = P_{k-p}, above).
  if (s == p) return out;
  std::vector<T> R(P + (k - p) * m, P + (k - s + 1) * m);  // R_i = P_{k-p+i}, i = 0..p-s
  std::size_t L = 0;
  for (int j = 1; j <= r; ++j) {
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const T alpha = (x - UP[L + i]) / (UP[i + k + 1] - UP[L + i]);
      T* a = R.data() + i * m;
      const T* b = R.data() + (i + 1) * m;
      for (std::size_t c = 0; c < m; ++c) a[c] += alpha * (b[c] - a[c]);
    }
    std::copy(R.begin(), R.begin() + m, Q + L * m);
    std::copy(R.begin() + (p - j - s) * m, R.begin() + (p - j - s + 1) * m, Q + (k + r - j - s) * m);
  }
  for (std::size_t i = L + 1; i + s < k; ++i) std::copy(R.begin() + (i - L) * m, R.begin() + (i - L + 1) * m, Q + i * m);
  return out;
}

/// A5.4 RefineKnotVectCurve: insert the sorted knots X (r+1 of them) in one pass.
template <class T>
CurveBlock<T> refine_knot_vect_curve(int p, const std::vector<T>& U, const T* P, std::size_t count, std::size_t mm,
                                     const std::vector<T>& X) {
  CurveBlock<T> out;
  out.p = p;
  if (X.empty()) { out.U = U; out.P.assign(P, P + count * mm); return out; }
  const std::size_t n = count - 1, m = n + p + 1, r = X.size() - 1;
  const std::size_t a = find_span(U, p, count, X.front());
  const std::size_t b = find_span(U, p, count, X.back()) + 1;
  out.U.resize(U.size() + r + 1);
  out.P.resize((count + r + 1) * mm);
  std::vector<T>& Ub = out.U;
  T* Q = out.P.data();
  auto copy_pt = [mm](const T* from, T* to) { std::copy(from, from + mm, to); };
  for (std::size_t j = 0; j + p <= a; ++j) copy_pt(P + j * mm, Q + j * mm);
  for (std::size_t j = b - 1; j <= n; ++j) copy_pt(P + j * mm, Q + (j + r + 1) * mm);
  for (std::size_t j = 0; j <= a; ++j) Ub[j] = U[j];
  for (std::size_t j = b + p; j <= m; ++j) Ub[j + r + 1] = U[j];
  std::size_t i = b + p - 1, k = b + p + r;
  for (std::size_t jj = r + 1; jj-- > 0;) {
    while (!(U[i] < X[jj]) && i > a) {
      copy_pt(P + (i - p - 1) * mm, Q + (k - p - 1) * mm);
      Ub[k] = U[i];
      --k;
      --i;
    }
    copy_pt(Q + (k - p) * mm, Q + (k - p - 1) * mm);
    for (int l = 1; l <= p; ++l) {
      const std::size_t ind = k - p + l;
      T alfa = Ub[k + l] - X[jj];
      T* dst = Q + (ind - 1) * mm;
      const T* src = Q + ind * mm;
      if (alfa == T(0)) {
        copy_pt(src, dst);
      } else {
        alfa = alfa / (Ub[k + l] - U[i - p + l]);
        // alfa*dst + (1-alfa)*src = src + alfa*(dst - src)
        for (std::size_t c = 0; c < mm; ++c) dst[c] = src[c] + alfa * (dst[c] - src[c]);
      }
    }
    Ub[k] = X[jj];
    --k;
  }
  return out;
}

template <class T>
void check_insertable(const BSpline<T>& S, int d, const T& x, std::size_t extra, const std::string& field) {
  const auto& U = S.knots[d];
  const int p = S.degrees[d];
  if (x < S.domain_lo(d) || S.domain_hi(d) < x)
    throw DomainError(field, "knot lies outside the domain of direction " + std::to_string(d),
                      "insert knots inside [U[p], U[n]]");
  const std::size_t mult = multiplicity(U, x);
  if (mult + extra > static_cast<std::size_t>(p) + 1)
    throw ValidationError(field,
                          "inserting it would give multiplicity " + std::to_string(mult + extra) + " above degree+1 = " +
                              std::to_string(p + 1),
                          "insert it at most " + std::to_string(p + 1 - std::min<std::size_t>(mult, p + 1)) + " more times");
}

/// Every run of equal knots in the sorted list X, checked as one insertion of that many copies.
template <class T>
void check_insertable_sorted(const BSpline<T>& S, int d, const std::vector<T>& X) {
  for (std::size_t i = 0; i < X.size(); ++i) {
    std::size_t same = 1;
    while (i + same < X.size() && X[i + same] == X[i]) ++same;
    check_insertable(S, d, X[i], same, "knots[" + std::to_string(i) + "]");
    i += same - 1;
  }
}

}  // namespace detail

template <class T>
BSpline<T> insert_knot(const BSpline<T>& S, int d, const T& x, int times, const Limits& limits) {
  detail::check_direction(S, d);
  if (times < 0) throw UsageError("times", "is negative", "insert a knot 0 or more times");
  if (times == 0) return S;
  detail::check_insertable(S, d, x, times, "knots");
  limits.check_count(S.size() / S.count(d) * (S.count(d) + times), "knots");
  /// A5.1 wants the span k with U[k] <= x < U[k+1]: the last knot <= x. (For x on the right end
  /// of an unclamped domain this lies past FindSpan's last span.)
  const auto& U0 = S.knots[d];
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(U0.begin(), U0.end(), x, [](const T& a, const T& b) { return a < b; }) -
                               U0.begin()) - 1;
  const int s = static_cast<int>(multiplicity(U0, x));
  const int p = S.degrees[d];
  /// A5.1 up to multiplicity p, then (if asked) the last step to p+1 separately.
  const int r1 = std::min(times, p - s);
  /// The input is read in place (apply_along); no copy of S is made unless nothing is inserted.
  const auto last_step = [&](const BSpline<T>& R) {
    return apply_along(R, d, [&](int pp, const std::vector<T>& U, const T* P, std::size_t nn, std::size_t m) {
      return detail::curve_knot_ins(pp, U, P, nn, m, x, k + r1, p, 1);
    });
  };
  if (r1 == 0) return last_step(S);
  BSpline<T> R = apply_along(S, d, [&](int pp, const std::vector<T>& U, const T* P, std::size_t nn, std::size_t m) {
    return detail::curve_knot_ins(pp, U, P, nn, m, x, k, s, r1);
  });
  if (times > r1) return last_step(R);
  return R;
}

template <class T>
BSpline<T> insert_knots_boehm(const BSpline<T>& S, int d, const std::vector<T>& X, const Limits& limits) {
  detail::check_direction(S, d);
  std::vector<T> sorted = X;
  std::sort(sorted.begin(), sorted.end(), [](const T& a, const T& b) { return a < b; });
  detail::check_insertable_sorted(S, d, sorted);
  limits.check_count(S.size() / S.count(d) * (S.count(d) + X.size()), "knots");
  return apply_along(S, d, [&](int p, const std::vector<T>& U0, const T* P0, std::size_t n0, std::size_t m) {
    CurveBlock<T> out;
    out.p = p;
    out.U = U0;
    out.P.assign(P0, P0 + n0 * m);
    std::vector<T>& U = out.U;
    std::vector<T>& P = out.P;
    std::vector<T> R;
    for (const T& x : X) {
      /// A5.1 with r = 1 (curve_knot_ins): span k is the last knot <= x, s its multiplicity.
      const std::size_t k = static_cast<std::size_t>(
                                std::upper_bound(U.begin(), U.end(), x, [](const T& a, const T& b) { return a < b; }) -
                                U.begin()) - 1;
      const int s = static_cast<int>(multiplicity(U, x));
      if (s >= p) {
        // Multiplicity p to p+1: the net repeats P_{k-p} (as insert_knot does).
        R.assign(P.begin() + (k - p) * m, P.begin() + (k - p + 1) * m);
        P.insert(P.begin() + (k - p + 1) * m, std::make_move_iterator(R.begin()), std::make_move_iterator(R.end()));
      } else {
        // New points Q_{k-p+1..k-s} from P_{k-p..k-s}; the points from P_{k-s} on move up by one.
        R.assign(P.begin() + (k - p) * m, P.begin() + (k - s + 1) * m);
        const std::size_t L = k - p + 1;
        for (int i = 0; i <= p - 1 - s; ++i) {
          const T alpha = (x - U[L + i]) / (U[i + k + 1] - U[L + i]);
          T* a = R.data() + i * m;
          const T* b = R.data() + (i + 1) * m;
          for (std::size_t c = 0; c < m; ++c) a[c] += alpha * (b[c] - a[c]);
        }
        P.insert(P.begin() + (k - s) * m, m, T(0));
        std::move(R.begin(), R.begin() + (p - s) * m, P.begin() + L * m);
      }
      U.insert(U.begin() + k + 1, x);
    }
    return out;
  });
}

template <class T>
BSpline<T> refine_knots(const BSpline<T>& S, int d, std::vector<T> X, const Limits& limits) {
  detail::check_direction(S, d);
  std::sort(X.begin(), X.end(), [](const T& a, const T& b) { return a < b; });
  detail::check_insertable_sorted(S, d, X);
  limits.check_count(S.size() / S.count(d) * (S.count(d) + X.size()), "knots");
  return apply_along(S, d, [&](int p, const std::vector<T>& U, const T* P, std::size_t n, std::size_t m) {
    return detail::refine_knot_vect_curve(p, U, P, n, m, X);
  });
}

template <class T>
BSpline<T> clamp(const BSpline<T>& S, int d, const Limits& limits) {
  detail::check_direction(S, d);
  const int p = S.degrees[d];
  if (is_clamped(S.knots[d], p, S.count(d))) return S;
  const T lo = S.domain_lo(d), hi = S.domain_hi(d);
  /// Raise the multiplicity of both domain ends to p+1 by Boehm insertion, then cut.
  BSpline<T> R = S;
  for (const T& e : {lo, hi}) {
    /// Multiplicity counted inside the domain end's own run (knots outside the domain may repeat it).
    std::size_t mult = multiplicity(R.knots[d], e);
    if (mult < static_cast<std::size_t>(p) + 1) R = insert_knot(R, d, e, static_cast<int>(p + 1 - mult), limits);
  }
  const auto& U = R.knots[d];
  std::size_t first = 0;
  while (U[first] < lo) ++first;  // first index of lo's run
  std::size_t last = U.size() - 1;
  while (hi < U[last]) --last;     // last index of hi's run
  const std::size_t n_new = (last - first + 1) - p - 1;
  return slice_direction(R, d, first, n_new, std::vector<T>(U.begin() + first, U.begin() + last + 1));
}

template <class T>
BSpline<T> clamp_all(const BSpline<T>& S, const Limits& limits) {
  BSpline<T> R = S;
  for (int d = 0; d < S.dim(); ++d) R = clamp(R, d, limits);
  return R;
}

}  // namespace splinex
