#pragma once
#include <string>

#include "spline/bezier.hpp"
#include "spline/insert_impl.hpp"

namespace splinex {
namespace detail {

/// Raises every interior breakpoint of direction d to multiplicity p (clamped first).
template <class T>
BSpline<T> to_bezier_form(const BSpline<T>& S, int d, const Limits& limits) {
  /// A clamped direction is refined from the input itself (clamp would return a copy).
  if (!is_clamped(S.knots[d], S.degrees[d], S.count(d))) return to_bezier_form(clamp(S, d, limits), d, limits);
  const int p = S.degrees[d];
  const std::vector<T>& U = S.knots[d];
  const std::size_t n = S.count(d);
  /// One walk over the interior runs U[p+1 .. n-1] (the domain ends are runs of p+1).
  std::vector<T> X;
  for (std::size_t i = static_cast<std::size_t>(p) + 1; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && U[j + 1] == U[i]) ++j;
    for (std::size_t r = j - i + 1; r < static_cast<std::size_t>(p); ++r) X.push_back(U[i]);
    i = j + 1;
  }
  if (X.empty()) return S;
  return refine_knots(S, d, std::move(X), limits);
}

/// Index (into the points of direction d) of the first control point of every segment of a
/// clamped knot vector: the piece on [bp[s], bp[s+1]) is carried by points span-p..span with
/// U[span] <= bp[s] < U[span+1]. Counting from s*p would assume every interior breakpoint has
/// multiplicity exactly p; a C^-1 knot (multiplicity p+1) or degree 0 breaks it.
template <class T>
std::vector<std::size_t> segment_starts(const std::vector<T>& U, int p, std::size_t n, const std::vector<T>& bp) {
  std::vector<std::size_t> out;
  out.reserve(bp.size() - 1);
  std::size_t span = static_cast<std::size_t>(p);
  for (std::size_t s = 0; s + 1 < bp.size(); ++s) {
    while (span + 1 < n && !(bp[s] < U[span + 1])) ++span;
    out.push_back(span - static_cast<std::size_t>(p));
  }
  return out;
}

}  // namespace detail

template <class T>
std::size_t bezier_pieces_size(const BSpline<T>& S, const Limits& limits) {
  std::size_t total = 1;
  for (int d = 0; d < S.dim(); ++d) {
    const std::size_t segs = breakpoints(S.knots[d], S.degrees[d], S.count(d)).size() - 1;
    total = checked_product(total, checked_product(segs, static_cast<std::size_t>(S.degrees[d]) + 1, limits, "pieces"),
                            limits, "pieces");
  }
  return total;
}

template <class T>
BezierForm<T> bezier_form(const BSpline<T>& S, const Limits& limits) {
  // The whole result's size is known from the breakpoints: checked before any work (a surface
  // would otherwise convert direction 0 in full before direction 1 reaches the limit). It bounds
  // the Bezier form of every direction too.
  bezier_pieces_size(S, limits);
  /// Each direction is converted from the previous result; the input is never copied whole.
  BezierForm<T> F;
  F.spline = detail::to_bezier_form(S, 0, limits);
  for (int d = 1; d < S.dim(); ++d) F.spline = detail::to_bezier_form(F.spline, d, limits);
  for (int d = 0; d < S.dim(); ++d) {
    const BSpline<T>& B = F.spline;
    F.breaks.push_back(breakpoints(B.knots[d], B.degrees[d], B.count(d)));
    F.first.push_back(detail::segment_starts(B.knots[d], B.degrees[d], B.count(d), F.breaks.back()));
  }
  return F;
}

template <class T>
std::size_t BezierForm<T>::size() const {
  std::size_t k = 1;
  for (const auto& f : first) k *= f.size();
  return k;
}

template <class T>
BezierPiece<T> BezierForm<T>::piece(std::size_t k) const {
  const int dim = spline.dim();
  BezierPiece<T> out;
  out.box.reserve(static_cast<std::size_t>(dim));
  BSpline<T>& R = out.spline;
  R.degrees = spline.degrees;
  R.q = spline.q;
  R.knots.resize(static_cast<std::size_t>(dim));
  /// The piece's multi-index (direction 0 fastest) and the offset of its first control point.
  std::size_t rest = k, offset = 0, stride = 1, local = 1;
  std::vector<std::size_t> strides(static_cast<std::size_t>(dim));
  for (int d = 0; d < dim; ++d) {
    const std::size_t segs = first[d].size(), s = rest % segs;
    rest /= segs;
    const int p = spline.degrees[d];
    out.box.emplace_back(breaks[d][s], breaks[d][s + 1]);
    R.knots[d].reserve(2 * static_cast<std::size_t>(p + 1));
    R.knots[d].insert(R.knots[d].end(), static_cast<std::size_t>(p + 1), breaks[d][s]);
    R.knots[d].insert(R.knots[d].end(), static_cast<std::size_t>(p + 1), breaks[d][s + 1]);
    strides[d] = stride;
    offset += first[d][s] * stride;
    stride *= spline.count(d);
    local *= static_cast<std::size_t>(p + 1);
  }
  /// Gather the local net: rows of direction 0 are contiguous in the spline's storage.
  const std::size_t row = static_cast<std::size_t>(spline.degrees[0] + 1), rows = local / row;
  auto gather = [&](const std::vector<T>& V, std::size_t width, std::vector<T>& W) {
    W.reserve(local * width);
    for (std::size_t r = 0; r < rows; ++r) {
      std::size_t at = offset, rr = r;
      for (int d = 1; d < dim; ++d) {
        const std::size_t m = static_cast<std::size_t>(spline.degrees[d] + 1);
        at += (rr % m) * strides[d];
        rr /= m;
      }
      const T* src = V.data() + at * width;
      W.insert(W.end(), src, src + row * width);
    }
  };
  gather(spline.points, spline.q, R.points);
  if (spline.is_rational()) gather(spline.weights, 1, R.weights);
  return out;
}

template <class T>
std::vector<BezierPiece<T>> extract_bezier(const BSpline<T>& S, const Limits& limits) {
  const BezierForm<T> F = bezier_form(S, limits);
  std::vector<BezierPiece<T>> pieces;
  const std::size_t k = F.size();
  pieces.reserve(k);
  for (std::size_t i = 0; i < k; ++i) pieces.push_back(F.piece(i));
  return pieces;
}

template <class T>
std::pair<BSpline<T>, BSpline<T>> split_at(const BSpline<T>& S, int d, const T& x, const Limits& limits) {
  detail::check_direction(S, d);
  if (!(S.domain_lo(d) < x && x < S.domain_hi(d)))
    throw DomainError("at", "split parameter is not strictly inside the domain of direction " + std::to_string(d),
                      "split at a parameter in the open domain (U[p], U[n])");
  BSpline<T> C = clamp(S, d, limits);
  const int p = C.degrees[d];
  const std::size_t mult = multiplicity(C.knots[d], x);
  if (mult < static_cast<std::size_t>(p) + 1) C = insert_knot(C, d, x, static_cast<int>(p + 1 - mult), limits);
  const auto& U = C.knots[d];
  std::size_t s = 0;  // first index of x's run (now of length p+1)
  while (U[s] < x) ++s;
  std::vector<T> left(U.begin(), U.begin() + s + p + 1), right(U.begin() + s, U.end());
  const std::size_t n = C.count(d);
  return {slice_direction(C, d, 0, s, std::move(left)), slice_direction(C, d, s, n - s, std::move(right))};
}

template <class T>
BSpline<T> reparametrize(const BSpline<T>& S, int d, const T& lo, const T& hi) {
  detail::check_direction(S, d);
  if (!(lo < hi)) throw DomainError("interval", "is empty or reversed", "give lo < hi (use reverse to flip)");
  const T a = S.domain_lo(d), b = S.domain_hi(d);
  const T scale = (hi - lo) / (b - a);
  BSpline<T> R = S;
  // Knots equal to a domain end map to the new end exactly, so that a rounding arithmetic keeps
  // the domain [lo, hi] and the end multiplicities.
  for (auto& u : R.knots[d]) u = (u == a) ? lo : (u == b) ? hi : lo + (u - a) * scale;
  return R;
}

template <class T>
BSpline<T> reverse(const BSpline<T>& S, int d) {
  detail::check_direction(S, d);
  const T c = S.domain_lo(d) + S.domain_hi(d);
  const std::vector<T>& U = S.knots[d];
  BSpline<T> R = S;
  const T a = S.domain_lo(d), b = S.domain_hi(d);
  // Domain ends map to each other exactly (a rounding arithmetic would otherwise move them).
  for (std::size_t i = 0; i < U.size(); ++i) {
    const T& u = U[U.size() - 1 - i];
    R.knots[d][i] = (u == a) ? b : (u == b) ? a : c - u;
  }
  /// Plain copies: a lambda may not capture structured bindings in C++17 (clang refuses it).
  const auto layout = fibre_layout(S, d);
  const std::size_t before = layout.before, n = layout.n, after = layout.after;
  auto flip = [&](const std::vector<T>& V, std::size_t width, std::vector<T>& W) {
    for (std::size_t b = 0; b < after; ++b)
      for (std::size_t i = 0; i < n; ++i) {
        const T* src = V.data() + ((b * n + (n - 1 - i)) * before) * width;
        std::copy(src, src + before * width, W.data() + ((b * n + i) * before) * width);
      }
  };
  flip(S.points, S.q, R.points);
  if (S.is_rational()) flip(S.weights, 1, R.weights);
  return R;
}

}  // namespace splinex
