// Output-sensitive interval joins for the sweeps of untrimming: instead of testing every pair of
// edges, pieces or samples (quadratic in the loop size), sort by the left end and keep an active
// list, so the work is O((n + m) log(n + m) + k) for k reported pairs.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace splinex {

/// f(i, j) for every A[i], B[j] whose closed ranges [lo, hi] intersect (lo <= hi each).
template <class R, class F>
void for_overlapping_pairs(const std::vector<std::pair<R, R>>& A, const std::vector<std::pair<R, R>>& B, F&& f) {
  std::vector<std::size_t> ia(A.size()), ib(B.size());
  std::iota(ia.begin(), ia.end(), 0);
  std::iota(ib.begin(), ib.end(), 0);
  std::sort(ia.begin(), ia.end(), [&](std::size_t x, std::size_t y) { return A[x].first < A[y].first; });
  std::sort(ib.begin(), ib.end(), [&](std::size_t x, std::size_t y) { return B[x].first < B[y].first; });
  std::vector<std::size_t> active_a, active_b;
  /// Drops the intervals ending before x; the rest all contain x (their left ends are <= x).
  const auto prune = [](std::vector<std::size_t>& act, const std::vector<std::pair<R, R>>& V, const R& x) {
    act.erase(std::remove_if(act.begin(), act.end(), [&](std::size_t k) { return V[k].second < x; }), act.end());
  };
  std::size_t a = 0, b = 0;
  while (a < ia.size() || b < ib.size()) {
    const bool take_a = b == ib.size() || (a < ia.size() && !(B[ib[b]].first < A[ia[a]].first));
    if (take_a) {
      const std::size_t i = ia[a++];
      prune(active_b, B, A[i].first);
      for (std::size_t j : active_b) f(i, j);
      active_a.push_back(i);
    } else {
      const std::size_t j = ib[b++];
      prune(active_a, A, B[j].first);
      for (std::size_t i : active_a) f(i, j);
      active_b.push_back(j);
    }
  }
}

/// f(i, j), i != j, once per unordered pair of V whose closed ranges intersect.
template <class R, class F>
void for_overlapping_pairs(const std::vector<std::pair<R, R>>& V, F&& f) {
  std::vector<std::size_t> iv(V.size());
  std::iota(iv.begin(), iv.end(), 0);
  std::sort(iv.begin(), iv.end(), [&](std::size_t x, std::size_t y) { return V[x].first < V[y].first; });
  std::vector<std::size_t> active;
  for (std::size_t i : iv) {
    const R& x = V[i].first;
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t k) { return V[k].second < x; }), active.end());
    for (std::size_t j : active) f(j, i);
    active.push_back(i);
  }
}

/// The number of unordered pairs of V whose closed ranges intersect, counted up to `cap` (the count
/// stops there): O(n log n), so a caller can choose an algorithm before enumerating the pairs.
template <class R>
std::size_t count_overlapping_pairs(const std::vector<std::pair<R, R>>& V, std::size_t cap) {
  std::vector<std::size_t> iv(V.size());
  std::iota(iv.begin(), iv.end(), 0);
  std::sort(iv.begin(), iv.end(), [&](std::size_t x, std::size_t y) { return V[x].first < V[y].first; });
  std::size_t count = 0;
  for (std::size_t k = 0; k < iv.size() && count < cap; ++k) {
    /// Every later interval whose left end is <= this one's right end meets it.
    const auto end = std::upper_bound(iv.begin() + static_cast<std::ptrdiff_t>(k) + 1, iv.end(), V[iv[k]].second,
                                      [&](const R& x, std::size_t j) { return x < V[j].first; });
    count += static_cast<std::size_t>(end - (iv.begin() + static_cast<std::ptrdiff_t>(k) + 1));
  }
  return std::min(count, cap);
}

/// The first pair of loop edges (l, m, i, j) with (l, i) < (m, j) for which meets(l, i, m, j) holds,
/// among the edges whose x-ranges x[k] meet; id[k] = (loop, edge). First: the least loop m that
/// meets an earlier loop, then the least such l, then the least edge j of m, then i of l (the order
/// untrim/polygon.hpp's first_meeting_loops finds loops in, for inputs too large for this join).
template <class R, class Meets>
std::optional<std::array<std::size_t, 4>> first_meeting_edges(const std::vector<std::pair<R, R>>& x,
                                                              const std::vector<std::pair<std::size_t, std::size_t>>& id,
                                                              Meets&& meets) {
  std::optional<std::array<std::size_t, 4>> first;
  for_overlapping_pairs(x, [&](std::size_t u, std::size_t v) {
    auto [l, i] = id[u];
    auto [m, j] = id[v];
    if (std::make_pair(m, j) < std::make_pair(l, i)) {
      std::swap(l, m);
      std::swap(i, j);
    }
    const std::array<std::size_t, 4> found{l, m, i, j};
    const auto key = [](const std::array<std::size_t, 4>& f) { return std::array<std::size_t, 4>{f[1], f[0], f[3], f[2]}; };
    if ((!first || key(found) < key(*first)) && meets(l, i, m, j)) first = found;
  });
  return first;
}

}  // namespace splinex
