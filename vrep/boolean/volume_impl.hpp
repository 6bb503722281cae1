// Volumes of V-model cells (vrep/boolean/boolean.hpp: cell_volume, volume_enclosure) and the bounds of
// N / W^power on a Bernstein box they use (vrep_detail::box_integral_bounds, coefficient_variation;
// box_integral_bounds is also used by vrep/freeform/freeform.cpp). Internal: template definitions,
// included by vrep/boolean/boolean_impl.hpp and instantiated in vrep/instances.cpp.
#pragma once
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "spline/bezier.hpp"
#include "spline/integrate.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/regularity_impl.hpp"  // vrep_detail::jacobian_numerator, homogeneous, mul, split_half, require_jacobian_input

namespace splinex {

namespace vrep_detail {

/// Bounds lo <= integral <= hi of N / W^power (det J: power 4) over a box that is the share `vol`
/// of its piece's unit cube (N, W in Bernstein form on the box): see volume_enclosure. `plain`:
/// the extreme coefficients' ratios only, without the Jensen / chord bounds' product N W.
template <class T>
void box_integral_bounds(const Bernstein<T>& N, const Bernstein<T>& W, const T& vol, T& lo, T& hi, int power = 4, bool plain = false) {
  T nmin = N.c.front(), nmax = nmin, wmin = W.c.front(), wmax = wmin;
  for (const auto& x : N.c) {
    if (x < nmin) nmin = x;
    if (nmax < x) nmax = x;
  }
  for (const auto& x : W.c) {
    if (x < wmin) wmin = x;
    if (wmax < x) wmax = x;
  }
  if (!(T(0) < wmin)) throw DomainError("trivariate.weights", "has a weight bound that is not positive", "give positive weights");
  // (f(W) = W^-power; power 4 for det J, 5 for a coordinate's moment X_c N / W^5.)
  T w4min(1), w4max(1);  // W^power at the ends
  for (int k = 0; k < power; ++k) {
    w4min *= wmin;
    w4max *= wmax;
  }
  if (!plain && (!(nmin < T(0)) || !(T(0) < nmax))) {
    // N of one sign on the box (sg N >= 0, sg = +-1): f(W) = W^-4 is convex, so with the
    // weight |N| Jensen gives the lower bound I f(J / I) (I = int |N|, J = int |N| W) and the
    // chord of f over [min W, max W] the upper bound; both integrals are exact (means of
    // Bernstein coefficients), and the gap shrinks with the square of the box.
    const T sg = nmax < T(0) || (nmax == T(0) && nmin < T(0)) ? T(-1) : T(1);
    T si(0);
    for (const auto& x : N.c) si += x;
    const T I = sg * vol * si / T(static_cast<long>(N.c.size()));
    // J = int |N| W; W constant (a polynomial cell: W = 1) needs no product.
    T J = I * wmin;
    if (!(wmax == wmin)) {
      T sj(0);
      const Bernstein<T> NW = vrep_detail::mul(N, W);
      for (const auto& x : NW.c) sj += x;
      J = sg * vol * sj / T(static_cast<long>(NW.c.size()));
    }
    if (I == T(0)) {
      lo = hi = T(0);
      return;
    }
    const T m = J / I;
    T mp(1);
    for (int k = 0; k < power; ++k) mp *= m;
    const T lower = I / mp;
    const T fa = T(1) / w4min, fb = T(1) / w4max;
    const T upper = wmax == wmin ? T(I * fa) : T(fa * I + (fb - fa) / (wmax - wmin) * (J - wmin * I));
    lo = sg < T(0) ? T(-upper) : lower;
    hi = sg < T(0) ? T(-lower) : upper;
    return;
  }
  lo = vol * (T(0) < nmin ? T(nmin / w4max) : T(nmin / w4min));
  hi = vol * (T(0) < nmax ? T(nmax / w4min) : T(nmax / w4max));
}

/// The largest difference of neighbouring coefficients along direction l: where a Bernstein
/// polynomial varies most (the direction to halve a box across).
template <class T>
T coefficient_variation(const Bernstein<T>& b, int l) {
  std::size_t stride = 1;
  for (int k = 0; k < l; ++k) stride *= b.deg[k] + 1;
  T v(0);
  for (std::size_t i = 0; i < b.c.size(); ++i) {
    if ((i / stride) % (b.deg[l] + 1) == static_cast<std::size_t>(b.deg[l])) continue;
    const T d = b.c[i + stride] - b.c[i];
    const T a = d < T(0) ? T(-d) : d;
    if (v < a) v = a;
  }
  return v;
}

}  // namespace vrep_detail

template <class T>
T cell_volume(const VModel<T>& M, std::size_t cell, const Limits& limits) {
  if (cell >= M.cells.size()) throw ValidationError("cell", "is not a cell of the model", "give 0 <= cell < the number of cells");
  const auto& V = M.trivariates[M.cells[cell].trivariates.front()];
  if (V.is_rational())
    throw DomainError("cells[" + std::to_string(cell) + "]", "is rational: its volume is not a rational number in general and the certified enclosure is not built yet",
                      "use polynomial cells for exact volumes");
  const T v = integrate(jacobian_determinant(V, limits))[0];
  return v < T(0) ? T(-v) : v;
}

template <class T>
VolumeEnclosure<T> volume_enclosure(const BSpline<T>& V, std::size_t max_boxes, const Limits& limits) {
  vrep_detail::require_jacobian_input(V, limits);
  if (max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
  // Per Bezier piece, in local coordinates s in [0, 1]^3 (the volume is the integral of the local
  // det J over the unit cube): det J = N / W^4, N and W in Bernstein form.
  struct Box {
    Bernstein<T> N, W;
    T vol, lo, hi;  // the box's share of the unit cube and the bounds of its integral
  };
  auto bounds = [](Box& b) { vrep_detail::box_integral_bounds(b.N, b.W, b.vol, b.lo, b.hi); };
  const auto variation = [](const Bernstein<T>& b, int l) { return vrep_detail::coefficient_variation(b, l); };
  VolumeEnclosure<T> out;
  const auto pieces = extract_bezier(V, limits);
  if (!V.is_rational()) {
    // Polynomial: the integral of N over the unit cube is the mean of its coefficients, exactly.
    for (const auto& pc : pieces) {
      const Bernstein<T> N = vrep_detail::jacobian_numerator(pc.spline);
      T sum(0);
      for (const auto& x : N.c) sum += x;
      out.lower += sum / T(static_cast<long>(N.c.size()));
    }
    out.upper = out.lower;
    if (out.lower < T(0)) out.lower = out.upper = -out.lower;
    out.boxes = pieces.size();
    return out;
  }
  // Rational: best first on the engine (bernstein/subdivide.hpp: refine), the widest enclosure
  // halved first, until the partition holds max_boxes boxes or every box's bounds meet.
  auto examine = [&](Box& b) {
    bounds(b);
    return b.hi == b.lo ? Examined::settled : Examined::split;
  };
  auto halve = [&](Box&& b, int, auto&& emit) {
    // Halve it across the direction where W varies most (N's if W is constant there).
    int dir = 0;
    T best(-1);
    for (int l = 0; l < 3; ++l) {
      const T v = b.W.deg[l] > 0 ? variation(b.W, l) : T(0);
      if (best < v) {
        best = v;
        dir = l;
      }
    }
    if (best == T(0)) {
      best = T(-1);
      for (int l = 0; l < 3; ++l) {
        const T v = b.N.deg[l] > 0 ? variation(b.N, l) : T(0);
        if (best < v) {
          best = v;
          dir = l;
        }
      }
    }
    auto [N0, N1] = vrep_detail::split_half(b.N, dir);
    auto [W0, W1] = vrep_detail::split_half(b.W, dir);
    emit(Box{std::move(N0), std::move(W0), b.vol / T(2), T(0), T(0)});
    emit(Box{std::move(N1), std::move(W1), b.vol / T(2), T(0), T(0)});
  };
  auto close = [&](Box&& b, bool) {
    out.lower += b.lo;
    out.upper += b.hi;
  };
  Budget budget;
  budget.max_boxes = max_boxes;
  const Subdivision run = refine_from<Box>(
      [&](auto&& emit) {
        for (const auto& pc : pieces) emit(Box{vrep_detail::jacobian_numerator(pc.spline), vrep_detail::homogeneous(pc.spline, 0), T(1), T(0), T(0)});
      },
      Order::best_first, budget, examine, halve, []() { return false; }, close, [](const Box& b) { return T(b.hi - b.lo); });
  out.boxes = run.boxes;
  if (out.upper < T(0)) {  // negatively oriented: the volume is the integral's magnitude
    const T l = -out.upper;
    out.upper = -out.lower;
    out.lower = l;
  }
  return out;
}

}  // namespace splinex
