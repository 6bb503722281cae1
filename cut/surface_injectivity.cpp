// The cutting surface's injectivity certificate on a grid of monotone windows (papers/004 Section
// 2's injectivity and regularity, the fallback of certify_cutting_surface when no single projection
// is monotone): grid_injectivity, described in surface_facet_impl.hpp.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "base/point.hpp"
#include "bernstein/tensor.hpp"
#include "cut/surface_facet_impl.hpp"

namespace splinex {
namespace surface_detail {

GridCertificate grid_injectivity(const std::vector<BezierPiece<Rational>>& pieces, const std::vector<K::Point_2>& poly, int max_level,
                                 std::size_t max_cells) {
  GridCertificate R;
  // the pieces' columns and rows
  std::vector<Rational> us, vs;
  for (const auto& pc : pieces) us.push_back(pc.box[0].first), vs.push_back(pc.box[1].first);
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  // Every coordinate times the common denominator L of all the pieces' control points: a positive
  // factor changes no sign and no order, and the integers it leaves (with the small denominators
  // of the dyadic splits) spare the gcds of exact patches' long fractions (minutes -> seconds).
  Rational L(1);
  {
    boost::multiprecision::mpz_int l(1);
    for (const auto& pc : pieces)
      for (const auto& x : pc.spline.points) {
        const boost::multiprecision::mpz_int d = boost::multiprecision::denominator(x);
        if (d != 1) mpz_lcm(l.backend().data(), l.backend().data(), d.backend().data());
      }
    L = Rational(l);
  }
  struct Cell {
    bool meets = false, built = false;
    P2 lo, hi;
    const BezierPiece<Rational>* piece = nullptr;
    int i = 0, j = 0;  // the sub-cell within the piece
    std::array<Bernstein<Rational>, 3> pu, pv;
    std::array<std::pair<Rational, Rational>, 3> box;
  };
  for (int m = 0; m <= max_level; ++m) {
    const long k = 1L << m, GI = static_cast<long>(us.size()) * k, GJ = static_cast<long>(vs.size()) * k;
    if (GI < 3 || GJ < 3) continue;
    if (static_cast<std::size_t>(GI * GJ) > max_cells) {
      if (R.why.empty()) R.why = "the grid would exceed " + std::to_string(max_cells) + " cells";
      break;
    }
    R.level = m;
    std::vector<Cell> cells(static_cast<std::size_t>(GI * GJ));
    auto at = [&](long I, long J) -> Cell& { return cells[static_cast<std::size_t>(J * GI + I)]; };
    for (const auto& pc : pieces) {
      const long pi = std::lower_bound(us.begin(), us.end(), pc.box[0].first) - us.begin();
      const long pj = std::lower_bound(vs.begin(), vs.end(), pc.box[1].first) - vs.begin();
      const Rational hu = (pc.box[0].second - pc.box[0].first) / k, hv = (pc.box[1].second - pc.box[1].first) / k;
      for (long i = 0; i < k; ++i)
        for (long j = 0; j < k; ++j) {
          Cell& c = at(pi * k + i, pj * k + j);
          c.piece = &pc;
          c.i = static_cast<int>(i), c.j = static_cast<int>(j);
          c.lo = {pc.box[0].first + hu * i, pc.box[1].first + hv * j};
          c.hi = {c.lo[0] + hu, c.lo[1] + hv};
          c.meets = box_meets_polygon(c.lo, c.hi, poly);
        }
    }
    auto build = [&](Cell& c) {
      if (c.built) return;
      c.built = true;
      const Rational a0(c.i, k), a1(c.i + 1, k), b0(c.j, k), b1(c.j + 1, k);
      const Rational hu = c.hi[0] - c.lo[0], hv = c.hi[1] - c.lo[1];
      for (int d = 0; d < 3; ++d) {
        auto X = scaled(bern_coordinate(c.piece->spline, d), L);
        if (k > 1) X = bern_restrict(bern_restrict(X, 0, a0, a1), 1, b0, b1);
        const auto [lo, hi] = bern_range(X);
        c.box[d] = {lo, hi};
        c.pu[d] = scaled(bern_derivative(X, 0), 1 / hu);
        c.pv[d] = scaled(bern_derivative(X, 1), 1 / hv);
      }
    };
    R.cells = 0;
    for (auto& c : cells)
      if (c.meets) ++R.cells;
    // (a) the windows
    bool ok = true;
    R.windows = 0;
    for (long I = 0; ok && I + 2 < GI; ++I)
      for (long J = 0; ok && J + 2 < GJ; ++J) {
        bool any = false;
        for (long a = 0; a < 3; ++a)
          for (long b = 0; b < 3; ++b) any = any || at(I + a, J + b).meets;
        if (!any) continue;
        ++R.windows;
        Cell& mid = at(I + 1, J + 1);
        build(mid);
        const std::vector<Rational> half{Rational(1, 2), Rational(1, 2)};
        P3 u, v;
        for (int d = 0; d < 3; ++d) u[d] = bern_value(mid.pu[d], half), v[d] = bern_value(mid.pv[d], half);
        const Rational g00 = dot(u, u), g01 = dot(u, v), g11 = dot(v, v), det = g00 * g11 - g01 * g01;
        if (det == 0) {
          ok = false;
          R.why = "p_u x p_v = 0 at the centre of the window at cell (" + std::to_string(I + 1) + ", " + std::to_string(J + 1) + ")";
          break;
        }
        // A = G^-1 [u^T; v^T], rounded to 20 bits relative to its largest entry
        std::array<Rational, 6> A;
        for (int d = 0; d < 3; ++d) A[d] = (g11 * u[d] - g01 * v[d]) / det, A[3 + d] = (g00 * v[d] - g01 * u[d]) / det;
        Rational mx(0);
        for (const auto& x : A) mx = std::max(mx, rabs(x));
        for (auto& x : A) x = round_to_grid(Rational(x / mx), 20);
        for (long a = 0; ok && a < 3; ++a)
          for (long b = 0; ok && b < 3; ++b) {
            Cell& c = at(I + a, J + b);
            build(c);
            auto row = [&](int r, const std::array<Bernstein<Rational>, 3>& w) {
              Bernstein<Rational> s = scaled(w[0], A[3 * r]);
              s = bern_combine(s, scaled(w[1], A[3 * r + 1]), false);
              return bern_combine(s, scaled(w[2], A[3 * r + 2]), false);
            };
            const auto fa = row(0, c.pu), fb1 = row(0, c.pv), fb2 = row(1, c.pu), fc = row(1, c.pv);
            const auto S = bern_combine(fb1, fb2, false);
            const auto Q = bern_combine(scaled(bern_product(fa, fc), Rational(4)), bern_product(S, S), true);
            if (!(bern_sign(fa) > 0 && bern_sign(Q) > 0)) {
              ok = false;
              R.why = "the window at cell (" + std::to_string(I + 1) + ", " + std::to_string(J + 1) + ") is not certified monotone";
            }
          }
      }
    if (!ok) continue;
    // (b) far cells: disjoint boxes (sweep over the x extent)
    std::vector<std::pair<long, long>> meet;
    for (long I = 0; I < GI; ++I)
      for (long J = 0; J < GJ; ++J)
        if (at(I, J).meets) build(at(I, J)), meet.emplace_back(I, J);
    std::sort(meet.begin(), meet.end(), [&](const auto& x, const auto& y) { return at(x.first, x.second).box[0].first < at(y.first, y.second).box[0].first; });
    for (std::size_t x = 0; ok && x < meet.size(); ++x) {
      const Cell& c1 = at(meet[x].first, meet[x].second);
      for (std::size_t y = x + 1; y < meet.size(); ++y) {
        const Cell& c2 = at(meet[y].first, meet[y].second);
        if (c1.box[0].second < c2.box[0].first) break;
        if (std::abs(meet[x].first - meet[y].first) < 3 && std::abs(meet[x].second - meet[y].second) < 3) continue;
        if (c1.box[1].second < c2.box[1].first || c2.box[1].second < c1.box[1].first || c1.box[2].second < c2.box[2].first ||
            c2.box[2].second < c1.box[2].first)
          continue;
        ok = false;
        R.why = "the boxes of the far cells (" + std::to_string(meet[x].first) + ", " + std::to_string(meet[x].second) + ") and (" +
                std::to_string(meet[y].first) + ", " + std::to_string(meet[y].second) + ") meet";
        break;
      }
    }
    if (ok) {
      R.proved = true;
      R.why.clear();
      return R;
    }
  }
  return R;
}

}  // namespace surface_detail
}  // namespace splinex
