// Certified regularity (vrep/model/regularity.hpp): the templates, instantiated in vrep/instances.cpp.
#pragma once
#include <array>
#include <deque>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "bernstein/tensor.hpp"
#include "compose/compose.hpp"
#include "spline/bezier.hpp"
#include "spline/knots.hpp"
#include "vrep/model/brackets.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/model/regularity.hpp"

namespace splinex {

namespace vrep_detail {


/// Homogeneous coordinate c of a Bezier trivariate piece: c = 0 the weight W (1 if polynomial),
/// c = 1..3 the geometry w x, w y, w z.
template <class T>
Bernstein<T> homogeneous(const BSpline<T>& piece, int c) {
  return bern_coordinate(piece, c == 0 ? piece.q : c - 1);
}

template <class T>
Bernstein<T> derivative(const Bernstein<T>& b, int l) {
  return bern_derivative(b, l);
}
template <class T>
Bernstein<T> sub(Bernstein<T> a, const Bernstein<T>& b) {
  return bern_sub(std::move(a), b);
}
template <class T>
Bernstein<T> add(Bernstein<T> a, const Bernstein<T>& b) {
  return bern_add(std::move(a), b);
}
template <class T>
Bernstein<T> mul(const Bernstein<T>& a, const Bernstein<T>& b) {
  return bern_product(a, b);
}

/// det of the 2x2 [[a, b], [c, d]].
template <class T>
Bernstein<T> det2(const Bernstein<T>& a, const Bernstein<T>& b, const Bernstein<T>& c, const Bernstein<T>& d) {
  return sub(mul(a, d), mul(b, c));
}

/// det J's numerator as a determinant: M[r][c], row r a homogeneous coordinate - (X, Y, Z) for a
/// polynomial piece (3x3, columns P_u, P_v, P_w), (W, X, Y, Z) for a rational one (4x4, columns P,
/// P_u, P_v, P_w).
template <class T>
using JacobianMatrix = std::array<std::array<Bernstein<T>, 4>, 4>;

template <class T>
JacobianMatrix<T> jacobian_matrix(const BSpline<T>& piece) {
  JacobianMatrix<T> M;
  if (!piece.is_rational()) {
    for (int r = 0; r < 3; ++r) {
      const Bernstein<T> x = homogeneous(piece, r + 1);
      for (int c = 0; c < 3; ++c) M[r][c] = derivative(x, c);
    }
    return M;
  }
  for (int r = 0; r < 4; ++r) {
    M[r][0] = homogeneous(piece, r);
    for (int c = 1; c < 4; ++c) M[r][c] = derivative(M[r][0], c - 1);
  }
  return M;
}

/// sum over t of sign[t] f[t] g[t], every f[t] of one degree vector and every g[t] of one
/// (product_sums: an exact arithmetic forms the products on integers and reduces once per
/// coefficient of the sum).
template <class T>
Bernstein<T> signed_products(const std::vector<const Bernstein<T>*>& f, const std::vector<const Bernstein<T>*>& g,
                             const std::vector<T>& sign) {
  Bernstein<T> h;
  h.deg.resize(f[0]->deg.size());
  for (std::size_t l = 0; l < h.deg.size(); ++l) h.deg[l] = f[0]->deg[l] + g[0]->deg[l];
  h.c.assign(detail::tensor_size(h.deg), T(0));
  product_sums(f, g, sign, std::vector<T>(f.size(), T(1)), 1, h.c);
  return h;
}

/// det J's numerator on integers (an arithmetic with product_sums): the same determinant as
/// jacobian_numerator's, expanded so that the factors of every sum share their degrees - along
/// the column of u-derivatives (polynomial), along columns (0, 1) (rational) - with one reduction
/// per sum instead of one per product and per addition.
template <class T>
Bernstein<T> jacobian_numerator_fused(const BSpline<T>& piece) {
  const T one(1), minus(-1);
  const JacobianMatrix<T> M = jacobian_matrix(piece);
  if (!piece.is_rational()) {
    // det = sum over r of (-1)^r M[r][0] (M[s][1] M[t][2] - M[t][1] M[s][2]), {s, t} the other rows.
    Bernstein<T> minor[3];
    for (int r = 0; r < 3; ++r) {
      const int s = r == 0 ? 1 : 0, t = r == 2 ? 1 : 2;
      minor[r] = signed_products<T>({&M[s][1], &M[t][1]}, {&M[t][2], &M[s][2]}, {one, minus});
    }
    return signed_products<T>({&M[0][0], &M[1][0], &M[2][0]}, {&minor[0], &minor[1], &minor[2]}, {one, minus, one});
  }
  // Laplace along columns (0, 1), as jacobian_numerator; each 2x2 minor pairs factors of one column.
  Bernstein<T> left[6], right[6];
  std::vector<const Bernstein<T>*> f, g;
  std::vector<T> sign;
  int k = 0;
  for (int r1 = 0; r1 < 4; ++r1)
    for (int r2 = r1 + 1; r2 < 4; ++r2, ++k) {
      int s1 = -1, s2 = -1;
      for (int r = 0; r < 4; ++r)
        if (r != r1 && r != r2) (s1 < 0 ? s1 : s2) = r;
      left[k] = signed_products<T>({&M[r1][0], &M[r2][0]}, {&M[r2][1], &M[r1][1]}, {one, minus});
      right[k] = signed_products<T>({&M[s1][2], &M[s2][2]}, {&M[s2][3], &M[s1][3]}, {one, minus});
      f.push_back(&left[k]);
      g.push_back(&right[k]);
      sign.push_back((r1 + r2 + 1) % 2 != 0 ? minus : one);
    }
  return signed_products(f, g, sign);
}

/// det J's numerator of a Bezier piece in local coordinates, product by product (along row 0;
/// rational: along columns (0, 1)): in floating point this fixes the order of the roundings.
template <class T>
Bernstein<T> jacobian_numerator_expanded(const BSpline<T>& piece) {
  const JacobianMatrix<T> M = jacobian_matrix(piece);
  if (!piece.is_rational()) {
    Bernstein<T> det = mul(M[0][0], det2(M[1][1], M[1][2], M[2][1], M[2][2]));
    det = sub(det, mul(M[0][1], det2(M[1][0], M[1][2], M[2][0], M[2][2])));
    return add(det, mul(M[0][2], det2(M[1][0], M[1][1], M[2][0], M[2][1])));
  }
  // Laplace expansion along columns (0, 1): sum over row pairs r1 < r2 of
  // (-1)^(r1 + r2 + 1) minor(r1, r2; 0, 1) minor(complement; 2, 3).
  Bernstein<T> det;
  bool first = true;
  for (int r1 = 0; r1 < 4; ++r1)
    for (int r2 = r1 + 1; r2 < 4; ++r2) {
      int s1 = -1, s2 = -1;
      for (int r = 0; r < 4; ++r)
        if (r != r1 && r != r2) (s1 < 0 ? s1 : s2) = r;
      Bernstein<T> term = mul(det2(M[r1][0], M[r1][1], M[r2][0], M[r2][1]), det2(M[s1][2], M[s1][3], M[s2][2], M[s2][3]));
      if ((r1 + r2 + 1) % 2 != 0)
        for (auto& x : term.c) x = -x;
      det = first ? term : add(det, term);
      first = false;
    }
  return det;
}

/// det J's numerator of a Bezier piece in local coordinates: jacobian_numerator_fused in an
/// arithmetic with product_sums (the same exact polynomial), jacobian_numerator_expanded otherwise.
template <class T>
Bernstein<T> jacobian_numerator(const BSpline<T>& piece) {
  if constexpr (FractionFreeProductSums<T>)
    return jacobian_numerator_fused(piece);
  else
    return jacobian_numerator_expanded(piece);
}

/// The two halves of b at t_l = 1/2.
template <class T>
std::pair<Bernstein<T>, Bernstein<T>> split_half(const Bernstein<T>& b, int l) {
  return bern_split(b, l, T(1) / T(2));
}

/// The halves of a subdivision box across its widest parameter side (the first of equal ones):
/// each keeps the box's other members, takes half of its range [lo, hi], and every leaf
/// polynomial the box carries (G[l]; an empty one is not carried and stays empty) is split there
/// (split_half). Used by the trimmed classification and the trimmed topology's covers.
template <class Box>
void halve_widest(Box x, Box (&c)[2]) {
  int dir = 0;
  for (int d = 1; d < static_cast<int>(x.lo.size()); ++d)
    if ((x.hi[dir] - x.lo[dir]) < (x.hi[d] - x.lo[d])) dir = d;
  using T = std::decay_t<decltype(x.lo[0])>;
  const T mid = (x.lo[dir] + x.hi[dir]) / T(2);
  auto G = std::move(x.G);
  x.G.clear();
  c[0] = x;
  c[1] = std::move(x);
  c[0].hi[dir] = mid;
  c[1].lo[dir] = mid;
  for (Box& h : c) h.G.resize(G.size());
  for (std::size_t l = 0; l < G.size(); ++l)
    if (!G[l].c.empty()) std::tie(c[0].G[l], c[1].G[l]) = split_half(G[l], dir);
}

/// det J's numerator degrees, checked against the limits before any work: the degree limit per
/// direction and, for all pieces together, the control-point limit. Returns the coefficients of
/// one piece's numerator.
template <class T>
std::size_t check_jacobian_size(const BSpline<T>& V, const Limits& limits) {
  const int extra = V.is_rational() ? 4 : 3;
  std::size_t per_piece = 1, pieces = 1;
  for (int d = 0; d < 3; ++d) {
    limits.check_degree(static_cast<long>(extra) * V.degrees[d] - 1, "degrees");
    per_piece *= static_cast<std::size_t>(extra * V.degrees[d]);
    pieces *= breakpoints(V.knots[d], V.degrees[d], V.count(d)).size() - 1;
  }
  limits.check_count(per_piece * pieces, "det J");
  return per_piece;
}

/// What det J needs, checked before any work: a valid trivariate in R^3 of degree >= 1 in every
/// direction (degree 0: det J is 0, refused), its sizes within the limits.
template <class T>
void require_jacobian_input(const BSpline<T>& V, const Limits& limits) {
  validate(V, limits);
  if (V.dim() != 3 || V.q < 3)
    throw ValidationError("degrees", "det J needs a trivariate with points in R^3", "give a spline with three directions and q >= 3");
  for (int d = 0; d < 3; ++d)
    if (V.degrees[d] == 0) throw ValidationError("degrees", "has degree 0 in a direction: det J is 0", "elevate it first");
  check_jacobian_size(V, limits);
}

/// A parameter box of a trivariate with det J's numerator on it in Bernstein form: the box of the
/// subdivisions that decide det J's sign (certify_regularity, certify_cell_shape).
template <class T>
struct JacobianBox {
  Bernstein<T> N;
  std::array<T, 3> lo, hi;

  /// f(i, x) for each corner coefficient N.c[i] - the numerator's exact value at the box's
  /// corner x - in storage order, until f returns false.
  template <class F>
  void for_each_corner(F&& f) const {
    std::vector<int> idx(3);
    for (std::size_t i = 0; i < N.c.size(); ++i) {
      detail::unflatten(i, N.deg, idx);
      bool corner = true;
      for (int d = 0; d < 3; ++d) corner = corner && (idx[d] == 0 || idx[d] == N.deg[d]);
      if (!corner) continue;
      std::vector<T> x(3);
      for (int d = 0; d < 3; ++d) x[d] = idx[d] == 0 ? lo[d] : hi[d];
      if (!f(i, x)) return;
    }
  }
};

/// The roots of those subdivisions: one box per Bezier piece of V.
template <class T>
std::vector<JacobianBox<T>> jacobian_boxes(const BSpline<T>& V, const Limits& limits) {
  const BezierForm<T> F = bezier_form(V, limits);
  std::vector<JacobianBox<T>> out;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    JacobianBox<T> b{jacobian_numerator(pc.spline), {}, {}};
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = pc.box[d].first;
      b.hi[d] = pc.box[d].second;
    }
    out.push_back(std::move(b));
  }
  return out;
}

/// The eight children of a box at its midpoints, emitted in the order of splitting direction 0,
/// then 1, then 2 (bern_halves: de Casteljau at 1/2, on integers in exact arithmetic).
/// `keep_upper_u` false loses the children above the midpoint of u (the planted bug of
/// vrep/model/planted.hpp, tests only).
template <class T, class Emit>
void split_octants(JacobianBox<T>&& b, Emit&& emit, bool keep_upper_u = true) {
  auto parts = bern_halves(b.N);  // part K: side (K >> (2 - d)) & 1 in direction d
  std::array<T, 3> mid;
  for (int d = 0; d < 3; ++d) mid[d] = (b.lo[d] + b.hi[d]) / T(2);
  for (std::size_t K = 0; K < parts.size(); ++K) {
    if (!keep_upper_u && (K >> 2) & 1) continue;
    JacobianBox<T> c{std::move(parts[K]), b.lo, b.hi};
    for (int d = 0; d < 3; ++d) ((K >> (2 - d)) & 1 ? c.lo[d] : c.hi[d]) = mid[d];
    emit(std::move(c));
  }
}

}  // namespace vrep_detail

template <class T>
BSpline<T> jacobian_determinant(const BSpline<T>& V, const Limits& limits) {
  vrep_detail::require_jacobian_input(V, limits);
  const BezierForm<T> F = bezier_form(V, limits);
  const int extra = V.is_rational() ? 4 : 3;
  BSpline<T> J;
  J.q = 1;
  for (int d = 0; d < 3; ++d) J.degrees.push_back(extra * V.degrees[d] - 1);
  for (int d = 0; d < 3; ++d) {
    std::vector<T> U;
    for (const auto& b : F.breaks[d]) U.insert(U.end(), J.degrees[d] + 1, b);
    J.knots.push_back(U);
  }
  std::size_t seg[3], cnt[3];
  for (int d = 0; d < 3; ++d) {
    seg[d] = F.breaks[d].size() - 1;
    cnt[d] = seg[d] * (J.degrees[d] + 1);
  }
  J.points.assign(cnt[0] * cnt[1] * cnt[2], T(0));
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    const auto N = vrep_detail::jacobian_numerator(pc.spline);
    T scale(1);
    for (int d = 0; d < 3; ++d) scale = scale * (pc.box[d].second - pc.box[d].first);
    const std::size_t k0 = k % seg[0], k1 = (k / seg[0]) % seg[1], k2 = k / (seg[0] * seg[1]);
    std::vector<int> idx(3);
    for (std::size_t i = 0; i < N.c.size(); ++i) {
      detail::unflatten(i, N.deg, idx);
      const std::size_t g0 = k0 * (J.degrees[0] + 1) + idx[0], g1 = k1 * (J.degrees[1] + 1) + idx[1],
                        g2 = k2 * (J.degrees[2] + 1) + idx[2];
      J.points[g0 + cnt[0] * (g1 + cnt[1] * g2)] = N.c[i] / scale;
    }
  }
  return J;
}

template <class T>
RegularityReport<T> certify_regularity(const BSpline<T>& V, int max_levels, const Limits& limits) {
  validate(V, limits);
  if (V.dim() != 3 || V.q < 3)
    throw ValidationError("degrees", "regularity needs a trivariate with points in R^3", "give a spline with three directions and q >= 3");
  if (max_levels < 0 || max_levels > 30) throw ValidationError("levels", "must be 0..30", "give the subdivision depth");
  RegularityReport<T> rep;
  for (int d = 0; d < 3; ++d)
    if (V.degrees[d] == 0) {
      rep.verdict = Verdict::refuted("degree 0 in direction " + std::to_string(d) + ": det J = 0 everywhere");
      rep.point = {V.domain_lo(0), V.domain_lo(1), V.domain_lo(2)};
      return rep;
    }
  // Memory: the boxes alive at once hold at most the control-point limit of coefficients.
  const std::size_t per_piece = vrep_detail::check_jacobian_size(V, limits);
  Budget budget;
  budget.max_depth = max_levels;
  budget.max_alive = std::max<std::size_t>(64, limits.max_control_points / per_piece);
  using Box = vrep_detail::JacobianBox<T>;
  int global = 0;
  std::vector<T> global_point;
  T global_value(0);
  std::vector<T> undecided_at;
  auto examine = [&](const Box& b, int) {
    int lo_sign = 2, hi_sign = -2, corner_lo = 2, corner_hi = -2;
    for (const auto& c : b.N.c) {
      const int s = vrep_detail::sign_of(c);
      lo_sign = std::min(lo_sign, s);
      hi_sign = std::max(hi_sign, s);
    }
    // The corners: exact values of the (local) numerator.
    bool refuted = false;
    b.for_each_corner([&](std::size_t i, const std::vector<T>& x) {
      const int s = vrep_detail::sign_of(b.N.c[i]);
      corner_lo = std::min(corner_lo, s);
      corner_hi = std::max(corner_hi, s);
      if (s == 0) {
        rep.verdict = Verdict::refuted("det J = 0 at a corner of a Bezier box");
        rep.point = x;
        rep.value = b.N.c[i];
        return !(refuted = true);
      }
      if (global == 0) {
        global = s;
        global_point = x;
        global_value = b.N.c[i];
      } else if (s != global) {
        rep.verdict = Verdict::refuted("det J changes sign");
        rep.point = x;
        rep.value = b.N.c[i];
        rep.other = global_point;
        rep.other_value = global_value;
        return !(refuted = true);
      }
      return true;
    });
    if (refuted) return Examined::refuted;
    if (lo_sign == hi_sign && lo_sign == global) return Examined::settled;  // certified on this box
    // Planted (tests only): the corners alone "certify" the box.
    if (vrep_testing::is_planted(vrep_testing::Plant::regularity_corners_only) && corner_lo == corner_hi && corner_lo == global)
      return Examined::settled;
    return Examined::split;
  };
  // Subdivide at the midpoints of all three directions: 8 children (planted, tests only: the
  // children on the upper side of u are lost).
  const bool keep_upper_u = !vrep_testing::is_planted(vrep_testing::Plant::regularity_drops_upper_u);
  auto split = [&](Box&& b, int, auto&& emit) { vrep_detail::split_octants(std::move(b), emit, keep_upper_u); };
  auto leave = [&](Box&& b, Left) {
    if (undecided_at.empty()) undecided_at = {(b.lo[0] + b.hi[0]) / T(2), (b.lo[1] + b.hi[1]) / T(2), (b.lo[2] + b.hi[2]) / T(2)};
  };
  const Subdivision run =
      subdivide(vrep_detail::jacobian_boxes(V, limits), Walk{Order::breadth_first, 8, false}, budget, examine, split, leave);
  rep.boxes = run.examined;
  rep.levels = run.deepest;
  if (run.stop == Subdivision::Stop::refuted) return rep;
  const bool undecided = run.left > 0, budget_hit = run.left_alive > 0;
  if (undecided) {
    rep.point = undecided_at;
    rep.verdict = Verdict::undecided(budget_hit ? "Bernstein coefficients of both signs when the boxes reached the memory budget (" +
                                  std::to_string(budget.max_alive) + " boxes; raise --max-control-points)"
                            : "Bernstein coefficients of both signs after " + std::to_string(max_levels) + " subdivision levels");
    return rep;
  }
  rep.verdict = Verdict::proved(global > 0 ? "det J > 0: every Bernstein coefficient positive" : "det J < 0: every Bernstein coefficient negative");
  rep.sign = vrep_testing::is_planted(vrep_testing::Plant::regularity_sign_flipped) ? -global : global;  // (planted: tests only)
  return rep;
}

}  // namespace splinex
