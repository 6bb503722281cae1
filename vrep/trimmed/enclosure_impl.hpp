// Adaptive certified enclosures of volumes, moments and field integrals over (trimmed) cells
// (vrep/trimmed/trimmed.hpp: integral_enclosures, trimmed_volume, trimmed_moment, trimmed_field_integral);
// the templates, instantiated in vrep/instances.cpp.
//
// One best-first refinement (bernstein/subdivide.hpp: refine) of parameter boxes over all cells,
// keyed by each box's share of the width
// (upper - lower, the moments' widths scaled to the volume's); the widest box is halved (exact de
// Casteljau) until the widths are within the requested relative width or the box budget is spent.
// Per box, with det J = N / W^4 and an integrand Q / W^p (Q = N: the volume; Q = X_c N, p = 5: a
// coordinate's moment; Q = F_k N, p = 4: a field's component):
//   - out (the trim's formula is false on the box, decided by the leaves' Bernstein coefficients):
//     0, dropped;
//   - in, polynomial cell: the exact integral (the mean of Q's coefficients), dropped;
//   - in, rational cell: Taylor's formula of f(w) = w^-p at a point w0 of order 6 with the
//     remainder f^(6)(xi) / 6! (W - w0)^6, f^(6) > 0 decreasing so between its values at the ends
//     of W's coefficient range, the moments int Q W^j exact (Gram matrices of Bernstein bases
//     contracted on integers); where Q has one sign also Jensen's lower bound and the chord's upper
//     bound (vrep/boolean/boolean.hpp's volume_enclosure), the tighter of each kept. The gap shrinks with
//     the seventh power of the box;
//   - cut by one trimming surface G whose sign the formula follows: where G is strictly monotone
//     along a direction k (its derivative's Bernstein coefficients of one strict sign, |dG/ds_k| >=
//     m) the part is one side of a graph s_k = phi(s_a, s_b) in every column. psi, a biquadratic
//     through approximate roots at a 3 x 3 grid (Newton in short dyadics), is certified within
//     eps = max |G(s, psi(s))| / m of phi (the Bernstein coefficients of the composition; where psi
//     leaves [0, 1], G monotone on the longer interval, by de Casteljau outside [0, 1]). The
//     integral of a polynomial P over the part is int int A(s, clamp(phi(s))) (A: P's antiderivative
//     along k), which is int int A(s, psi(s)) (exact: Gram contraction with B_l^q(psi)) within eps
//     max |P|, corrected where psi leaves [0, 1] by a subdivision of the face (exact where psi is on
//     one side, bounded where the level set still crosses after 5 halvings). Polynomial cells take
//     P = Q; rational ones Taylor's formula of order 2 at w0 (P = Q and Q (W - w0), the remainder
//     between 0 and the whole box's f''/2 Q (W - w0)^2). The gap shrinks with the cube of the box.
//     Otherwise an affine L with |G - L| <= e on the box bounds the part between the exact volumes
//     of {L >= e} and {L >= -e} (a half-space in a cube), the integrand between its coefficient
//     ratios; with several undecided surfaces the part holds between none and all of the box.
// Bounds are rounded outward to about 64 significant bits when their numbers grow beyond 128 bits
// (exact results are kept exact). Exact in exact arithmetic; in double and MPFR the same steps,
// uncertified.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <queue>
#include <type_traits>

#include "vrep/trimmed/graph_cut_impl.hpp"

namespace splinex {

namespace vrep_detail {

/// One unit in the 64th significant bit of x: 2^(floor(log2 |x|) - 63) (2^-64 for 0).
template <class T>
T last_bit_unit(const T& x) {
  const T ax = x < T(0) ? T(-x) : x;
  T u(1);
  if (!(ax == T(0))) {
    while (!(ax < u)) u *= T(2);
    while (ax < u) u /= T(2);
  }
  for (int i = 0; i < 63 + (ax == T(0) ? 1 : 0); ++i) u /= T(2);
  return u;
}

}  // namespace vrep_detail

namespace vrep_detail {

/// One run of integral_enclosures: the cells' checks and their Bezier pieces, each box's bounds
/// (an in-box, a box cut by one surface through its graph, otherwise an affine fit), and the sums,
/// refined best first on the engine (bernstein/subdivide.hpp: refine).
template <class T>
class IntegralRun {
 public:
  IntegralRun(const std::vector<IntegrandCell<T>>& cells_, const std::vector<int>& components_, const T& rel_width_, std::size_t max_boxes,
              const Limits& limits_)
      : cells(cells_), components(components_), rel_width(rel_width_), limits(limits_), K(components_.size()), C(cells_.size()) {
    if (max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
    if (rel_width < T(0)) throw ValidationError("rel_width", "is negative", "give a relative width >= 0 (0: spend the whole budget)");
    out.scale.assign(K, T(0));
    make_roots(max_boxes);
  }

  IntegralEnclosures<T> run() {
    // A box is examined when it is made: its bounds count at once; one cut at a parameter plane is
    // replaced by its two parts.
    auto examine = [&](Box& b) {
      const bool alive = evaluate(b);
      if (!(b.at == T(0))) return Examined::replace;
      ++C[b.cell].boxes;
      add_bounds(b, false);
      if (!alive) return Examined::settled;
      carried.add(CarriedCoefficients::of(b.G));
      return Examined::split;
    };
    auto halves = [&](Box&& b, int, auto&& emit) {
      if (b.at == T(0)) {  // a box of the partition: its bounds leave the sums
        carried.remove(CarriedCoefficients::of(b.G));
        add_bounds(b, true);
        --C[b.cell].boxes;
      }
      Box c[2];
      split(b, c);
      b = Box{};
      emit(std::move(c[0]));
      emit(std::move(c[1]));
    };
    // The widest box first (its share of the summed widths), until the target or the budget.
    Budget budget;
    budget.max_boxes = out.budget;
    refine(std::move(initial), Order::best_first, budget, examine, halves, [&]() { return reached(); }, [](Box&&, bool) {},
           [](const Box& b) -> T { return b.key; });
    finish();
    return std::move(out);
  }

 private:
  struct Cell {
    const Region<T>* trim = nullptr;
    std::vector<const Poly3<T>*> leaves;
    bool rational = false;
    int power = 5;
    T vlo{0}, vhi{0};
    std::vector<T> mlo, mhi;
    std::size_t boxes = 0;
    int orientation = 0;  // the sign of det J (of a regular cell): of N's integral over a piece, exactly
  };
  struct Box {
    std::size_t cell = 0;
    std::vector<Truth> lt;   // every leaf's truth on the box
    std::vector<SBern<T>> G;  // the undecided leaves' compositions (decided: emptied)
    SBern<T> N, W;
    std::vector<SBern<T>> Q;  // per component: the integrand's numerator
    T vol{1};                // share of its piece's unit cube
    T vlo{0}, vhi{0};
    std::vector<T> mlo, mhi;
    T key{0};
    int dir = 0;
    std::array<unsigned char, 3> splits{0, 0, 0};  // halvings per direction so far
    T at{0};  // > 0: cut at this parameter of direction dir before anything else (a parameter plane)
  };
  const std::vector<IntegrandCell<T>>& cells;
  const std::vector<int>& components;
  const T rel_width;
  const Limits& limits;
  const std::size_t K;
  const Region<T> whole = region_and<T>({});
  std::vector<Cell> C;
  IntegralEnclosures<T> out;
  GramCache<T> gram;
  static constexpr int order = 6;  // Taylor's order in the rational in-boxes (even)
  const vrep_testing::EnclosurePlant plant = vrep_testing::planted_enclosure;
  std::vector<Box> initial;  // the roots: every Bezier piece of every cell
  std::vector<T> inv_scale;  // the moments' widths count in the volume's units: width / scale
  CarriedCoefficients carried{limits};  // the leaves' coefficients carried by the open boxes, against the limit

  // The checks and the initial boxes: every Bezier piece of every cell.
  void make_roots(std::size_t max_boxes) {
    CarriedCoefficients initial_carried{limits};
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string who = cells.size() == 1 ? std::string() : "cells[" + std::to_string(c) + "].";
      if (!cells[c].trivariate) throw ValidationError(who + "trivariate", "is missing", "give the cell's trivariate");
      const BSpline<T>& V0 = *cells[c].trivariate;
      const BSpline<T>* field = cells[c].field;
      require_jacobian_input(V0, limits);
      std::optional<std::pair<BSpline<T>, BSpline<T>>> refined;
      for (int k : components) {
        if (k < 0) throw ValidationError(field ? "component" : "coordinate", "is negative", "give 0 <= coordinate < q");
        if (!field && k >= V0.q) throw ValidationError("coordinate", "is not a point coordinate of the trivariate", "give 0 <= coordinate < q");
        if (field) require_field(V0, *field, k, "field", limits);
      }
      if (field && K > 0) refined = common_breakpoints(V0, *field, limits);
      const BSpline<T>& V = refined ? refined->first : V0;
      require_positive_weights(V);
      Cell& cell = C[c];
      cell.trim = cells[c].trim ? cells[c].trim : &whole;
      collect_leaves(*cell.trim, cell.leaves);
      cell.rational = V.is_rational();
      cell.power = field ? 4 : 5;
      cell.mlo.assign(K, T(0));
      cell.mhi.assign(K, T(0));
      // Limits before the work: all leaves composed on one piece; the boxes' compositions are
      // counted as they are made (a box carries only the leaves that can still change its truth).
      composed_leaves_size(V, cell.leaves, limits);
      // The moments' scales: the largest |coordinate| (or |field component|) of the control points.
      for (std::size_t k = 0; k < K; ++k) {
        const BSpline<T>& S = field ? *field : V;
        for (std::size_t i = 0; i < S.size(); ++i) {
          T x = S.points[i * S.q + components[k]];
          if (x < T(0)) x = -x;
          if (out.scale[k] < x) out.scale[k] = x;
        }
      }
      const BezierForm<T> F = bezier_form(V, limits);
      std::optional<BezierForm<T>> FF;
      if (field && K > 0) FF = bezier_form(refined->second, limits);
      for (std::size_t p = 0; p < F.size(); ++p) {
        const auto pc = F.piece(p);
        Box b;
        b.cell = c;
        b.lt.assign(cell.leaves.size(), Truth::mixed);
        // The planes first (cheap); then only the leaves the formula may still depend on.
        b.G.resize(cell.leaves.size());
        PiecePowers<T> powers(pc.spline);
        for (std::size_t l = 0; l < cell.leaves.size(); ++l)
          if (cell.leaves[l]->degree() <= 1) {
            b.G[l] = scaled(compose_leaf(*cell.leaves[l], powers));
            b.lt[l] = coefficient_truth(b.G[l]);
            if (b.lt[l] != Truth::mixed) b.G[l] = SBern<T>{};
          }
        std::vector<char> live;
        live_leaves(*cell.trim, b.lt, live);
        for (std::size_t l = 0; l < cell.leaves.size(); ++l)
          if (cell.leaves[l]->degree() > 1 && live[l]) b.G[l] = scaled(compose_leaf(*cell.leaves[l], powers));
        initial_carried.add(CarriedCoefficients::of(b.G), "the cells' pieces");  // as they are made
        const Bernstein<T> N = jacobian_numerator(pc.spline);
        if (cell.orientation == 0) {
          // N's mean is its integral over the piece, W^4 > 0: a regular cell's orientation.
          T sum(0);
          for (const auto& x : N.c) sum += x;
          cell.orientation = sum < T(0) ? -1 : T(0) < sum ? 1 : 0;
        }
        b.N = scaled(N);
        b.W = scaled(homogeneous(pc.spline, 0));
        for (std::size_t k = 0; k < K; ++k)
          b.Q.push_back(scaled(mul(FF ? homogeneous(FF->piece(p).spline, components[k] + 1) : homogeneous(pc.spline, components[k] + 1), N)));
        b.mlo.assign(K, T(0));
        b.mhi.assign(K, T(0));
        initial.push_back(std::move(b));
      }
    }
    out.budget = checked_product(max_boxes, std::max<std::size_t>(cells.size(), 1), limits, "box budget");
    if (initial.size() > out.budget) out.budget = initial.size();
    inv_scale.assign(K, T(0));
    for (std::size_t k = 0; k < K; ++k)
      if (T(0) < out.scale[k]) inv_scale[k] = round_outward(T(T(1) / out.scale[k]), true);
  }

  // Where the integrands vary most relative to their size (N, the moments' numerators, W to the
  // power 4): the direction to halve a box whose width comes from them.
  int density_direction(const Box& b) {
    std::array<T, 3> score{T(0), T(0), T(0)};
    auto add = [&](const SBern<T>& P, const T& weight) {
      T lo, hi;
      coefficient_range(P, lo, hi);
      const T m = std::max(T(-lo), hi);
      if (!(T(0) < m)) return;
      const auto v = variation_along(P);
      for (int d = 0; d < 3; ++d) score[d] += weight * v[d] * P.scale / m;
    };
    add(b.N, T(1));
    for (const auto& q : b.Q) add(q, T(1));
    if (C[b.cell].rational) add(b.W, T(4));
    int dir = 0;
    for (int d = 1; d < 3; ++d)
      if (score[dir] < score[d]) dir = d;
    return dir;
  }

  // Bounds, priority and split direction of a box; false when the box is done (no width left to
  // gain from it: out, or exact). (A box cut at a parameter plane: true, with b.at set.)
  bool evaluate(Box& b) {
    Cell& cell = C[b.cell];
    // A leaf not carried (empty) is decided, or one the formula no longer depends on (kept mixed).
    for (std::size_t l = 0; l < b.G.size(); ++l) {
      if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
      b.lt[l] = coefficient_truth(b.G[l]);
      if (b.lt[l] != Truth::mixed) b.G[l] = SBern<T>{};
    }
    std::size_t k0 = 0;
    const Truth truth = cell.leaves.empty() ? Truth::in : combine(*cell.trim, b.lt, k0);
    std::size_t open = 0, last_open = 0;
    if (truth == Truth::mixed) {
      std::vector<char> live;
      live_leaves(*cell.trim, b.lt, live);
      for (std::size_t l = 0; l < b.G.size(); ++l) {
        if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
        if (!live[l]) b.G[l] = SBern<T>{};
        else {
          ++open;
          last_open = l;
        }
      }
    }
    b.vlo = b.vhi = T(0);
    for (std::size_t k = 0; k < K; ++k) b.mlo[k] = b.mhi[k] = T(0);
    b.key = T(0);
    if (truth == Truth::out) return false;
    if (truth == Truth::in) {
      if (!in_bounds(b, cell)) return false;
    } else {
      if (cut_bounds(b, cell, open, last_open)) return true;
    }
    T key = b.vhi - b.vlo;
    for (std::size_t k = 0; k < K; ++k) key += (b.mhi[k] - b.mlo[k]) * inv_scale[k];
    b.key = round_outward(key, true);
    return T(0) < b.key;
  }

  // An in-box: the formula is in whatever its undecided leaves do; a polynomial cell's integrals
  // exact (false: nothing left to gain), a rational one's by Taylor's formula.
  bool in_bounds(Box& b, Cell& cell) {
    // The formula is in whatever its undecided leaves do (Kleene's logic is monotone): they
    // count as in from here on, for the box's parts too.
    for (std::size_t l = 0; l < b.G.size(); ++l) {
      b.G[l] = SBern<T>{};
      if (b.lt[l] == Truth::mixed) b.lt[l] = Truth::in;
    }
    if (!cell.rational) {
      b.vlo = b.vhi = b.vol * coefficient_mean(b.N);
      for (std::size_t k = 0; k < K; ++k) b.mlo[k] = b.mhi[k] = b.vol * coefficient_mean(b.Q[k]);
      return false;
    }
    T lo, hi;
    std::vector<SBern<T>> Wp{b.W};  // W, W^2, ..., W^order
    for (int j = 2; j <= order; ++j) Wp.push_back(product(Wp.back(), b.W));
    taylor_bounds(b.N, Wp, 4, order, gram, lo, hi);
    b.vlo = round_outward(T(b.vol * lo), false);
    b.vhi = round_outward(T(b.vol * hi), true);
    for (std::size_t k = 0; k < K; ++k) {
      taylor_bounds(b.Q[k], Wp, cell.power, order, gram, lo, hi);
      b.mlo[k] = round_outward(T(b.vol * lo), false);
      b.mhi[k] = round_outward(T(b.vol * hi), true);
    }
    // Across the direction where W varies most (N's where W is constant).
    T best;
    b.dir = most_varying(b.W, &best);
    if (!(T(0) < best)) b.dir = most_varying(b.N);
    return true;
  }

  // A box the trimming cuts: its bounds and split direction; true when it is to be cut at a
  // parameter plane first (b.at).
  bool cut_bounds(Box& b, Cell& cell, std::size_t open, std::size_t last_open) {
    // Cut. One undecided leaf the formula follows: the part is {G >= 0} or {G <= 0} on the box.
    T wmin, wmax;
    coefficient_range(b.W, wmin, wmax);
    if (!(T(0) < wmin)) throw DomainError("trivariate.weights", "has a weight bound that is not positive", "give positive weights");
    int sense = 0;  // +1: {G >= 0}, -1: {G <= 0}
    if (open == 1 && plant != vrep_testing::EnclosurePlant::drop_crossing) {
      auto lt = b.lt;
      lt[last_open] = Truth::in;
      std::size_t k1 = 0;
      const Truth t_in = combine(*cell.trim, lt, k1);
      lt[last_open] = Truth::out;
      k1 = 0;
      const Truth t_out = combine(*cell.trim, lt, k1);
      if (t_in == Truth::in && t_out == Truth::out) sense = 1;
      if (t_in == Truth::out && t_out == Truth::in) sense = -1;
    }
    GraphCut<T> graph;
    // A surface affine in the parameters (a plane of an affine cell) is cut exactly below.
    bool planar = false;
    if (sense != 0) {
      const auto cv = curvature_along(b.G[last_open]);
      planar = cv[0] == T(0) && cv[1] == T(0) && cv[2] == T(0);
    }
    if (planar) {
      // A parameter plane s_d = c: the box is cut there exactly (both parts then decided).
      T a0, e;
      std::array<T, 3> a;
      affine_fit(b.G[last_open], a0, a, e, false);
      int nonzero = 0, d0 = 0;
      for (int d = 0; d < 3; ++d)
        if (!(a[d] == T(0))) {
          ++nonzero;
          d0 = d;
        }
      if (nonzero == 1) {
        const T c = -a0 / a[d0];
        if (T(0) < c && c < T(1)) {
          b.dir = d0;
          b.at = c;
          return true;
        }
      }
    }
    if (sense != 0 && !planar && graph_cut(b.G[last_open], sense > 0, graph)) graph_bounds(b, cell, wmin, wmax, graph);
    else fit_bounds(b, cell, sense, planar, last_open, wmin, wmax, graph);
    if (!(b.vlo == b.vhi)) {
      b.vlo = round_outward(b.vlo, false);
      b.vhi = round_outward(b.vhi, true);
    }
    for (std::size_t k = 0; k < K; ++k)
      if (!(b.mlo[k] == b.mhi[k])) {
        b.mlo[k] = round_outward(b.mlo[k], false);
        b.mhi[k] = round_outward(b.mhi[k], true);
      }
    return false;
  }

  // The range of the integrand Q / W^p over the box from its coefficients: Q's coefficient range,
  // divided by W^p's for a rational cell (ratio_bounds).
  void integrand_range(const Cell& cell, const SBern<T>& Q, int p, const T& wmin, const T& wmax, T& lo, T& hi) const {
    T qmin, qmax;
    coefficient_range(Q, qmin, qmax);
    if (cell.rational) {
      ratio_bounds(qmin, qmax, wmin, wmax, p, lo, hi);
    } else {
      lo = qmin;
      hi = qmax;
    }
  }

  // One surface the formula follows, a graph over a face of the box (GraphCut).
  void graph_bounds(Box& b, Cell& cell, const T& wmin, const T& wmax, GraphCut<T>& graph) {
    // The whole box's integral of Q / W^p between none and all of it (the coefficient ratios).
    auto trivial = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
      integrand_range(cell, Q, p, wmin, wmax, lo, hi);
      lo = std::min(T(0), lo);
      hi = std::max(T(0), hi);
    };
    T geometric(0);  // the width the graph's eps causes (volume's units)
    // int_part Q / W^p: polynomial cells int_part Q directly; rational ones Taylor's formula of
    // order 2 at w0 with int_part Q, Q (W - w0), Q (W - w0)^2, the remainder f''(xi) / 2 between
    // its values at the ends of W's range.
    T w0 = short_dyadic(coefficient_mean(b.W));
    if (w0 < wmin) w0 = wmin;
    if (wmax < w0) w0 = wmax;
    SBern<T> Wm, Wm2;
    if (cell.rational) {
      Bernstein<T> v{b.W.deg, std::vector<T>(b.W.c.size())};
      for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(b.W.c[i]) * b.W.scale - w0;
      Wm = scaled(v);
      Wm2 = product(Wm, Wm);
    }
    auto through_graph = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
      T l0, h0;
      graph_integral(Q, graph, gram, l0, h0);
      if (!cell.rational) {
        lo = l0;
        hi = h0;
        geometric += h0 - l0;
        return;
      }
      T l1, h1;
      graph_integral(product(Q, Wm), graph, gram, l1, h1);
      T qmin, qmax;
      coefficient_range(Q, qmin, qmax);
      const T c0 = T(1) / power_of(w0, p), c1 = -T(p) / power_of(w0, p + 1);
      const T r = T(p * (p + 1)) / T(2);
      const T rhi = r / power_of(std::min(wmin, w0), p + 2);  // f''(xi) / 2 at most this (xi >= wmin)
      T Rlo, Rhi;
      if (!(qmin < T(0)) || !(T(0) < qmax)) {
        // Q of one sign: int_part Q (W - w0)^2 has it, and is at most the box's.
        const bool pos = !(qmin < T(0));
        const T E2 = product_integral(Q, Wm2, gram);
        Rlo = pos ? T(0) : T(rhi * E2);
        Rhi = pos ? T(rhi * E2) : T(0);
      } else {
        // Q f''(xi) / 2 (W - w0)^2 with the part's int of (W - w0)^2 between 0 and the box's.
        const T E0 = coefficient_mean(Wm2);
        Rlo = std::min(T(0), qmin) * rhi * E0;
        Rhi = std::max(T(0), qmax) * rhi * E0;
      }
      lo = c0 * l0 + c1 * h1 + Rlo;
      hi = c0 * h0 + c1 * l1 + Rhi;
      geometric += c0 * (h0 - l0) - c1 * (h1 - l1);
    };
    T tl, th;
    through_graph(b.N, 4, b.vlo, b.vhi);
    trivial(b.N, 4, tl, th);
    b.vlo = std::max(b.vlo, tl);
    b.vhi = std::min(b.vhi, th);
    const T geo_volume = geometric;
    for (std::size_t k = 0; k < K; ++k) {
      through_graph(b.Q[k], cell.power, b.mlo[k], b.mhi[k]);
      trivial(b.Q[k], cell.power, tl, th);
      b.mlo[k] = std::max(b.mlo[k], tl);
      b.mhi[k] = std::min(b.mhi[k], th);
    }
    for (T* x : {&b.vlo, &b.vhi}) *x *= b.vol;
    for (std::size_t k = 0; k < K; ++k) {
      b.mlo[k] *= b.vol;
      b.mhi[k] *= b.vol;
    }
    // Across the face direction where psi curves most when the graph's error dominates, else
    // where W varies most.
    const int fa = graph.k == 0 ? 1 : 0, fb = graph.k == 2 ? 1 : 2;
    if (!cell.rational || (b.vhi - b.vlo) < T(2) * geo_volume * b.vol) b.dir = graph.curvature[1] < graph.curvature[0] ? fa : graph.curvature[0] < graph.curvature[1] ? fb : (b.splits[fa] <= b.splits[fb] ? fa : fb);
    else b.dir = density_direction(b);
  }

  // Otherwise the affine fit (or, with several surfaces, none and all of the box).
  void fit_bounds(Box& b, Cell& cell, int sense, bool planar, std::size_t last_open, const T& wmin, const T& wmax, const GraphCut<T>& graph) {
    // Otherwise the affine fit: with |G - L| <= e on the box, {L >= e} lies in the part and
    // the part in {L >= -e}: its share of the box is between their exact volumes, and the
    // integrand between its coefficient-ratio bounds. Several undecided leaves: between none
    // and all of the box.
    T f_lo(0), f_hi(1);
    bool fitted = false;
    std::array<T, 3> curv{T(0), T(0), T(0)};
    if (sense != 0) {
      T a0, e;
      std::array<T, 3> a;
      affine_fit(b.G[last_open], a0, a, e, !planar);
      e = round_outward(e, true);
      std::array<T, 3> na{-a[0], -a[1], -a[2]};
      if (sense > 0) {
        // a . s >= e - a0 is -a . s <= a0 - e.
        f_lo = halfspace_share(na, T(a0 - e));
        f_hi = halfspace_share(na, T(a0 + e));
      } else {
        f_lo = halfspace_share(a, T(-a0 - e));
        f_hi = halfspace_share(a, T(-a0 + e));
      }
      fitted = true;
      curv = curvature_along(b.G[last_open]);
    }
    T dmin, dmax;
    auto part = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
      integrand_range(cell, Q, p, wmin, wmax, dmin, dmax);
      lo = b.vol * (f_lo * dmin + (f_hi - f_lo) * std::min(T(0), dmin));
      hi = b.vol * (f_lo * dmax + (f_hi - f_lo) * std::max(T(0), dmax));
      if (plant == vrep_testing::EnclosurePlant::drop_crossing) lo = hi = T(0);
      return std::make_pair(T(b.vol * (f_hi - f_lo) * std::max(T(-dmin), dmax)), T(b.vol * f_lo * (dmax - dmin)));
    };
    const auto [slab, density] = part(b.N, 4, b.vlo, b.vhi);
    for (std::size_t k = 0; k < K; ++k) part(b.Q[k], cell.power, b.mlo[k], b.mhi[k]);
    // Across the cut where the fit's error (the part's slab) dominates, else where the
    // integrand varies most.
    if (fitted && density < slab && (T(0) < curv[0] || T(0) < curv[1] || T(0) < curv[2])) {
      // Across the surface's curvature; where G is monotone along k (the surface a graph over
      // the other two directions, leaving the box through a face across k), not across k.
      // (Where the graph could not be built along k, the surface is steep over the face:
      // halve the face where G varies most.)
      b.dir = -1;
      for (int d = 0; d < 3; ++d)
        if (d != graph.monotone && (b.dir < 0 || curv[b.dir] < curv[d])) b.dir = d;
      // Unless G bends most along k itself (the box long across the surface): the fit's error
      // then shrinks only when k is cut. The steepest direction only while its curvature is
      // comparable (the fit's error comes from the curvature).
      if (graph.monotone >= 0 && T(4) * curv[b.dir] < curv[graph.monotone]) b.dir = graph.monotone;
      else if (graph.steepest >= 0 && curv[b.dir] <= T(4) * curv[graph.steepest]) b.dir = graph.steepest;
    } else if (!fitted && density < slab) {
      // Several surfaces (or one the formula does not simply follow): where they vary most.
      T best(-1);
      for (std::size_t l = 0; l < b.G.size(); ++l) {
        if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
        T gmin, gmax;
        coefficient_range(b.G[l], gmin, gmax);
        const T scale = std::max(T(-gmin), gmax);
        const auto var = variation_along(b.G[l]);
        for (int d = 0; d < 3; ++d) {
          if (b.G[l].deg[d] == 0 || !(T(0) < scale)) continue;
          const T v = var[d] * b.G[l].scale / scale;
          if (best < v) {
            best = v;
            b.dir = d;
          }
        }
      }
    } else b.dir = density_direction(b);
  }

  void add_bounds(const Box& b, bool sub) {
    Cell& cell = C[b.cell];
    if (sub) {
      cell.vlo -= b.vlo;
      cell.vhi -= b.vhi;
      for (std::size_t k = 0; k < K; ++k) {
        cell.mlo[k] -= b.mlo[k];
        cell.mhi[k] -= b.mhi[k];
      }
    } else {
      cell.vlo += b.vlo;
      cell.vhi += b.vhi;
      for (std::size_t k = 0; k < K; ++k) {
        cell.mlo[k] += b.mlo[k];
        cell.mhi[k] += b.mhi[k];
      }
    }
    // Exact box integrals with unlike denominators make the sums grow by digits with every box
    // (and every addition a gcd of that size): past 256 bits a sum is rounded outward to 96 bits.
    // It stays a bound of the boxes it holds, also after a box's own bounds are taken out again.
    cell.vlo = round_dyadic(cell.vlo, false, 96, 256);
    cell.vhi = round_dyadic(cell.vhi, true, 96, 256);
    for (std::size_t k = 0; k < K; ++k) {
      cell.mlo[k] = round_dyadic(cell.mlo[k], false, 96, 256);
      cell.mhi[k] = round_dyadic(cell.mhi[k], true, 96, 256);
    }
  }

  // The two parts of b across b.dir at 1/2 (or at b.at for a parameter plane).
  void split(Box& b, Box* c) {
    const int dir = b.dir;
    const bool half = b.at == T(0);
    const T t = half ? T(1) / T(2) : b.at;
    for (int h = 0; h < 2; ++h) {
      c[h].cell = b.cell;
      c[h].lt = b.lt;
      c[h].vol = h == 0 ? T(b.vol * t) : T(b.vol * (T(1) - t));
      c[h].splits = b.splits;
      c[h].splits[dir] = static_cast<unsigned char>(std::min(255, b.splits[dir] + 1));
      c[h].G.resize(b.G.size());
      c[h].Q.resize(K);
      c[h].mlo.assign(K, T(0));
      c[h].mhi.assign(K, T(0));
    }
    auto cut = [&](const SBern<T>& x, SBern<T>& l, SBern<T>& r) { std::tie(l, r) = half ? split_half(x, dir) : split_at(x, dir, t); };
    for (std::size_t l = 0; l < b.G.size(); ++l)
      if (b.lt[l] == Truth::mixed && !b.G[l].c.empty()) cut(b.G[l], c[0].G[l], c[1].G[l]);
    cut(b.N, c[0].N, c[1].N);
    cut(b.W, c[0].W, c[1].W);
    for (std::size_t k = 0; k < K; ++k) cut(b.Q[k], c[0].Q[k], c[1].Q[k]);
  }

  // The target: the summed widths within rel_width of the summed volumes' lower bound (the
  // moments' within rel_width of it times their scales).
  bool reached() {
    T low(0), wv(0);
    std::vector<T> wm(K, T(0));
    for (const auto& c : C) {
      low += T(0) < c.vlo ? c.vlo : c.vhi < T(0) ? T(-c.vhi) : T(0);
      wv += c.vhi - c.vlo;
      for (std::size_t k = 0; k < K; ++k) wm[k] += c.mhi[k] - c.mlo[k];
    }
    const T budget = rel_width * low;
    if (budget < wv) return false;
    for (std::size_t k = 0; k < K; ++k)
      if (budget * out.scale[k] < wm[k]) return false;
    return true;
  }

  // The cells' enclosures: oriented, rounded outward, summed.
  void finish() {
    out.reached = reached();
    out.volume.resize(C.size());
    out.moment.assign(C.size(), std::vector<VolumeEnclosure<T>>(K));
    out.total_moment.assign(K, VolumeEnclosure<T>{});
    for (std::size_t c = 0; c < C.size(); ++c) {
      Cell& cell = C[c];
      // Negatively oriented (det J < 0): the volume is the integral's magnitude, the moments flip.
      // The orientation is decided exactly (not from the enclosure, which may straddle 0 while
      // the integral is negative); then the volume is at least 0. Orientation unknown (N's integral
      // over the first piece 0, so not a regular cell): whichever sign the integral has.
      auto flip = [&]() {
        std::swap(cell.vlo, cell.vhi);
        cell.vlo = -cell.vlo;
        cell.vhi = -cell.vhi;
        for (std::size_t k = 0; k < K; ++k) {
          std::swap(cell.mlo[k], cell.mhi[k]);
          cell.mlo[k] = -cell.mlo[k];
          cell.mhi[k] = -cell.mhi[k];
        }
      };
      if (cell.orientation < 0) flip();
      if (cell.orientation != 0) {
        if (cell.vlo < T(0)) cell.vlo = T(0);
      } else if (cell.vhi < T(0) || (cell.vhi == T(0) && cell.vlo < T(0))) {
        flip();
      } else if (cell.vlo < T(0)) {
        // The integral's sign undecided: its magnitude and the moments of either sign.
        cell.vhi = std::max(cell.vhi, T(-cell.vlo));
        cell.vlo = T(0);
        for (std::size_t k = 0; k < K; ++k) {
          const T lo = std::min(cell.mlo[k], T(-cell.mhi[k])), hi = std::max(cell.mhi[k], T(-cell.mlo[k]));
          cell.mlo[k] = lo;
          cell.mhi[k] = hi;
        }
      }
      // Sums of exact box integrals can carry thousands of digits: what is not exact is rounded
      // outward here (about 64 significant bits once past 128), so the totals stay short too.
      if (cell.vlo != cell.vhi) {
        cell.vlo = round_outward(cell.vlo, false);
        cell.vhi = round_outward(cell.vhi, true);
      }
      for (std::size_t k = 0; k < K; ++k)
        if (cell.mlo[k] != cell.mhi[k]) {
          cell.mlo[k] = round_outward(cell.mlo[k], false);
          cell.mhi[k] = round_outward(cell.mhi[k], true);
        }
      if (plant == vrep_testing::EnclosurePlant::shrink_last_bit) cell.vhi -= last_bit_unit(cell.vhi);
      out.volume[c] = {cell.vlo, cell.vhi, cell.boxes};
      out.total.lower += cell.vlo;
      out.total.upper += cell.vhi;
      out.total.boxes += cell.boxes;
      for (std::size_t k = 0; k < K; ++k) {
        out.moment[c][k] = {cell.mlo[k], cell.mhi[k], cell.boxes};
        out.total_moment[k].lower += cell.mlo[k];
        out.total_moment[k].upper += cell.mhi[k];
        out.total_moment[k].boxes += cell.boxes;
      }
    }
    auto outward = [](VolumeEnclosure<T>& e) {
      if (e.lower == e.upper) return;
      e.lower = round_outward(e.lower, false);
      e.upper = round_outward(e.upper, true);
    };
    outward(out.total);
    for (auto& e : out.total_moment) outward(e);
  }
};

}  // namespace vrep_detail

template <class T>
IntegralEnclosures<T> integral_enclosures(const std::vector<IntegrandCell<T>>& cells, const std::vector<int>& components, const T& rel_width,
                                          std::size_t max_boxes, const Limits& limits) {
  return vrep_detail::IntegralRun<T>(cells, components, rel_width, max_boxes, limits).run();
}

template <class T>
VolumeEnclosure<T> trimmed_volume(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits, const T& rel_width) {
  return integral_enclosures<T>({IntegrandCell<T>{&V, &trim, nullptr}}, {}, rel_width, max_boxes, limits).volume.front();
}

template <class T>
MomentEnclosure<T> trimmed_moment(const BSpline<T>& V, const Region<T>& trim, int coordinate, std::size_t max_boxes, const Limits& limits,
                                  const T& rel_width) {
  if (coordinate < 0) throw ValidationError("coordinate", "is negative", "give 0 <= coordinate < q");
  const auto r = integral_enclosures<T>({IntegrandCell<T>{&V, &trim, nullptr}}, {coordinate}, rel_width, max_boxes, limits);
  return {r.volume.front(), r.moment.front().front()};
}

template <class T>
MomentEnclosure<T> trimmed_field_integral(const BSpline<T>& V, const Region<T>& trim, const BSpline<T>& field, int component,
                                          std::size_t max_boxes, const Limits& limits, const T& rel_width) {
  const auto r = integral_enclosures<T>({IntegrandCell<T>{&V, &trim, &field}}, {component}, rel_width, max_boxes, limits);
  return {r.volume.front(), r.moment.front().front()};
}

}  // namespace splinex
