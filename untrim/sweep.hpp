// Untrimming by a vertical line sweep (papers/000 Section 2.2 after [19]; papers/002 Section 5.1):
// a planar straight-line subdivision of a parameter box (box edges, trimming lines or trimming
// polylines) is cut into trapezoids by vertical lines through every vertex; trapezoids with the
// same label (the trimmed region they belong to) that continue each other across a vertical line
// (same interval there) are merged into one tile. A tile is a topological quad: vertical left and
// right sides (possibly degenerate, giving a triangle with a singular corner, as in the paper),
// a bottom and a top chain that are graphs over x. Its parametrization is the Boolean sum (Coons
// patch) of its four sides; with vertical sides that is the ruled surface
//     Q(x, l) = (x, y_b(x) + l (y_t(x) - y_b(x))),  x in [x_0, x_m], l in [0, 1],
// a degree (1, 1) B-spline with the chains' break points as knots in x. det dQ/d(x, l) = y_t - y_b
// >= 0, positive inside, so every tile is regular in its interior.
//
// Everything is comparisons and + - * / on the scalar T: exact for exact T (rational vertices in,
// rational tiles out, areas exact), and the same code runs in floating point.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <vector>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "spline/arith.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
struct Trapezoid {
  T x0, x1;                  // slab
  T yb0, yb1, yt0, yt1;      // bottom and top edge at x0 and x1
  std::size_t below, above;  // indices of the bounding segments
};

template <class T>
struct Tile {
  int label = -1;
  std::vector<T> x, yb, yt;  // samples at the slab boundaries, x increasing
  // Curved chains (untrim/curved.hpp). Empty: every chain piece is the straight segment between
  // the samples. Otherwise one entry per piece i (between x[i] and x[i+1]): the piece's Bernstein
  // ordinates over [x[i], x[i+1]] (first yb[i], last yb[i+1]; likewise top), degree >= 1, degrees
  // may differ between pieces and chains.
  std::vector<std::vector<T>> bottom, top;

  bool curved() const { return !bottom.empty(); }
  std::vector<T> bottom_piece(std::size_t i) const { return curved() ? bottom[i] : std::vector<T>{yb[i], yb[i + 1]}; }
  std::vector<T> top_piece(std::size_t i) const { return curved() ? top[i] : std::vector<T>{yt[i], yt[i + 1]}; }
  /// The sub-tile over [x[i], x[i+1]].
  Tile piece(std::size_t i) const {
    Tile p{label, {x[i], x[i + 1]}, {yb[i], yb[i + 1]}, {yt[i], yt[i + 1]}, {}, {}};
    if (curved()) {
      p.bottom = {bottom[i]};
      p.top = {top[i]};
    }
    return p;
  }
};

/// Bernstein ordinates of degree n raised to degree m >= n (exact for exact T).
template <class T>
std::vector<T> elevate_ordinates(const std::vector<T>& c, int m) {
  std::vector<T> a = c;
  for (int n = static_cast<int>(a.size()) - 1; n < m; ++n) {
    std::vector<T> b(n + 2);
    b[0] = a[0];
    b[n + 1] = a[n];
    for (int i = 1; i <= n; ++i) b[i] = (T(i) * a[i - 1] + T(n + 1 - i) * a[i]) / T(n + 1);
    a = std::move(b);
  }
  return a;
}

namespace detail {

template <class T>
T orient2(const Point2<T>& a, const Point2<T>& b, const Point2<T>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
template <class T>
int sgn(const T& v) {
  return T(0) < v ? 1 : (v < T(0) ? -1 : 0);
}
template <class T>
bool lex_less(const Point2<T>& p, const Point2<T>& q) {
  return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
}
/// p on the closed segment [a, b], given collinear.
template <class T>
bool within(const Point2<T>& a, const Point2<T>& b, const Point2<T>& p) {
  const auto mn = [](const T& u, const T& v) { return u < v ? u : v; };
  const auto mx = [](const T& u, const T& v) { return u < v ? v : u; };
  return !(p[0] < mn(a[0], b[0])) && !(mx(a[0], b[0]) < p[0]) && !(p[1] < mn(a[1], b[1])) && !(mx(a[1], b[1]) < p[1]);
}
/// y of the non-vertical segment s at x.
template <class T>
T y_at(const Segment2<T>& s, const T& x) {
  if (x == s.a[0]) return s.a[1];
  if (x == s.b[0]) return s.b[1];
  return s.a[1] + (s.b[1] - s.a[1]) * (x - s.a[0]) / (s.b[0] - s.a[0]);
}

}  // namespace detail

/// Splits the segments where they cross or touch, so that they meet only at end points; removes
/// zero-length and duplicate segments; orients each from its lexicographically smaller end.
template <class T>
std::vector<Segment2<T>> planar_subdivision(const std::vector<Segment2<T>>& in) {
  using detail::orient2;
  using detail::sgn;
  std::vector<Segment2<T>> segs;
  for (auto s : in) {
    if (s.a == s.b) continue;
    if (detail::lex_less(s.b, s.a)) std::swap(s.a, s.b);
    segs.push_back(s);
  }
  // Sort by x of the left end: only segments whose x-ranges overlap are compared.
  std::sort(segs.begin(), segs.end(), [](const Segment2<T>& p, const Segment2<T>& q) { return p.a[0] < q.a[0]; });
  std::vector<std::vector<Point2<T>>> cuts(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const auto& s = segs[i];
    for (std::size_t j = i + 1; j < segs.size() && !(s.b[0] < segs[j].a[0]); ++j) {
      const auto& t = segs[j];
      const int o1 = sgn(orient2(s.a, s.b, t.a)), o2 = sgn(orient2(s.a, s.b, t.b));
      const int o3 = sgn(orient2(t.a, t.b, s.a)), o4 = sgn(orient2(t.a, t.b, s.b));
      if (o1 == 0 && o2 == 0) {  // collinear: each cut at the other's ends inside it
        for (const auto& p : {t.a, t.b})
          if (detail::within(s.a, s.b, p)) cuts[i].push_back(p);
        for (const auto& p : {s.a, s.b})
          if (detail::within(t.a, t.b, p)) cuts[j].push_back(p);
        continue;
      }
      if (o1 * o2 > 0 || o3 * o4 > 0) continue;
      if (o1 == 0) { cuts[i].push_back(t.a); continue; }  // t touches s at t.a (o3 != o4 or touching)
      if (o2 == 0) { cuts[i].push_back(t.b); continue; }
      if (o3 == 0) { cuts[j].push_back(s.a); continue; }
      if (o4 == 0) { cuts[j].push_back(s.b); continue; }
      /// Proper crossing: s.a + u (s.b - s.a) with u = orient(t.a, t.b, s.a) / (that - orient(t.a, t.b, s.b)).
      const T d3 = orient2(t.a, t.b, s.a), d4 = orient2(t.a, t.b, s.b);
      const T u = d3 / (d3 - d4);
      const Point2<T> p{s.a[0] + (s.b[0] - s.a[0]) * u, s.a[1] + (s.b[1] - s.a[1]) * u};
      cuts[i].push_back(p);
      cuts[j].push_back(p);
    }
  }
  std::vector<Segment2<T>> out;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    auto pts = cuts[i];
    pts.push_back(segs[i].a);
    pts.push_back(segs[i].b);
    std::sort(pts.begin(), pts.end(), detail::lex_less<T>);
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) out.push_back({pts[k], pts[k + 1]});
  }
  std::sort(out.begin(), out.end(), [](const Segment2<T>& p, const Segment2<T>& q) {
    return detail::lex_less(p.a, q.a) || (p.a == q.a && detail::lex_less(p.b, q.b));
  });
  out.erase(std::unique(out.begin(), out.end(), [](const Segment2<T>& p, const Segment2<T>& q) { return p.a == q.a && p.b == q.b; }),
            out.end());
  return out;
}

/// The trapezoids between consecutive non-vertical segments in every slab between consecutive
/// vertex x values. The segments must meet only at end points (planar_subdivision).
template <class T>
std::vector<Trapezoid<T>> vertical_decomposition(const std::vector<Segment2<T>>& segs) {
  std::vector<T> xs;
  for (const auto& s : segs) {
    xs.push_back(s.a[0]);
    xs.push_back(s.b[0]);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<std::size_t> order;  // non-vertical segments by left x
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (!(segs[i].a[0] == segs[i].b[0])) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return segs[p].a[0] < segs[q].a[0]; });
  std::vector<Trapezoid<T>> out;
  std::vector<std::size_t> active;
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const T &x0 = xs[k], &x1 = xs[k + 1], mid = (x0 + x1) / T(2);
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t i) { return !(x0 < segs[i].b[0]); }),
                 active.end());
    while (next < order.size() && !(x0 < segs[order[next]].a[0])) {
      if (x0 < segs[order[next]].b[0]) active.push_back(order[next]);
      ++next;
    }
    // Segments span the whole slab (no vertex strictly inside), so their order at mid is their order.
    std::vector<std::pair<T, std::size_t>> at;
    for (std::size_t i : active) at.emplace_back(detail::y_at(segs[i], mid), i);
    std::sort(at.begin(), at.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    for (std::size_t m = 0; m + 1 < at.size(); ++m) {
      const auto &lo = segs[at[m].second], &hi = segs[at[m + 1].second];
      out.push_back({x0, x1, detail::y_at(lo, x0), detail::y_at(lo, x1), detail::y_at(hi, x0), detail::y_at(hi, x1),
                     at[m].second, at[m + 1].second});
    }
  }
  return out;
}

/// The open-tile bookkeeping of a left-to-right sweep, shared by the straight sweep
/// (merge_trapezoids) and the curved one (untrim/curved.cpp): a trapezoid whose left side
/// (x, y_bottom, y_top) and label are exactly the right side of an open tile continues that tile;
/// otherwise it starts a new one. Keys are ordered by comparisons only (the arithmetic concept).
template <class T>
class TileAssembler {
 public:
  /// The tile a trapezoid with this left side and label belongs to (a new one when `may_continue`
  /// is false, e.g. on a barrier, or when no open tile ends there). The caller appends the
  /// trapezoid's right samples to tiles()[t] and then calls close(t, ...).
  std::size_t open_at(int label, const T& x0, const T& yb0, const T& yt0, bool may_continue = true) {
    const auto it = may_continue ? open_.find(Key{x0, yb0, yt0, label}) : open_.end();
    if (it != open_.end()) {
      const std::size_t t = it->second;
      open_.erase(it);
      return t;
    }
    tiles_.push_back(Tile<T>{label, {x0}, {yb0}, {yt0}, {}, {}});
    return tiles_.size() - 1;
  }
  /// Tile t now ends at the right side (x1, yb1, yt1).
  void close(std::size_t t, const T& x1, const T& yb1, const T& yt1) {
    open_.emplace(Key{x1, yb1, yt1, tiles_[t].label}, t);
  }
  std::vector<Tile<T>>& tiles() { return tiles_; }

 private:
  struct Key {
    T x, yb, yt;
    int label;
    bool operator<(const Key& o) const {
      if (x < o.x) return true;
      if (o.x < x) return false;
      if (yb < o.yb) return true;
      if (o.yb < yb) return false;
      if (yt < o.yt) return true;
      if (o.yt < yt) return false;
      return label < o.label;
    }
  };
  std::vector<Tile<T>> tiles_;
  std::map<Key, std::size_t> open_;
};

/// Trapezoids (in sweep order) with labels merged into tiles: a trapezoid continues a tile of the
/// same label whose right side is exactly its left side, unless that side lies on one of the
/// vertical `barriers` (the knot lines x = k of a surface the tiles are composed into: a tile must
/// not cross them). Labels < 0 are dropped (outside).
template <class T>
std::vector<Tile<T>> merge_trapezoids(const std::vector<Trapezoid<T>>& traps, const std::vector<int>& labels,
                                      std::vector<T> barriers = {}) {
  const auto less = [](const T& a, const T& b) { return a < b; };
  std::sort(barriers.begin(), barriers.end(), less);
  const auto on_barrier = [&](const T& x) { return std::binary_search(barriers.begin(), barriers.end(), x, less); };
  TileAssembler<T> tiles;
  for (std::size_t i = 0; i < traps.size(); ++i) {
    if (labels[i] < 0) continue;
    const auto& z = traps[i];
    const std::size_t t = tiles.open_at(labels[i], z.x0, z.yb0, z.yt0, !on_barrier(z.x0));
    auto& tl = tiles.tiles()[t];
    /// Drop the previous sample when both chains run straight through it, decided exactly by
    /// orientation. Not in floating point: there a chain's sample y_at(s, x) is rounded off the
    /// segment s, and a tile that drops it no longer shares the boundary with its neighbour that
    /// keeps it (measured: a gap of 2.8e-23 at eps 1e-6; dropping samples where the same two segments
    /// continue instead left a gap of 8e-21 and an overlap of 2.9e-20). Keeping every slab sample makes
    /// adjacent float tiles share identical boundary points, so they partition the box exactly.
    const std::size_t m = tl.x.size();
    bool straight = false;
    if constexpr (ArithTraits<T>::exact)
      straight = m >= 2 &&
                 detail::sgn(detail::orient2(Point2<T>{tl.x[m - 2], tl.yb[m - 2]}, Point2<T>{tl.x[m - 1], tl.yb[m - 1]},
                                             Point2<T>{z.x1, z.yb1})) == 0 &&
                 detail::sgn(detail::orient2(Point2<T>{tl.x[m - 2], tl.yt[m - 2]}, Point2<T>{tl.x[m - 1], tl.yt[m - 1]},
                                             Point2<T>{z.x1, z.yt1})) == 0;
    if (straight) {
      tl.x.back() = z.x1;
      tl.yb.back() = z.yb1;
      tl.yt.back() = z.yt1;
    } else {
      tl.x.push_back(z.x1);
      tl.yb.push_back(z.yb1);
      tl.yt.push_back(z.yt1);
    }
    tiles.close(t, z.x1, z.yb1, z.yt1);
  }
  return std::move(tiles.tiles());
}

/// The tile with every number converted by conv (e.g. exact tiles rounded, or float tiles taken exactly).
template <class B, class A, class F>
Tile<B> convert_tile(const Tile<A>& t, F&& conv) {
  Tile<B> u;
  u.label = t.label;
  const auto all = [&](const std::vector<A>& v) {
    std::vector<B> w;
    for (const auto& a : v) w.push_back(conv(a));
    return w;
  };
  u.x = all(t.x);
  u.yb = all(t.yb);
  u.yt = all(t.yt);
  for (const auto& c : t.bottom) u.bottom.push_back(all(c));
  for (const auto& c : t.top) u.top.push_back(all(c));
  return u;
}

/// The tile's Coons patch Q(x, l), degree (d, 1) with d the highest chain piece degree (1 for
/// straight chains), x in [x_0, x_m], l in [0, 1]; points in R^2. Break points have multiplicity d
/// (the chains are only C0 there); x is linear in its parameter, so Q(x, l) has first coordinate x.
template <class T>
BSpline<T> tile_spline(const Tile<T>& t) {
  int d = 1;
  if (t.curved())
    for (std::size_t i = 0; i + 1 < t.x.size(); ++i)
      d = std::max({d, static_cast<int>(t.bottom[i].size()) - 1, static_cast<int>(t.top[i].size()) - 1});
  BSpline<T> Q;
  Q.degrees = {d, 1};
  Q.q = 2;
  std::vector<T> U(d + 1, t.x.front());
  for (std::size_t i = 1; i + 1 < t.x.size(); ++i) U.insert(U.end(), d, t.x[i]);
  U.insert(U.end(), d + 1, t.x.back());
  Q.knots = {U, {T(0), T(0), T(1), T(1)}};
  for (int side = 0; side < 2; ++side) {
    for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
      const auto c = elevate_ordinates(side == 0 ? t.bottom_piece(i) : t.top_piece(i), d);
      for (int j = i == 0 ? 0 : 1; j <= d; ++j) {
        Q.points.push_back(j == d ? t.x[i + 1] : t.x[i] + (t.x[i + 1] - t.x[i]) * T(j) / T(d));
        Q.points.push_back(c[j]);
      }
    }
    if (t.x.size() == 1) {  // a tile of zero width (not produced by the sweeps)
      Q.points.push_back(t.x[0]);
      Q.points.push_back(side == 0 ? t.yb[0] : t.yt[0]);
    }
  }
  return Q;
}

/// The tile's area: the integral of det dQ = y_t - y_b over x; on a piece the integral of a
/// Bernstein polynomial is the width times the mean of its ordinates (the trapezoid rule for lines).
template <class T>
T tile_area(const Tile<T>& t) {
  T a(0);
  for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
    const auto b = t.bottom_piece(i), c = t.top_piece(i);
    T mt(0), mb(0);
    for (const auto& v : c) mt = mt + v;
    for (const auto& v : b) mb = mb + v;
    a = a + (t.x[i + 1] - t.x[i]) * (mt / T(static_cast<long>(c.size())) - mb / T(static_cast<long>(b.size())));
  }
  return a;
}

/// The tile's boundary as a counter-clockwise polygon (bottom left to right, top right to left;
/// repeated points of degenerate sides removed). Straight chains only.
template <class T>
std::vector<Point2<T>> tile_polygon(const Tile<T>& t) {
  if (t.curved()) throw std::logic_error("tile_polygon: the tile has curved chains");
  std::vector<Point2<T>> p;
  for (std::size_t i = 0; i < t.x.size(); ++i) p.push_back({t.x[i], t.yb[i]});
  for (std::size_t i = t.x.size(); i-- > 0;) p.push_back({t.x[i], t.yt[i]});
  std::vector<Point2<T>> out;
  for (const auto& v : p)
    if (out.empty() || !(out.back() == v)) out.push_back(v);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

}  // namespace splinex
