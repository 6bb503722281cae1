#pragma once
#include <algorithm>
#include <string>

#include "spline/arith.hpp"
#include "compose/affine.hpp"
#include "compose/compose_impl.hpp"
#include "compose/trimmed_compose.hpp"

namespace splinex {
namespace detail {

template <class T>
struct Candidate {
  std::vector<CellCondition<T>> conds;
};

/// Whether some point of the piece maps into the conditions: first exact samples, then a proof
/// of emptiness by subdivision (a sub-piece whose hull misses a condition's interval holds no
/// such point). Returns 1 non-empty (a point found), 0 empty (proved), -1 undecided.
template <class T>
int region_nonempty(const BSpline<T>& piece, const std::vector<CellCondition<T>>& conds, int depth, const Limits& limits) {
  const int k = piece.dim();
  /// Samples: 9 per direction including the corners.
  const int G = 9;
  std::vector<int> idx(k, 0);
  std::vector<T> r(k);
  while (true) {
    for (int l = 0; l < k; ++l)
      r[l] = piece.domain_lo(l) + (piece.domain_hi(l) - piece.domain_lo(l)) * T(idx[l]) / T(G - 1);
    const auto s = evaluate(piece, r);
    bool in = true;
    for (const auto& c : conds) in = in && c.holds(s[c.coord]);
    if (in) return 1;
    int l = 0;
    while (l < k && ++idx[l] == G) { idx[l] = 0; ++l; }
    if (l == k) break;
  }
  /// Subdivision: every sub-piece's hull must miss some condition.
  std::vector<BSpline<T>> work{piece};
  for (int level = 0; level <= depth && !work.empty(); ++level) {
    std::vector<BSpline<T>> next;
    for (const auto& sub : work) {
      bool misses = false;
      for (const auto& c : conds) {
        const auto [lo, hi] = hull_range(sub, c.coord);
        if ((c.check_lo && hi < c.lo) || (c.check_hi && (c.hi_closed ? c.hi < lo : !(lo < c.hi)))) { misses = true; break; }
      }
      if (misses) continue;
      if (level == depth) return -1;
      /// Split in every direction at the middle.
      std::vector<BSpline<T>> parts{sub};
      for (int l = 0; l < k; ++l) {
        std::vector<BSpline<T>> halves;
        for (const auto& pp : parts) {
          const T mid = (pp.domain_lo(l) + pp.domain_hi(l)) / T(2);
          auto [a, b] = split_at(pp, l, mid, limits);
          halves.push_back(std::move(a));
          halves.push_back(std::move(b));
        }
        parts = std::move(halves);
      }
      for (auto& pp : parts) next.push_back(std::move(pp));
    }
    work = std::move(next);
  }
  return 0;
}

}  // namespace detail

template <class T>
std::size_t TrimmedComposition<T>::locate_piece(const std::vector<T>& r) const {
  if (r.size() != static_cast<std::size_t>(inner.dim()))
    throw DomainError("at", "needs " + std::to_string(inner.dim()) + " parameters", "give one per direction of S");
  for (std::size_t i = 0; i < inner_pieces.size(); ++i) {
    bool in = true;
    for (int l = 0; l < inner.dim() && in; ++l) {
      const auto& [lo, hi] = inner_pieces[i].box[l];
      const bool closed = hi == inner.domain_hi(l);
      in = !(r[l] < lo) && (closed ? !(hi < r[l]) : r[l] < hi);
    }
    if (in) return i;
  }
  throw DomainError("at", "lies outside the inner spline's domain", "give a parameter in the domain of S");
}

template <class T>
std::size_t TrimmedComposition<T>::locate_cell(const std::vector<T>& u) const {
  std::size_t cell = 0, stride = 1;
  for (std::size_t j = 0; j < outer_breaks.size(); ++j) {
    const auto& bp = outer_breaks[j];
    if (u[j] < bp.front() || bp.back() < u[j])
      throw DomainError("inner", "S(r) leaves the outer domain in coordinate " + std::to_string(j),
                        "keep the inner spline inside the outer spline's domain");
    cell += detail::cell_index(bp, u[j]) * stride;
    stride *= bp.size() - 1;
  }
  return cell;
}

template <class T>
std::size_t TrimmedComposition<T>::locate(const std::vector<T>& r) const {
  const std::size_t i = locate_piece(r);
  const std::size_t c = locate_cell(splinex::evaluate(inner_pieces[i].spline, r));
  const auto it = index.find({i, c});
  if (it == index.end())
    throw std::logic_error("trimmed composition: a point lands in a region proved empty (inner piece " + std::to_string(i) +
                           ", cell " + std::to_string(c) + ")");
  return it->second;
}

template <class T>
std::vector<T> evaluate_patch(const TrimmedPatch<T>& p, const std::vector<T>& r) {
  std::vector<T> h = splinex::evaluate(p.patch.net, r);
  return p.patch.weighted ? divide_by_weight(h) : h;
}

template <class T>
std::vector<T> TrimmedComposition<T>::evaluate(const std::vector<T>& r) const {
  return evaluate_patch(patches[locate(r)], r);
}

template <class T>
bool TrimmedComposition<T>::in_region(const TrimmedPatch<T>& p, const std::vector<T>& r) const {
  const auto s = splinex::evaluate(inner_pieces[p.inner_piece].spline, r);
  for (const auto& c : p.region)
    if (!c.holds(s[c.coord])) return false;
  return true;
}

template <class T>
TrimmedComposition<T> compose_trimmed(const BSpline<T>& outer, const BSpline<T>& inner, const TrimmedOptions& options,
                                      const Limits& limits) {
  detail::check_composable(outer, inner);
  TrimmedComposition<T> R;
  R.outer = outer;
  R.inner = inner;
  R.outer_pieces = extract_bezier(outer, limits);
  const int n = outer.dim(), k = inner.dim();
  for (int j = 0; j < n; ++j) R.outer_breaks.push_back(breakpoints(outer.knots[j], outer.degrees[j], outer.count(j)));
  /// Inner pieces, split where a coordinate is affine in one parameter and meets a knot of T.
  std::vector<BezierPiece<T>> todo = extract_bezier(inner, limits);
  while (!todo.empty()) {
    BezierPiece<T> pc = std::move(todo.back());
    todo.pop_back();
    bool split = false;
    for (int c = 0; c < n && !split; ++c)
      for (int l = 0; l < k && !split; ++l) {
        const auto form = affine_form(pc.spline, c);
        if (!form || !form->only_in(l)) continue;
        const BSpline<T>& P = pc.spline;
        /// s_c(r_l) runs affinely from a (r_l = lo) to b (r_l = hi).
        const T a = P.points[c], b = P.points[(P.size() - 1) * P.q + c];
        if (a == b) continue;
        for (const T& u : R.outer_breaks[c]) {
          if (!((a < u && u < b) || (b < u && u < a))) continue;
          const T lo = P.domain_lo(l), hi = P.domain_hi(l);
          const T x = lo + (u - a) * (hi - lo) / (b - a);
          if (!(lo < x && x < hi)) continue;
          auto [L, Rr] = split_at(P, l, x, limits);
          auto bl = pc.box, br = pc.box;
          bl[l].second = x;
          br[l].first = x;
          todo.push_back({bl, std::move(L)});
          todo.push_back({br, std::move(Rr)});
          ++R.isoparametric_splits;
          split = true;
          break;
        }
      }
    if (!split) R.inner_pieces.push_back(std::move(pc));
  }
  // Keep a deterministic order: by box, direction k-1 slowest.
  std::sort(R.inner_pieces.begin(), R.inner_pieces.end(), [k](const BezierPiece<T>& A, const BezierPiece<T>& B) {
    for (int l = k - 1; l >= 0; --l) {
      if (A.box[l].first < B.box[l].first) return true;
      if (B.box[l].first < A.box[l].first) return false;
    }
    return false;
  });
  std::vector<std::size_t> cstride(n);
  std::size_t st = 1;
  for (int j = 0; j < n; ++j) { cstride[j] = st; st *= R.outer_breaks[j].size() - 1; }
  for (std::size_t i = 0; i < R.inner_pieces.size(); ++i) {
    const BSpline<T>& P = R.inner_pieces[i].spline;
    /// Candidate cell ranges per coordinate from the exact hull.
    std::vector<std::pair<std::size_t, std::size_t>> range(n);
    std::vector<std::pair<T, T>> hull(n);
    for (int j = 0; j < n; ++j) {
      hull[j] = detail::hull_range(P, j);
      const auto& bp = R.outer_breaks[j];
      detail::check_hull_in_domain(hull[j], bp, j, "move the inner spline into the outer domain");
      range[j] = {detail::cell_index(bp, hull[j].first), detail::cell_index(bp, hull[j].second)};
    }
    std::vector<std::size_t> c(n);
    for (int j = 0; j < n; ++j) c[j] = range[j].first;
    while (true) {
      std::vector<CellCondition<T>> conds;
      std::size_t cell = 0;
      for (int j = 0; j < n; ++j) {
        const auto& bp = R.outer_breaks[j];
        CellCondition<T> cc;
        cc.coord = j;
        cc.lo = bp[c[j]];
        cc.hi = bp[c[j] + 1];
        cc.hi_closed = c[j] + 2 == bp.size();
        cc.check_lo = hull[j].first < cc.lo;
        cc.check_hi = cc.hi_closed ? cc.hi < hull[j].second : !(hull[j].second < cc.hi);
        if (cc.check_lo || cc.check_hi) conds.push_back(cc);
        cell += c[j] * cstride[j];
      }
      const int ne = conds.empty() ? 1 : detail::region_nonempty(P, conds, options.emptiness_depth, limits);
      if (ne != 0) {
        TrimmedPatch<T> patch;
        patch.inner_piece = i;
        patch.outer_cell = cell;
        patch.region = std::move(conds);
        patch.status = patch.region.empty() ? RegionStatus::untrimmed : ne == 1 ? RegionStatus::trimmed : RegionStatus::unproven_nonempty;
        patch.patch = compose_bezier_homogeneous(R.outer_pieces[cell].spline, P, options.method, limits);
        R.index[{i, cell}] = R.patches.size();
        R.patches.push_back(std::move(patch));
      }
      int j = 0;
      while (j < n && ++c[j] > range[j].second) { c[j] = range[j].first; ++j; }
      if (j == n) break;
    }
  }
  return R;
}

}  // namespace splinex
