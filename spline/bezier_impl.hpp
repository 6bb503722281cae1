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
  const BSpline<T>& C = S;
  const int p = C.degrees[d];
  const std::vector<T> bp = breakpoints(C.knots[d], p, C.count(d));
  std::vector<T> X;
  for (std::size_t i = 1; i + 1 < bp.size(); ++i) {
    const std::size_t mult = multiplicity(C.knots[d], bp[i]);
    for (std::size_t r = mult; r < static_cast<std::size_t>(p); ++r) X.push_back(bp[i]);
  }
  return refine_knots(C, d, X, limits);
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
std::vector<BezierPiece<T>> extract_bezier(const BSpline<T>& S, const Limits& limits) {
  // The whole result's size is known from the breakpoints: checked before any work (a surface
  // would otherwise convert direction 0 in full before direction 1 reaches the limit). It bounds
  // the Bezier form of every direction too.
  bezier_pieces_size(S, limits);
  /// Fully Bezier form in every direction first, then cut piece by piece.
  /// (Each direction is converted from the previous result; the input is never copied whole.)
  BSpline<T> B = detail::to_bezier_form(S, 0, limits);
  for (int d = 1; d < S.dim(); ++d) B = detail::to_bezier_form(B, d, limits);
  const std::vector<int> degrees = B.degrees;
  const std::vector<std::vector<T>> knots_all = B.knots;
  std::vector<std::size_t> counts(S.dim());
  for (int d = 0; d < S.dim(); ++d) counts[d] = B.count(d);
  std::vector<BezierPiece<T>> pieces;
  pieces.push_back(BezierPiece<T>{{}, std::move(B)});
  for (int d = 0; d < S.dim(); ++d) {
    const int p = degrees[d];
    const std::vector<T> bp = breakpoints(knots_all[d], p, counts[d]);
    std::vector<BezierPiece<T>> next;
    /// Direction-0-fastest ordering: later directions form the outer loop. The piece on
    /// [bp[seg], bp[seg+1]) is carried by the p+1 control points before the end of its knot span s
    /// (U[s] <= bp[seg] < U[s+1]): points s-p..s. Counting from seg*p would assume every interior
    /// breakpoint has multiplicity exactly p; a C^-1 knot (multiplicity p+1) or degree 0 breaks it.
    const std::size_t n = counts[d];
    for (std::size_t seg = 0; seg + 1 < bp.size(); ++seg) {
      const std::size_t first = find_span(knots_all[d], p, n, bp[seg]) - static_cast<std::size_t>(p);
      for (const auto& piece : pieces) {
        std::vector<T> knots(p + 1, bp[seg]);
        knots.insert(knots.end(), p + 1, bp[seg + 1]);
        BezierPiece<T> np{piece.box, slice_direction(piece.spline, d, first, p + 1, std::move(knots))};
        np.box.emplace_back(bp[seg], bp[seg + 1]);
        next.push_back(std::move(np));
      }
    }
    pieces = std::move(next);
  }
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
