// Components of a set of parameter boxes (internal to vrep/): the union-find, closed boxes that
// touch, and the identifications of a trivariate's own domain (a face collapsed to a curve or a
// point, a face equal to another face: seams). Used for the certified lower bounds on components
// of trimmed cells (freeform.hpp, trimmed.hpp's topology): components of a cover that each hold a
// certified point are distinct components of the true set, provided the only points of the
// domain the trivariate maps together are those identified here.
#pragma once
#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

#include "base/limits.hpp"
#include "spline/bspline.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex::vrep_detail {

struct UnionFind {
  std::vector<std::size_t> p;
  explicit UnionFind(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), std::size_t(0)); }
  std::size_t find(std::size_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { p[find(a)] = find(b); }
};

/// The pairs of closed boxes among `ids` (lo, hi in N parameters) that have a common point.
template <class T, std::size_t N>
std::vector<std::pair<std::size_t, std::size_t>> touching_pairs(const std::vector<std::array<T, N>>& lo, const std::vector<std::array<T, N>>& hi,
                                                                std::vector<std::size_t> ids) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::sort(ids.begin(), ids.end(), [&](std::size_t a, std::size_t b) { return lo[a][0] < lo[b][0]; });
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size() && !(hi[ids[i]][0] < lo[ids[j]][0]); ++j) {
      const std::size_t a = ids[i], b = ids[j];
      bool meet = true;
      for (std::size_t d = 1; d < N && meet; ++d) meet = !(hi[a][d] < lo[b][d] || hi[b][d] < lo[a][d]);
      if (meet) out.push_back({a, b});
    }
  return out;
}

/// Numbers the pieces of resolved boxes (members lo, hi, pieces, first) consecutively: each box's
/// `first`, its corners in lo/hi and all of them in ids; returns the number of pieces.
template <class Box, class T, std::size_t N>
std::size_t number_pieces(std::vector<Box>& boxes, std::vector<std::array<T, N>>& lo, std::vector<std::array<T, N>>& hi, std::vector<std::size_t>& ids) {
  std::size_t total = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    boxes[i].first = total;
    total += static_cast<std::size_t>(boxes[i].pieces);
    lo.push_back(boxes[i].lo);
    hi.push_back(boxes[i].hi);
    ids.push_back(i);
  }
  return total;
}

/// Joins the closed boxes among `ids` that have a common point.
template <class T, std::size_t N>
void join_touching(const std::vector<std::array<T, N>>& lo, const std::vector<std::array<T, N>>& hi, std::vector<std::size_t> ids,
                   UnionFind& uf) {
  for (const auto& [a, b] : touching_pairs(lo, hi, std::move(ids))) uf.join(a, b);
}

/// A surface collapses along its direction `a` (0 or 1) when every line of its net along a holds
/// one point (its points then depend on the other direction only).
template <class T>
bool collapsed(const BSpline<T>& F, int a) {
  const std::size_t n0 = F.count(0), n1 = F.count(1), q = static_cast<std::size_t>(F.q);
  for (std::size_t j = 0; j < (a == 0 ? n1 : n0); ++j)
    for (std::size_t i = 1; i < (a == 0 ? n0 : n1); ++i) {
      const std::size_t x = a == 0 ? i + n0 * j : j + n0 * i, y = a == 0 ? n0 * j : j;
      for (int k = 0; k < 3; ++k)
        if (!(F.points[x * q + k] == F.points[y * q + k])) return false;
    }
  return true;
}

/// A curve whose control points (geometry) are all one point: an edge collapsed to a point.
template <class T>
bool curve_collapsed(const BSpline<T>& C) {
  for (std::size_t i = 1; i < C.count(0); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(C.points[i * static_cast<std::size_t>(C.q) + static_cast<std::size_t>(k)] == C.points[static_cast<std::size_t>(k)])) return false;
  return true;
}

/// The four corner points of a surface's net (geometry), sorted: equal surfaces have equal sets.
template <class T>
std::vector<std::array<T, 3>> corner_set(const BSpline<T>& F) {
  const std::size_t n0 = F.count(0), n1 = F.count(1), q = static_cast<std::size_t>(F.q);
  std::vector<std::array<T, 3>> c;
  for (std::size_t idx : {std::size_t(0), n0 - 1, n0 * (n1 - 1), n0 * n1 - 1}) c.push_back({F.points[idx * q], F.points[idx * q + 1], F.points[idx * q + 2]});
  std::sort(c.begin(), c.end());
  return c;
}

/// Joins the boxes (in V's parameters, among `ids`) that V's own identifications put together: a
/// face collapsed along one of its directions joins the boxes meeting it over a common interval of
/// the other; a face collapsed to a point, or equal to another face of V, joins all boxes meeting
/// it (and the other face): more than needed, so lower bounds stay sound.
template <class T>
void join_identified(const BSpline<T>& V, const std::vector<std::array<T, 3>>& lo, const std::vector<std::array<T, 3>>& hi,
                     const std::vector<std::size_t>& ids, UnionFind& uf, const Limits& limits) {
  std::array<std::array<BSpline<T>, 2>, 3> faces;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) faces[d][s] = face(V, d, s);
  auto touching_face = [&](int d, int s) {
    std::vector<std::size_t> t;
    const T at = s ? V.domain_hi(d) : V.domain_lo(d);
    for (std::size_t i : ids)
      if ((s ? hi[i][d] : lo[i][d]) == at) t.push_back(i);
    return t;
  };
  auto join_all = [&](const std::vector<std::size_t>& t) {
    for (std::size_t i = 1; i < t.size(); ++i) uf.join(t[0], t[i]);
  };
  const std::size_t n = lo.size();
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;  // the face's directions in V
      const bool along0 = collapsed(faces[d][s], 0), along1 = collapsed(faces[d][s], 1);
      const auto t = touching_face(d, s);
      if (along0 && along1) join_all(t);
      else if (along0 || along1) {
        const int kept = along0 ? b : a;
        std::vector<std::array<T, 1>> l1(n), h1(n);
        for (std::size_t i : t) {
          l1[i] = {lo[i][kept]};
          h1[i] = {hi[i][kept]};
        }
        join_touching(l1, h1, t, uf);
      }
      for (int d2 = d; d2 < 3; ++d2)
        for (int s2 = 0; s2 < 2; ++s2) {
          if (d2 == d && s2 <= s) continue;
          if (corner_set(faces[d][s]) != corner_set(faces[d2][s2])) continue;
          if (!same_surface(faces[d][s], faces[d2][s2], T(0), limits)) continue;
          auto both = t;
          const auto t2 = touching_face(d2, s2);
          both.insert(both.end(), t2.begin(), t2.end());
          join_all(both);
        }
    }
}

/// An edge of a trimmed cell cut at events (enclosures [lo, hi] of the parameters where a trimming
/// surface crosses it, possibly overlapping): the runs of the edge [a, b] inside the cell and their
/// ends strictly inside the edge. `truth_at(t)` is the cell's truth at a parameter between events
/// (in / out; mixed makes the answer undecided). An empty gap at an end of the edge is a crossing
/// at the corner, not a V-point of the edge.
template <class T>
struct EdgeRuns {
  bool decided = true;
  std::size_t pieces = 0, points = 0;
  std::vector<std::pair<T, T>> cuts;
};
template <class T, class TruthAt>
EdgeRuns<T> edge_runs(std::vector<std::pair<T, T>> events, const T& a, const T& b, TruthAt&& truth_at) {
  std::sort(events.begin(), events.end());
  std::vector<std::pair<T, T>> merged;  // overlapping enclosures joined
  for (const auto& ev : events) {
    if (!merged.empty() && !(merged.back().second < ev.first)) merged.back().second = std::max(merged.back().second, ev.second);
    else merged.push_back(ev);
  }
  struct Gap {
    int truth;   // 0 out, 1 mixed, 2 in
    long after;  // the event before it (-1: the edge's start)
  };
  std::vector<Gap> gaps;
  T from = a;
  for (std::size_t i = 0; i <= merged.size(); ++i) {
    const T to = i < merged.size() ? merged[i].first : b;
    if (from < to) gaps.push_back({truth_at((from + to) / T(2)), static_cast<long>(i) - 1});
    if (i < merged.size()) from = merged[i].second;
  }
  EdgeRuns<T> r;
  bool inside = false;
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    if (gaps[i].truth == 1) {
      r.decided = false;
      break;
    }
    const bool in = gaps[i].truth == 2;
    if (in && !inside) ++r.pieces;
    if (i > 0 && in != inside) {
      ++r.points;
      r.cuts.push_back(merged[static_cast<std::size_t>(gaps[i].after)]);
    }
    inside = in;
  }
  if (!r.decided) r = EdgeRuns<T>{false, 0, 0, {}};
  return r;
}

}  // namespace splinex::vrep_detail
