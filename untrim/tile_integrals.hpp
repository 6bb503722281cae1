// Integrals over untrimmed regions: the reason the V-rep paper untrims (papers/002 Section 5.1).
// A tile {(x, y): x in [x_0, x_m], y_b(x) <= y <= y_t(x)} with Coons patch Q(x, l) = (x, y_b + l (y_t - y_b))
// has det dQ/d(x, l) = y_t(x) - y_b(x) (linear on every straight chain piece), so for a polynomial density f
//     int_tile f dA = int_{x_0}^{x_m} int_0^1 f(Q(x, l)) (y_t(x) - y_b(x)) dl dx.
// f(Q) is composed exactly (a B-spline in (x, l) with the chain vertices as knots in x); on each
// Bezier piece with coefficients c_ab (degrees n in x, k in l) and the determinant d0, d1 at the
// piece's ends, int B_a^n(s) ((1-s) d0 + s d1) ds = (d0 (n+1-a) + d1 (a+1)) / ((n+1)(n+2)) and
// int B_b^k = 1/(k+1), so
//     int_piece = dx * sum_ab c_ab (d0 (n+1-a) + d1 (a+1)) / ((n+1)(n+2)(k+1)).
// Curved chains (degree e pieces, det = sum_c delta_c B_c^e) use the general product rule
//     int_0^1 B_a^n B_c^e ds = C(n, a) C(e, c) / (C(n+e, a+c) (n+e+1)),
// which is the formula above for e = 1.
// Exact for exact T; the same code in floating point.
#pragma once
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bernstein.hpp"
#include "compose/compose.hpp"
#include "untrim/sweep.hpp"

namespace splinex {

/// The integral of the polynomial density f (one polynomial piece in (x, y), any box: it is used
/// as the polynomial on all of R^2; points in R^q, one integral per coordinate) over the tile.
template <class T>
std::vector<T> integrate_over_tile(const BSpline<T>& f, const Tile<T>& tile, const Limits& limits = {}) {
  if (f.dim() != 2) throw ValidationError("density", "has " + std::to_string(f.dim()) + " parameters", "give a density in (x, y)");
  if (f.is_rational()) throw ValidationError("density", "is rational", "give a polynomial density (no weights)");
  for (int d = 0; d < 2; ++d)
    if (f.knots[d].size() != static_cast<std::size_t>(2 * f.degrees[d] + 2))
      throw ValidationError("density", "knots[" + std::to_string(d) + "] has interior knots",
                            "give the density as one polynomial (Bezier) piece");
  std::vector<T> sum(f.q, T(0));
  if (tile.x.size() < 2) return sum;
  CompositionOptions co;
  co.expand = true;
  // One chain piece at a time: there Q is one Bezier patch and f(Q) one Bezier piece (composing
  // the whole tile would merge pieces where f(Q) happens to be smooth, e.g. constant f).
  for (std::size_t i = 0; i + 1 < tile.x.size(); ++i) {
    const Tile<T> piece = tile.piece(i);
    const BSpline<T> F = compose(f, tile_spline(piece), co, limits);
    const int n = F.degrees[0], k = F.degrees[1];
    if (F.count(0) != static_cast<std::size_t>(n + 1) || F.count(1) != static_cast<std::size_t>(k + 1))
      throw std::logic_error("integrate_over_tile: f(Q) on a chain piece is not one Bezier piece");
    /// det dQ = y_t - y_b in Bernstein form of degree e.
    const auto bt = piece.top_piece(0), bb = piece.bottom_piece(0);
    const int e = static_cast<int>(std::max(bt.size(), bb.size())) - 1;
    const auto ct = elevate_ordinates(bt, e), cb = elevate_ordinates(bb, e);
    const T dx = tile.x[i + 1] - tile.x[i];
    for (int c = 0; c <= e; ++c) {
      const T delta = ct[c] - cb[c];
      for (int a = 0; a <= n; ++a) {
        const T w = delta * dx * detail::binomial<T>(n, a) * detail::binomial<T>(e, c) / (detail::binomial<T>(n + e, a + c) * T(n + e + 1) * T(k + 1));
        for (int b = 0; b <= k; ++b)
          for (int q = 0; q < f.q; ++q)
            sum[q] = sum[q] + F.points[(static_cast<std::size_t>(b) * (n + 1) + a) * f.q + q] * w;
      }
    }
  }
  return sum;
}

}  // namespace splinex
