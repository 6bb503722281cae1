#pragma once
#include <algorithm>
#include <string>

#include "bernstein/tensor.hpp"
#include "compose/compose.hpp"
#include "spline/arith.hpp"
#include "spline/basis_sum.hpp"
#include "spline/bernstein.hpp"
#include "spline/bezier.hpp"
#include "spline/elevate.hpp"
#include "spline/evaluate.hpp"

namespace splinex {
namespace detail {

/// The cell index c of breakpoints bp with bp[c] <= x < bp[c+1], the last cell closed.
template <class T>
std::size_t cell_index(const std::vector<T>& bp, const T& x) {
  const auto less = [](const T& a, const T& b) { return a < b; };
  std::size_t c = static_cast<std::size_t>(std::upper_bound(bp.begin(), bp.end(), x, less) - bp.begin());
  c = c == 0 ? 0 : c - 1;
  return std::min(c, bp.size() - 2);
}

template <class T>
std::pair<T, T> hull_range(const BSpline<T>& P, int coord) {
  T lo = P.points[coord], hi = P.points[coord];
  for (std::size_t i = 1; i < P.size(); ++i) {
    const T& x = P.points[i * P.q + coord];
    if (x < lo) lo = x;
    if (hi < x) hi = x;
  }
  return {lo, hi};
}

/// DomainError naming how far the control-point hull [lo, hi] of coordinate j leaves [bp.front(), bp.back()].
template <class T>
void check_hull_in_domain(const std::pair<T, T>& hull, const std::vector<T>& bp, int j, const std::string& fix) {
  const auto& [lo, hi] = hull;
  if (!(lo < bp.front()) && !(bp.back() < hi)) return;
  T far = lo < bp.front() ? T(bp.front() - lo) : T(0);
  if (bp.back() < hi && far < T(hi - bp.back())) far = hi - bp.back();
  throw DomainError("inner", "control points leave the outer domain in coordinate " + std::to_string(j) + " (by up to " +
                                 ArithTraits<T>::to_string(far) + ")",
                    fix);
}

/// The inner spline's points must live in the outer spline's parameter space.
template <class T>
void check_composable(const BSpline<T>& outer, const BSpline<T>& inner) {
  if (inner.q != outer.dim())
    throw ValidationError("inner", "has points in R^" + std::to_string(inner.q) + " but the outer spline has " +
                                       std::to_string(outer.dim()) + " parameters",
                          "give the inner spline one coordinate per parameter of the outer one");
}

template <class T>
void check_bezier(const BSpline<T>& S, const std::string& field) {
  for (int d = 0; d < S.dim(); ++d)
    if (S.count(d) != static_cast<std::size_t>(S.degrees[d]) + 1 || !is_clamped(S.knots[d], S.degrees[d], S.count(d)))
      throw UsageError(field, "is not a single Bezier piece in direction " + std::to_string(d),
                       "extract its Bezier pieces first (extract-bezier), or compose the B-splines");
}

/// Solves the Bernstein interpolation at nodes i/D along direction `dir` of a tensor of values
/// with `width` values per point, in place. Gaussian elimination with partial pivoting (by
/// magnitude; in exact arithmetic any non-zero pivot is exact).
template <class T>
void bernstein_solve_direction(std::vector<T>& V, const std::vector<int>& deg, int dir, std::size_t width) {
  const int D = deg[dir];
  if (D == 0) return;
  const std::size_t N = D + 1;
  /// M[i][j] = B_j^D(i/D)
  std::vector<std::vector<T>> M(N, std::vector<T>(N));
  for (std::size_t i = 0; i < N; ++i) {
    const T t = T(static_cast<long>(i)) / T(D), s = T(1) - t;
    for (std::size_t j = 0; j < N; ++j) {
      T v = binomial<T>(D, static_cast<int>(j));
      for (std::size_t a = 0; a < j; ++a) v *= t;
      for (std::size_t a = j; a < N - 1; ++a) v *= s;
      M[i][j] = v;
    }
  }
  std::size_t before = width, after = 1;
  for (int l = 0; l < dir; ++l) before *= deg[l] + 1;
  for (std::size_t l = dir + 1; l < deg.size(); ++l) after *= deg[l] + 1;
  /// Factor once (LU with row permutation), then solve for every fibre: right-hand sides are the
  /// `before` contiguous values at each node.
  std::vector<std::size_t> perm(N);
  for (std::size_t i = 0; i < N; ++i) perm[i] = i;
  auto mag = [](const T& x) { return x < T(0) ? T(-x) : x; };
  for (std::size_t col = 0; col < N; ++col) {
    std::size_t piv = col;
    for (std::size_t r = col + 1; r < N; ++r)
      if (mag(M[piv][col]) < mag(M[r][col])) piv = r;
    std::swap(M[col], M[piv]);
    std::swap(perm[col], perm[piv]);
    for (std::size_t r = col + 1; r < N; ++r) {
      M[r][col] /= M[col][col];
      for (std::size_t c = col + 1; c < N; ++c) M[r][c] -= M[r][col] * M[col][c];
    }
  }
  std::vector<T> rhs(N * before);
  for (std::size_t b = 0; b < after; ++b) {
    T* base = V.data() + b * N * before;
    for (std::size_t i = 0; i < N; ++i)
      std::copy(base + perm[i] * before, base + (perm[i] + 1) * before, rhs.begin() + i * before);
    for (std::size_t i = 0; i < N; ++i)  // forward (unit lower)
      for (std::size_t j = 0; j < i; ++j)
        for (std::size_t c = 0; c < before; ++c) rhs[i * before + c] -= M[i][j] * rhs[j * before + c];
    for (std::size_t ii = N; ii-- > 0;) {  // backward
      for (std::size_t j = ii + 1; j < N; ++j)
        for (std::size_t c = 0; c < before; ++c) rhs[ii * before + c] -= M[ii][j] * rhs[j * before + c];
      for (std::size_t c = 0; c < before; ++c) rhs[ii * before + c] /= M[ii][ii];
    }
    std::copy(rhs.begin(), rhs.end(), base);
  }
}

}  // namespace detail

template <class T>
std::vector<int> composed_degrees(const BSpline<T>& outer, const BSpline<T>& inner) {
  int E = 0;
  for (int e : outer.degrees) E += e;
  std::vector<int> D;
  for (int d : inner.degrees) D.push_back(d * E);
  return D;
}

template <class T>
std::vector<T> evaluate_bezier_anywhere(const BSpline<T>& B, const std::vector<T>& u) {
  const int n = B.dim();
  std::vector<std::vector<T>> basis(n);
  for (int j = 0; j < n; ++j) {
    const int e = B.degrees[j];
    const T t = (u[j] - B.domain_lo(j)) / (B.domain_hi(j) - B.domain_lo(j)), s = T(1) - t;
    basis[j].resize(e + 1);
    for (int i = 0; i <= e; ++i) {
      T v = detail::binomial<T>(e, i);
      for (int a = 0; a < i; ++a) v *= t;
      for (int a = i; a < e; ++a) v *= s;
      basis[j][i] = v;
    }
  }
  std::vector<std::size_t> span(n);
  std::vector<const std::vector<T>*> ptr(n);
  for (int j = 0; j < n; ++j) {
    span[j] = B.degrees[j];
    ptr[j] = &basis[j];
  }
  return basis_sum(B, span, ptr);
}

template <class T>
Homogeneous<T> compose_bezier_homogeneous(const BSpline<T>& outer, const BSpline<T>& inner, CompositionMethod method,
                                          const Limits& limits) {
  detail::check_bezier(outer, "outer");
  detail::check_bezier(inner, "inner");
  detail::check_composable(outer, inner);
  const int k = inner.dim(), n = outer.dim();
  const std::vector<int> D = composed_degrees(outer, inner);
  int E = 0;
  for (int e : outer.degrees) E += e;
  std::size_t total = 1;
  for (int l = 0; l < k; ++l) {
    limits.check_degree(D[l], "inner");
    total = checked_product(total, static_cast<std::size_t>(D[l]) + 1, limits, "inner");
  }
  const bool rational = inner.is_rational() || outer.is_rational();
  const std::size_t q = outer.q, qq = q + (rational ? 1 : 0);
  std::vector<T> H(total * qq, T(0));  // homogeneous result, direction 0 fastest, coordinates fastest

  if (method == CompositionMethod::symbolic) {
    /// Homogeneous inner components: W and the local coordinates U_j = (X_j - a_j W)/(b_j - a_j).
    const std::size_t ns = inner.size();
    Bernstein<T> W{inner.degrees, std::vector<T>(ns, T(1))};
    if (inner.is_rational()) W.c = inner.weights;
    std::vector<std::vector<Bernstein<T>>> basis(n);  // basis[j][i] = B^{e_j}_i(u_j(S)) * W^{e_j}
    for (int j = 0; j < n; ++j) {
      const T a = outer.domain_lo(j), w = outer.domain_hi(j) - a;
      Bernstein<T> U{inner.degrees, std::vector<T>(ns)}, V{inner.degrees, std::vector<T>(ns)};
      for (std::size_t i = 0; i < ns; ++i) {
        const T X = inner.points[i * inner.q + j] * (inner.is_rational() ? inner.weights[i] : T(1));
        U.c[i] = (X - a * W.c[i]) / w;
        V.c[i] = W.c[i] - U.c[i];
      }
      const int e = outer.degrees[j];
      std::vector<Bernstein<T>> PU{Bernstein<T>{std::vector<int>(k, 0), {T(1)}}}, PV = PU;
      for (int i = 1; i <= e; ++i) {
        PU.push_back(bern_product(PU.back(), U));
        PV.push_back(bern_product(PV.back(), V));
      }
      for (int i = 0; i <= e; ++i) {
        Bernstein<T> b = bern_product(PU[i], PV[e - i]);
        const T c = detail::binomial<T>(e, i);
        for (auto& x : b.c) x *= c;
        basis[j].push_back(std::move(b));
      }
    }
    /// Sum over the outer control points: prod_j basis[j][I_j] times (w_I C_I, w_I).
    /// In batches of at most 64 outer points (the terms of a batch are kept; the sum runs in the
    /// order of the points, see weighted_sums). The last factor's product is fused into the sum
    /// (product_sums: in exact arithmetic the products' coefficients are never formed).
    const std::size_t nt = outer.size(), batch = 64;
    std::vector<int> I(n);
    std::vector<Bernstein<T>> heads;  // prod_{j < n-1} basis[j][I_j], for n >= 3
    std::vector<const Bernstein<T>*> fp, gp;
    std::vector<const std::vector<T>*> tc;
    std::vector<T> w, P;  // weights; coordinates, then 1 for the weight
    for (std::size_t t0 = 0; t0 < nt; t0 += batch) {
      const std::size_t nb = std::min(batch, nt - t0);
      heads.assign(n >= 3 ? nb : 0, Bernstein<T>{});
      fp.assign(nb, nullptr);
      gp.assign(nb, nullptr);
      tc.assign(nb, nullptr);
      w.assign(nb, T(1));
      P.assign(nb * qq, T(1));
      for (std::size_t b = 0; b < nb; ++b) {
        const std::size_t t = t0 + b;
        detail::unflatten(t, outer.degrees, I);
        if (n >= 3) {
          heads[b] = basis[0][I[0]];
          for (int j = 1; j + 1 < n; ++j) heads[b] = bern_product(heads[b], basis[j][I[j]]);
          fp[b] = &heads[b];
        } else {
          fp[b] = &basis[0][I[0]];
        }
        gp[b] = &basis[n - 1][I[n - 1]];
        tc[b] = &basis[0][I[0]].c;
        if (outer.is_rational()) w[b] = outer.weights[t];
        for (std::size_t c = 0; c < q; ++c) P[b * qq + c] = outer.points[t * q + c];
      }
      if (n == 1) weighted_sums(tc, w, P, qq, H);
      else product_sums(fp, gp, w, P, qq, H);
    }
  } else {
    /// Exact values of the homogeneous composition at (D_l + 1) equispaced nodes per direction.
    std::vector<int> idx(k);
    std::vector<T> r(k), u(n);
    for (std::size_t K = 0; K < total; ++K) {
      detail::unflatten(K, D, idx);
      for (int l = 0; l < k; ++l) {
        const T lo = inner.domain_lo(l), hi = inner.domain_hi(l);
        r[l] = D[l] == 0 ? lo : lo + (hi - lo) * T(idx[l]) / T(D[l]);
      }
      const std::vector<T> s = evaluate_homogeneous(inner, r);
      const T W = inner.is_rational() ? s[inner.q] : T(1);
      if (W == T(0))
        throw DomainError("inner.weights", "the inner spline's weight vanishes inside its domain",
                          "use weights that keep the denominator non-zero");
      for (int j = 0; j < n; ++j) u[j] = s[j] / W;
      const std::vector<T> h = evaluate_bezier_anywhere(outer, u);
      T WE(1);
      for (int a = 0; a < E; ++a) WE *= W;
      for (std::size_t c = 0; c < q; ++c) H[K * qq + c] = h[c] * WE;
      if (rational) H[K * qq + q] = (outer.is_rational() ? h[q] : T(1)) * WE;
    }
    for (int l = 0; l < k; ++l) detail::bernstein_solve_direction(H, D, l, qq);
  }

  BSpline<T> R;
  R.degrees = D;
  R.q = static_cast<int>(qq);
  for (int l = 0; l < k; ++l) {
    std::vector<T> U(D[l] + 1, inner.domain_lo(l));
    U.insert(U.end(), D[l] + 1, inner.domain_hi(l));
    R.knots.push_back(std::move(U));
  }
  R.points = std::move(H);
  return Homogeneous<T>{std::move(R), rational};
}

template <class T>
BSpline<T> compose_bezier(const BSpline<T>& outer, const BSpline<T>& inner, CompositionMethod method,
                          const Limits& limits) {
  Homogeneous<T> form = compose_bezier_homogeneous(outer, inner, method, limits);
  BSpline<T>& H = form.net;
  if (!form.weighted) return std::move(H);
  const std::size_t q = outer.q, qq = q + 1;
  for (std::size_t K = 0; K < H.size(); ++K)
    if (!(T(0) < H.points[K * qq + q]))
      throw DomainError("composition.weights",
                        "the composed weights are not all positive (the inner spline leaves the outer box, or "
                        "a weight vanishes)",
                        "keep the inner spline inside the outer piece's box for rational compositions");
  std::vector<T> hom = std::move(H.points);  // set_from_homogeneous rewrites H.points
  H.q = static_cast<int>(q);
  set_from_homogeneous(H, std::move(hom), true);
  return std::move(H);
}

template <class T>
std::size_t compose_least_size(const BSpline<T>& outer, const BSpline<T>& inner, const Limits& limits) {
  detail::check_composable(outer, inner);
  const std::vector<int> D = composed_degrees(outer, inner);
  for (int l = 0; l < inner.dim(); ++l) limits.check_degree(D[l], "inner");  // every degree before any size
  std::size_t least = 1;
  for (int l = 0; l < inner.dim(); ++l) {
    const std::size_t segs = breakpoints(inner.knots[l], inner.degrees[l], inner.count(l)).size() - 1;
    least = checked_product(least, checked_product(segs, static_cast<std::size_t>(D[l]), limits, "inner") + 1, limits,
                            "inner");
  }
  return least;
}

namespace detail {

/// A Bezier piece of S whose control points reach x = hi in coordinate j from below, where T may
/// jump: a DomainError when a corner the piece owns (FindSpan's half-open rule: its left ends, and
/// its right ends only at S's domain end) lies on x, since T(S) is then no polynomial on the piece.
template <class T>
void refuse_owned_corner_at(const BezierPiece<T>& piece, const BSpline<T>& inner, int j, const T& hi) {
  const BSpline<T>& S = piece.spline;
  const int k = inner.dim();
  const std::size_t corners = std::size_t(1) << k;
  for (std::size_t m = 0; m < corners; ++m) {
    bool owned = true;
    std::size_t idx = 0, stride = 1;
    for (int l = 0; l < k; ++l) {
      const bool right = (m >> l) & 1;
      if (right && !(piece.box[l].second == inner.domain_hi(l))) owned = false;
      idx += (right ? S.count(l) - 1 : 0) * stride;
      stride *= S.count(l);
    }
    if (owned && S.points[idx * S.q + j] == hi)
      throw DomainError("inner", "a piece reaches the knot line u_" + std::to_string(j) + " = " + ArithTraits<T>::to_string(hi) +
                                     ", where the outer spline may jump, from below at a parameter it owns: T(S) "
                                     "is not one polynomial on that piece",
                        "compose with --method trimmed (Algorithm 1), or insert a knot into the inner spline there");
  }
}

}  // namespace detail

template <class T>
BSpline<T> compose(const BSpline<T>& outer, const BSpline<T>& inner, const CompositionOptions& options,
                   const Limits& limits) {
  // Before any work: the pair is composable, the composed degrees and the result's least size are
  // within the limits (C^-1 joins add one each, counted once the joins are known, before the
  // result is allocated), and both extractions are bounded.
  compose_least_size(outer, inner, limits);
  const int k = inner.dim(), n = outer.dim();
  const std::vector<int> D = composed_degrees(outer, inner);
  bezier_pieces_size(outer, limits);
  bezier_pieces_size(inner, limits);
  const auto outer_pieces = extract_bezier(outer, limits);
  const auto inner_pieces = extract_bezier(inner, limits);
  std::vector<std::vector<T>> outer_breaks(n);  // per direction
  std::vector<std::size_t> cell_stride(n);
  std::size_t st = 1;
  for (int j = 0; j < n; ++j) {
    outer_breaks[j] = breakpoints(outer.knots[j], outer.degrees[j], outer.count(j));
    cell_stride[j] = st;
    st *= outer_breaks[j].size() - 1;
  }
  /// A knot line of T where T may jump: multiplicity e_j + 1 (a C^-1 knot; degree 0 has one at
  /// every breakpoint).
  auto outer_jumps_at = [&](int j, const T& x) { return is_full_multiplicity(outer.knots[j], outer.degrees[j], x); };
  std::vector<std::vector<T>> inner_breaks(k);
  std::vector<std::size_t> piece_stride(k);
  std::size_t ss = 1;
  for (int l = 0; l < k; ++l) {
    inner_breaks[l] = breakpoints(inner.knots[l], inner.degrees[l], inner.count(l));
    piece_stride[l] = ss;
    ss *= inner_breaks[l].size() - 1;
  }
  /// Pass 1: the cell of T that holds each piece of S (exact control-point hull).
  std::vector<std::vector<std::size_t>> piece_cell(inner_pieces.size(), std::vector<std::size_t>(n));
  for (std::size_t pi = 0; pi < inner_pieces.size(); ++pi) {
    const auto& S = inner_pieces[pi].spline;
    for (int j = 0; j < n; ++j) {
      const auto hull = detail::hull_range(S, j);
      const auto& [lo, hi] = hull;
      if (!options.expand)
        detail::check_hull_in_domain(hull, outer_breaks[j], j,
                                     "move the inner spline into the outer domain, or ask for expanded pieces (--expand)");
      /// The cell c with outer_breaks[c] <= lo and hi <= outer_breaks[c+1]; clamped to the end cells when expanding.
      const std::size_t c = detail::cell_index(outer_breaks[j], lo);
      if (outer_breaks[j][c + 1] < hi && !(c + 2 >= outer_breaks[j].size() && options.expand))
        throw DomainError("inner", "a piece crosses the knot line u_" + std::to_string(j) + " = " +
                                       ArithTraits<T>::to_string(outer_breaks[j][c + 1]) + " of the outer spline",
                          "compose with --method trimmed (Algorithm 1: trimmed patches across knot lines)");
      // A piece below an interior knot line x of T that reaches x (hi == x) at a parameter it owns
      // (FindSpan's half-open rule: the left end, and the right end only at S's domain end) takes
      // the value of T's upper piece there. If T may jump at x, T(S) is then no polynomial on the
      // piece. Bernstein coefficients <= x reach x only where a corner value does.
      if (lo < hi && hi == outer_breaks[j][c + 1] && c + 2 < outer_breaks[j].size() && outer_jumps_at(j, hi))
        detail::refuse_owned_corner_at(inner_pieces[pi], inner, j, hi);
      piece_cell[pi][j] = c;
    }
  }
  /// Pass 2: the join at each interior breakpoint of S. C^0 (multiplicity D_l) where S is
  /// continuous (multiplicity <= d_l) and both sides lie in one piece of T, or in pieces between
  /// which T is continuous; else C^-1 (multiplicity D_l + 1): T(S) may jump there. The rule reads
  /// only the inputs' structure, so every arithmetic gives the same knots.
  std::vector<std::vector<char>> jump(k);
  for (int l = 0; l < k; ++l) {
    jump[l].assign(inner_breaks[l].size(), 0);
    for (std::size_t b = 1; b + 1 < inner_breaks[l].size(); ++b)
      jump[l][b] = D[l] == 0 || is_full_multiplicity(inner.knots[l], inner.degrees[l], inner_breaks[l][b]);
  }
  for (std::size_t pi = 0; pi < inner_pieces.size(); ++pi)
    for (int l = 0; l < k; ++l) {
      const std::size_t seg = (pi / piece_stride[l]) % (inner_breaks[l].size() - 1);
      if (seg + 1 >= inner_breaks[l].size() - 1) continue;
      const std::size_t other = pi + piece_stride[l];  // the neighbour across breakpoint seg + 1
      for (int j = 0; j < n && !jump[l][seg + 1]; ++j) {
        const std::size_t a = std::min(piece_cell[pi][j], piece_cell[other][j]),
                          b = std::max(piece_cell[pi][j], piece_cell[other][j]);
        for (std::size_t c = a + 1; c <= b; ++c)
          if (outer_jumps_at(j, outer_breaks[j][c])) jump[l][seg + 1] = 1;
      }
    }
  /// The result net: per direction, first control point of each segment.
  std::vector<std::vector<std::size_t>> offset(k);
  std::vector<std::size_t> result_count(k), result_stride(k);
  std::size_t total = 1;
  for (int l = 0; l < k; ++l) {
    std::size_t o = 0;
    for (std::size_t seg = 0; seg + 1 < inner_breaks[l].size(); ++seg) {
      if (seg > 0) o += static_cast<std::size_t>(D[l]) + (jump[l][seg] ? 1 : 0);
      offset[l].push_back(o);
    }
    result_count[l] = o + D[l] + 1;
    result_stride[l] = total;
    total = checked_product(total, result_count[l], limits, "inner");
  }
  limits.check_count(total, "inner");
  BSpline<T> R;
  R.degrees = D;
  R.q = outer.q;
  for (int l = 0; l < k; ++l) {
    std::vector<T> U(D[l] + 1, inner_breaks[l].front());
    for (std::size_t b = 1; b + 1 < inner_breaks[l].size(); ++b) U.insert(U.end(), D[l] + (jump[l][b] ? 1 : 0), inner_breaks[l][b]);
    U.insert(U.end(), D[l] + 1, inner_breaks[l].back());
    R.knots.push_back(std::move(U));
  }
  const std::size_t q = outer.q;
  R.points.assign(total * q, T(0));
  std::vector<char> written(total, 0);
  bool rational = false;
  for (std::size_t pi = 0; pi < inner_pieces.size(); ++pi) {
    std::size_t cell = 0;
    for (int j = 0; j < n; ++j) cell += piece_cell[pi][j] * cell_stride[j];
    const BSpline<T> piece = compose_bezier(outer_pieces[cell].spline, inner_pieces[pi].spline, options.method, limits);
    if (piece.is_rational() && !rational) {
      rational = true;
      R.weights.assign(total, T(0));
    }
    std::vector<std::size_t> seg(k);
    std::vector<int> loc(k);
    for (int l = 0; l < k; ++l) seg[l] = (pi / piece_stride[l]) % (inner_breaks[l].size() - 1);
    for (std::size_t i = 0; i < piece.size(); ++i) {
      detail::unflatten(i, piece.degrees, loc);
      std::size_t g = 0;
      for (int l = 0; l < k; ++l) g += (offset[l][seg[l]] + loc[l]) * result_stride[l];
      if (written[g]) continue;  // shared C^0 boundary: equal in exact arithmetic (proved), first piece kept in float
      written[g] = 1;
      for (std::size_t c = 0; c < q; ++c) R.points[g * q + c] = piece.points[i * q + c];
      if (piece.is_rational()) R.weights[g] = piece.weights[i];
    }
  }
  if (rational)
    for (std::size_t g = 0; g < total; ++g)
      if (!(T(0) < R.weights[g]))
        throw DomainError("composition.weights", "a piece of the composition is polynomial while another is rational",
                          "internal inconsistency; please report");
  return R;
}

}  // namespace splinex
