#include "untrim/algorithm2.hpp"

#include <stdexcept>
#include <string>

#include "compose/affine.hpp"
#include "exact/flint_rational.hpp"
#include "exact/rational.hpp"
#include "float/mpfr.hpp"
#include "untrim/trimming_polyline.hpp"

namespace splinex {

namespace {

template <class T>
double dbl(const T& x) {
  return to_double(ArithTraits<T>::to_rational(x));
}
template <class T>
T from_dbl(double x) {
  return ArithTraits<T>::from_rational(exact_from_double(x));
}

}  // namespace

template <class T>
std::vector<T> TensorComposition<T>::evaluate_tile(std::size_t k, const std::vector<T>& xl) const {
  const auto& tt = tiles.at(k);
  auto v = evaluate(tt.R.net, xl);
  return tt.R.weighted ? divide_by_weight(v) : v;
}

template <class T>
TensorComposition<T> compose_tensor(const BSpline<T>& outer, const BSpline<T>& inner, const TensorOptions& options,
                                    const Limits& limits) {
  if (inner.dim() != 2)
    throw ValidationError("inner", "has " + std::to_string(inner.dim()) + " parameters; untrimming (Algorithm 2) is "
                                   "implemented for inner surfaces",
                          "use compose --method trimmed (Algorithm 1) for curves and trivariates");
  if (!(options.eps > 0) || !(options.eps < 1))
    throw ValidationError("eps", "must be in (0, 1)", "give a trimming tolerance like 1e-6");
  if (options.grid < 1 || options.grid > 4096)
    throw ValidationError("grid", "must be in 1..4096", "use a marching-squares grid like 16");
  TensorComposition<T> R;
  R.trimmed = compose_trimmed(outer, inner, options.trimmed, limits);
  const auto& C = R.trimmed;
  std::vector<std::vector<std::size_t>> by_piece(C.inner_pieces.size());
  for (std::size_t k = 0; k < C.patches.size(); ++k) by_piece[C.patches[k].inner_piece].push_back(k);
  R.subdivisions.resize(C.inner_pieces.size());
  for (std::size_t i = 0; i < C.inner_pieces.size(); ++i) {
    const BSpline<T>& P = C.inner_pieces[i].spline;
    const T r0 = P.domain_lo(0), r1 = P.domain_hi(0), t0 = P.domain_lo(1), t1 = P.domain_hi(1);
    std::vector<Segment2<T>> segs{{{r0, t0}, {r1, t0}}, {{r1, t0}, {r1, t1}}, {{r0, t1}, {r1, t1}}, {{r0, t0}, {r0, t1}}};
    // The distinct trimming levels (coordinate, value) tested by this piece's regions.
    std::vector<std::pair<int, T>> levels;
    auto level_index = [&](int c, const T& v) {
      for (std::size_t l = 0; l < levels.size(); ++l)
        if (levels[l].first == c && levels[l].second == v) return l;
      levels.emplace_back(c, v);
      return levels.size() - 1;
    };
    for (std::size_t k : by_piece[i])
      for (const auto& cond : C.patches[k].region) {
        if (cond.check_lo) level_index(cond.coord, cond.lo);
        if (cond.check_hi) level_index(cond.coord, cond.hi);
      }
    // The piece on [0, 1]^2 in double, for tracing and for polyline sides.
    BSpline<double> unit;
    std::vector<std::vector<Segment2<double>>> polylines(levels.size());
    std::vector<bool> straight(levels.size(), false);
    bool have_unit = false;
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const int c = levels[l].first;
      const T& L = levels[l].second;
      if (const auto form = affine_form(P, c)) {
        const T &al = form->alpha, &be = form->beta[0], &ga = form->beta[1];
        straight[l] = true;
        ++R.straight_boundaries;
        // The line al + be r + ga t = L against the box: corners on it and strict edge crossings.
        const Point2<T> cs[4] = {{r0, t0}, {r1, t0}, {r1, t1}, {r0, t1}};
        T g[4];
        for (int e = 0; e < 4; ++e) g[e] = al + be * cs[e][0] + ga * cs[e][1] - L;
        std::vector<Point2<T>> pts;
        for (int e = 0; e < 4; ++e) {
          const int f = (e + 1) % 4;
          if (g[e] == T(0)) pts.push_back(cs[e]);
          if ((g[e] < T(0) && g[f] > T(0)) || (g[e] > T(0) && g[f] < T(0))) {
            const T s = g[e] / (g[e] - g[f]);
            pts.push_back({cs[e][0] + (cs[f][0] - cs[e][0]) * s, cs[e][1] + (cs[f][1] - cs[e][1]) * s});
          }
        }
        if (pts.size() == 2) segs.push_back({pts[0], pts[1]});
        continue;
      }
      if (options.boundary == TrimBoundary::exact)
        throw DomainError("inner", "piece " + std::to_string(i) + " meets the knot " + ArithTraits<T>::to_string(L) +
                                       " of coordinate " + std::to_string(c) +
                                       " along a curved trimming curve; exact untrimming needs straight (affine) ones",
                          "untrim with a tolerance (--eps) to use trimming polylines");
      if (!have_unit) {
        BSpline<T> U01 = reparametrize(reparametrize(P, 0, T(0), T(1)), 1, T(0), T(1));
        unit = convert<double>(U01, [](const T& x) { return dbl(x); });
        have_unit = true;
      }
      TrimmingTolerance tol;
      tol.eps = options.eps;
      tol.grid = options.grid;
      polylines[l] = trace_level_set(unit, c, dbl(L), tol);
      ++R.curved_boundaries;
      auto map = [&](const Point2<double>& p) {
        const T x = from_dbl<T>(p[0]), y = from_dbl<T>(p[1]);
        return Point2<T>{x == T(1) ? r1 : r0 + (r1 - r0) * x, y == T(1) ? t1 : t0 + (t1 - t0) * y};
      };
      for (const auto& s : polylines[l]) segs.push_back({map(s.a), map(s.b)});
    }
    R.subdivisions[i] = planar_subdivision(segs);
    const auto traps = vertical_decomposition(R.subdivisions[i]);
    R.trapezoids += traps.size();
    // Label each trapezoid by the region owning a point strictly inside it.
    std::vector<int> labels(traps.size(), -1);
    for (std::size_t z = 0; z < traps.size(); ++z) {
      const auto& tz = traps[z];
      const T mx = (tz.x0 + tz.x1) / T(2), my = (tz.yb0 + tz.yb1 + tz.yt0 + tz.yt1) / T(4);
      const std::vector<T> m{mx, my};
      const auto s = evaluate(P, m);
      auto at_least = [&](int c, const T& L) {  // the side of level (c, L) that m is on: s_c >= L?
        const std::size_t l = level_index(c, L);
        if (straight[l] || options.boundary == TrimBoundary::exact) return !(s[c] < L);
        const Point2<double> mu{dbl(T((mx - r0) / (r1 - r0))), dbl(T((my - t0) / (t1 - t0)))};
        return polyline_side(unit, c, dbl(L), polylines[l], mu);
      };
      int owner = -1, owners = 0;
      for (std::size_t k : by_piece[i]) {
        bool in = true;
        for (const auto& cond : C.patches[k].region) {
          if (cond.check_lo && !at_least(cond.coord, cond.lo)) in = false;
          if (cond.check_hi && at_least(cond.coord, cond.hi)) in = false;
        }
        if (in) {
          owner = static_cast<int>(k);
          ++owners;
        }
      }
      const T area = (tz.x1 - tz.x0) * ((tz.yt0 - tz.yb0) + (tz.yt1 - tz.yb1)) / T(2);
      if (owners != 1 && (options.boundary == TrimBoundary::exact || levels.size() == 0))
        throw std::logic_error("compose_tensor: a tile of inner piece " + std::to_string(i) + " has " +
                               std::to_string(owners) + " owning regions");
      // Polylines of different levels may cross where the true curves come within eps: the
      // sides then disagree; what no region claims is a gap, what two claim an overlap.
      if (owners == 0) R.gap_area = R.gap_area + area;
      if (owners > 1) R.overlap_area = R.overlap_area + area;
      labels[z] = owner;
    }
    for (auto& tile : merge_trapezoids(traps, labels)) {
      TensorTile<T> tt;
      tt.patch = static_cast<std::size_t>(tile.label);
      tt.Q = tile_spline(tile);
      tt.area = tile_area(tile);
      tt.tile = std::move(tile);
      R.tiles.push_back(std::move(tt));
    }
  }
  // Every tile is known: before composing any, the tiles' nets together must fit the limit.
  const std::string what = R.curved_boundaries > 0 ? "eps" : "inner";  // what makes the tiles many
  std::size_t least = 0;
  for (const auto& tt : R.tiles) {
    least += compose_least_size(C.patches[tt.patch].patch.net, tt.Q, limits);
    limits.check_total(least, what);
  }
  CompositionOptions co;
  co.method = options.trimmed.method;
  co.expand = true;
  std::size_t total = 0;
  for (auto& tt : R.tiles) {
    // The patch is polynomial (homogeneous if rational): compose its Bezier form with Q.
    tt.R = {compose(C.patches[tt.patch].patch.net, tt.Q, co, limits), C.patches[tt.patch].patch.weighted};
    total += tt.R.net.size();
    limits.check_total(total, what);
  }
  return R;
}

template struct TensorComposition<Rational>;
template struct TensorComposition<double>;
template struct TensorComposition<Mpfr>;
template TensorComposition<Rational> compose_tensor(const BSpline<Rational>&, const BSpline<Rational>&,
                                                    const TensorOptions&, const Limits&);
template TensorComposition<double> compose_tensor(const BSpline<double>&, const BSpline<double>&, const TensorOptions&,
                                                  const Limits&);
template TensorComposition<Mpfr> compose_tensor(const BSpline<Mpfr>&, const BSpline<Mpfr>&, const TensorOptions&,
                                                const Limits&);

}  // namespace splinex
