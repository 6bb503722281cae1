// A box cut by one trimming surface through its graph (vrep/trimmed/enclosure_impl.hpp): the graph
// s_k = phi(s_a, s_b) of a surface strictly monotone along k, its certified biquadratic stand-in
// psi with the error eps, and integrals of a polynomial over the part on one side. Internal to
// vrep/trimmed/ (included by enclosure_impl.hpp).
#pragma once
#include "vrep/trimmed/box_bounds_impl.hpp"

namespace splinex {

namespace vrep_detail {

/// A cut box's part as the region on one side of a graph s_k = phi(s_a, s_b) (a, b the other two
/// directions in order): G strictly monotone along k (its derivative's coefficients of one strict
/// sign, |dG/ds_k| >= m), phi its root along k. psi is a biquadratic through approximate roots at
/// the 3 x 3 grid of the face (Newton in short dyadics), and |phi - psi| <= eps = max |G(s,
/// psi(s))| / m (the coefficients of the composition G(s, psi(s))); psi +- eps within (0, 1) so
/// the part over every point of the face is one interval of the column.
template <class T>
struct GraphCut {
  int k = 0;
  bool below = false;  // the part is {s_k <= phi} (else {s_k >= phi})
  std::vector<Coef<T>> psi, one_minus_psi;
  std::vector<int> dpsi{2, 2};
  T psi_unit{1};
  T eps{0};
  std::array<T, 2> curvature{T(0), T(0)};  // of psi along a and b
  int monotone = -1;                       // the flattest direction where G is monotone (-1: none)
  int steepest = -1;                       // then the other direction where G varies most
  bool exits = false;                      // psi +- eps leaves [0, 1]: the part's columns are clamped
  T ext_lo{0}, ext_hi{1};                  // an interval of t holding psi +- eps, where G is monotone
  /// int int (psi - 1)_+ and (-psi)_+ over the face, each between two bounds: subdivision of
  /// psi's coefficients, exact on sub-squares wholly on one side, between 0 and the largest
  /// overshoot times the area where the level set still crosses after 8 halvings.
  std::optional<std::array<T, 4>> overshoot_;
  const std::array<T, 4>& overshoot() {
    if (overshoot_) return *overshoot_;
    std::array<T, 4> o{T(0), T(0), T(0), T(0)};
    Bernstein<T> p{dpsi, std::vector<T>(psi.size())};
    for (std::size_t i = 0; i < p.c.size(); ++i) p.c[i] = as_value<T>(psi[i]) * psi_unit;
    // f = psi - 1 (top) or -psi (bottom) on a sub-square of the given area.
    std::function<void(const Bernstein<T>&, bool, int, const T&)> walk = [&](const Bernstein<T>& q, bool top, int depth, const T& area) {
      std::vector<T> f(q.c.size());
      for (std::size_t i = 0; i < f.size(); ++i) f[i] = top ? T(q.c[i] - T(1)) : T(-q.c[i]);
      T mn = f.front(), mx = mn, sum(0);
      for (const auto& x : f) {
        if (x < mn) mn = x;
        if (mx < x) mx = x;
        sum += x;
      }
      T& lo = o[top ? 0 : 2];
      T& hi = o[top ? 1 : 3];
      if (!(T(0) < mx)) return;  // not above
      if (!(mn < T(0))) {        // wholly above: exact
        const T v = sum / T(static_cast<long>(q.c.size())) * area;
        lo += v;
        hi += v;
        return;
      }
      if (depth == 0) {
        hi += mx * area;
        return;
      }
      T va(0), vb(0);  // halve across the direction where psi varies more
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 2; ++i) {
          T d1 = q.c[i + 1 + 3 * j] - q.c[i + 3 * j], d2 = q.c[j + 3 * (i + 1)] - q.c[j + 3 * i];
          if (d1 < T(0)) d1 = -d1;
          if (d2 < T(0)) d2 = -d2;
          if (va < d1) va = d1;
          if (vb < d2) vb = d2;
        }
      auto [q0, q1] = bern_split(q, va < vb ? 1 : 0, T(1) / T(2));
      walk(q0, top, depth - 1, area / T(2));
      walk(q1, top, depth - 1, area / T(2));
    };
    walk(p, true, 8, T(1));
    walk(p, false, 8, T(1));
    overshoot_ = o;
    return *overshoot_;
  }
  /// psi^j, j = 0, 1, ..., in two directions (raw coefficients; values times unit[j]).
  std::vector<std::vector<Coef<T>>> powers{std::vector<Coef<T>>{Coef<T>(1)}};
  std::vector<std::vector<int>> power_deg{std::vector<int>{0, 0}};
  std::vector<T> power_unit{T(1)};
  void ensure_powers(int q) {
    while (static_cast<int>(powers.size()) <= q) {
      std::vector<int> dn;
      T u(1);
      auto next = raw_product<T>(powers.back(), power_deg.back(), psi, dpsi, dn, u);
      power_unit.push_back(power_unit.back() * u * psi_unit);
      powers.push_back(std::move(next));
      power_deg.push_back(dn);
    }
  }
};

template <class T>
T univariate_value(const std::vector<T>& u, const T& t) {
  std::vector<T> w = u;
  const T s = T(1) - t;
  for (std::size_t r = w.size() - 1; r > 0; --r)
    for (std::size_t i = 0; i < r; ++i) w[i] = w[i] * s + w[i + 1] * t;
  return w[0];
}

template <class T>
bool graph_along(const SBern<T>& G, int k, int sign_k, const T& m, bool part_is_nonneg, GraphCut<T>& g);
/// part_is_nonneg: the part is {G >= 0} (else {G <= 0}).
template <class T>
bool graph_cut(const SBern<T>& G, bool part_is_nonneg, GraphCut<T>& g) {
  using C = Coef<T>;
  const std::size_t n[3] = {static_cast<std::size_t>(G.deg[0]) + 1, static_cast<std::size_t>(G.deg[1]) + 1,
                            static_cast<std::size_t>(G.deg[2]) + 1};
  const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
  // Per direction: the derivative's coefficients (without the factor p) and their range.
  std::array<T, 3> mins{T(0), T(0), T(0)}, maxabs{T(0), T(0), T(0)};
  std::array<int, 3> sign{0, 0, 0};
  C diff;
  for (int d = 0; d < 3; ++d) {
    if (G.deg[d] == 0) continue;
    bool pos = true, neg = true;
    C lo(0), hi(0);
    bool first = true;
    for (std::size_t i = 0; i < G.c.size(); ++i) {
      if ((i / stride[d]) % n[d] == n[d] - 1) continue;
      diff = G.c[i + stride[d]];
      diff -= G.c[i];
      pos = pos && 0 < diff;
      neg = neg && diff < 0;
      if (first || diff < lo) lo = diff;
      if (first || hi < diff) hi = diff;
      first = false;
    }
    const T p(G.deg[d]);
    maxabs[d] = std::max(T(-as_value<T>(lo)), as_value<T>(hi)) * p;
    if (pos || neg) {
      sign[d] = pos ? 1 : -1;
      mins[d] = (pos ? as_value<T>(lo) : T(-as_value<T>(hi))) * p;
    }
  }
  // The directions where G is monotone, the flattest graph first: m_k against the other
  // directions' slopes.
  std::vector<std::pair<T, int>> order;
  for (int d = 0; d < 3; ++d) {
    if (sign[d] == 0) continue;
    T other(0);
    for (int e = 0; e < 3; ++e)
      if (e != d && other < maxabs[e]) other = maxabs[e];
    // (The composition's cost grows with G's degree along d: prefer the lower degrees.)
    order.push_back({(T(0) < other ? T(mins[d] / other) : T(mins[d] * T(1000000))) / T(G.deg[d] * G.deg[d]), d});
  }
  if (order.empty()) return false;
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return y.first < x.first; });
  g.monotone = order.front().second;
  for (int d = 0; d < 3; ++d)
    if (d != g.monotone && (g.steepest < 0 || maxabs[g.steepest] < maxabs[d])) g.steepest = d;
  for (const auto& [score, k] : order)
    if (graph_along(G, k, sign[k], mins[k], part_is_nonneg, g)) return true;
  return false;
}

/// graph_cut along direction k (G's derivative along k of sign `sign`, at least m).
template <class T>
bool graph_along(const SBern<T>& G, int k, int sign_k, const T& m, bool part_is_nonneg, GraphCut<T>& g) {
  using C = Coef<T>;
  g.k = k;
  std::vector<int> ds;
  const auto sl = slices_along(G, k, false, ds);
  // Approximate roots at the 3 x 3 grid, then psi's Bernstein coefficients.
  const T half = T(1) / T(2);
  const T grid[3] = {T(0), half, T(1)};
  T f[3][3];
  for (int ia = 0; ia < 3; ++ia)
    for (int ib = 0; ib < 3; ++ib) {
      std::vector<T> u(sl.size());
      for (std::size_t l = 0; l < sl.size(); ++l) {
        Bernstein<T> b2{ds, std::vector<T>(sl[l].size())};
        for (std::size_t i = 0; i < sl[l].size(); ++i) b2.c[i] = as_value<T>(sl[l][i]);
        u[l] = bern_value(b2, std::vector<T>{grid[ia], grid[ib]});
      }
      std::vector<T> du(u.size() - 1);
      for (std::size_t l = 0; l + 1 < u.size(); ++l) du[l] = (u[l + 1] - u[l]) * T(static_cast<long>(u.size() - 1));
      // Start: the chord's root; then Newton.
      T t = (u.front() == u.back()) ? half : T(u.front() / (u.front() - u.back()));
      for (int it = 0; it < 8; ++it) {
        const T dv = univariate_value(du, t);
        if (dv == T(0)) return false;
        const T next = round_dyadic(T(t - univariate_value(u, t) / dv), false, 40, 0);
        if (next == t) break;
        t = next;
        if (t < T(-1) || T(2) < t) return false;
      }
      f[ia][ib] = t;
    }
  // Values at 0, 1/2, 1 to Bernstein coefficients of degree 2, per direction.
  T bcoef[3][3];
  for (int ib = 0; ib < 3; ++ib) {
    T v0 = f[0][ib], v1 = f[1][ib], v2 = f[2][ib];
    f[0][ib] = v0;
    f[1][ib] = T(2) * v1 - (v0 + v2) / T(2);
    f[2][ib] = v2;
  }
  for (int ia = 0; ia < 3; ++ia) {
    T v0 = f[ia][0], v1 = f[ia][1], v2 = f[ia][2];
    bcoef[ia][0] = round_dyadic(v0, false, 24, 0);
    bcoef[ia][1] = round_dyadic(T(T(2) * v1 - (v0 + v2) / T(2)), false, 24, 0);
    bcoef[ia][2] = round_dyadic(v2, false, 24, 0);
  }
  T pmin = bcoef[0][0], pmax = pmin;
  for (int ia = 0; ia < 3; ++ia)
    for (int ib = 0; ib < 3; ++ib) {
      pmin = std::min(pmin, bcoef[ia][ib]);
      pmax = std::max(pmax, bcoef[ia][ib]);
    }
  // Where psi leaves [0, 1] (the surface leaves the box through a face across k), G is needed
  // monotone on a longer interval [lo, hi] of t: its coefficients there (de Casteljau at
  // parameters outside [0, 1]).
  T m_used = m;
  const T eighth = T(1) / T(8);
  T ext_lo(0), ext_hi(1);
  while (!(ext_lo + eighth < pmin)) ext_lo -= eighth;
  while (!(pmax < ext_hi - eighth)) ext_hi += eighth;
  if (ext_lo < T(-1) || T(2) < ext_hi) return false;
  if (ext_lo < T(0) || T(1) < ext_hi) {
    Bernstein<T> v{G.deg, std::vector<T>(G.c.size())};
    for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(G.c[i]);
    v = bern_split(v, k, ext_lo).second;                                           // over [ext_lo, 1]
    v = bern_split(v, k, T((ext_hi - ext_lo) / (T(1) - ext_lo))).first;          // over [ext_lo, ext_hi]
    const std::size_t n[3] = {static_cast<std::size_t>(G.deg[0]) + 1, static_cast<std::size_t>(G.deg[1]) + 1,
                              static_cast<std::size_t>(G.deg[2]) + 1};
    const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
    T lo(0), hi(0);  // (degree 0 along k: no difference, and no monotonicity claimed below)
    bool first = true;
    for (std::size_t i = 0; i < v.c.size(); ++i) {
      if ((i / stride[k]) % n[k] == n[k] - 1) continue;
      const T dlt = v.c[i + stride[k]] - v.c[i];
      if (first || dlt < lo) lo = dlt;
      if (first || hi < dlt) hi = dlt;
      first = false;
    }
    if (sign_k > 0 ? !(T(0) < lo) : !(hi < T(0))) return false;
    // d/dt over [ext_lo, ext_hi] is p (c_{l+1} - c_l) / (ext_hi - ext_lo).
    m_used = (sign_k > 0 ? lo : T(-hi)) * T(G.deg[k]) / (ext_hi - ext_lo);
  }
  // psi's raw coefficients (a fastest).
  g.psi.assign(9, C(0));
  g.one_minus_psi.assign(9, C(0));
  if constexpr (integer_coefficients<T>) {
    mp_bitcnt_t K = 0;
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) K = std::max<mp_bitcnt_t>(K, mpz_sizeinbase(mpq_denref(bcoef[ia][ib].backend().data()), 2) - 1);
    Integer one(1);
    mpz_mul_2exp(one.backend().data(), one.backend().data(), K);
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) {
        Rational x = bcoef[ia][ib];
        mpq_mul_2exp(x.backend().data(), x.backend().data(), K);
        g.psi[ia + 3 * ib] = numerator(x);
        g.one_minus_psi[ia + 3 * ib] = one - numerator(x);
      }
    g.psi_unit = T(1) / T(one);
  } else {
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) {
        g.psi[ia + 3 * ib] = bcoef[ia][ib];
        g.one_minus_psi[ia + 3 * ib] = T(1) - bcoef[ia][ib];
      }
    g.psi_unit = T(1);
  }
  // eps = max |G(s, psi(s))| / m.
  std::vector<int> dh;
  T factor;
  const auto H = compose_graph<T>(sl, ds, g.psi, g.one_minus_psi, g.dpsi, g.psi_unit, dh, factor);
  C hmax(0), x;
  for (const auto& h : H) {
    x = h;
    if (x < 0) x = -x;
    if (hmax < x) hmax = x;
  }
  g.eps = round_outward(T(as_value<T>(hmax) * factor / m_used), true);
  if (!(ext_lo < pmin - g.eps) || !(pmax + g.eps < ext_hi)) return false;
  g.exits = pmin - g.eps < T(0) || T(1) < pmax + g.eps;
  g.ext_lo = ext_lo;
  g.ext_hi = ext_hi;
  g.below = (sign_k > 0) != part_is_nonneg;
  for (int ib = 0; ib < 3; ++ib) {
    T v = bcoef[0][ib] - T(2) * bcoef[1][ib] + bcoef[2][ib];
    if (v < T(0)) v = -v;
    if (g.curvature[0] < v) g.curvature[0] = v;
  }
  for (int ia = 0; ia < 3; ++ia) {
    T v = bcoef[ia][0] - T(2) * bcoef[ia][1] + bcoef[ia][2];
    if (v < T(0)) v = -v;
    if (g.curvature[1] < v) g.curvature[1] = v;
  }
  return true;
}

/// The integral over [0, 1]^2 of a b (two directions, raw coefficients; the values times the
/// Gram units times a's and b's units), by the Gram matrices contracted direction by direction.
template <class T>
Coef<T> contract_2d(const std::vector<Coef<T>>& a, const std::vector<int>& da, const std::vector<Coef<T>>& b, const std::vector<int>& db,
                    GramCache<T>& gram, T& unit) {
  using C = Coef<T>;
  const std::size_t a0 = da[0] + 1, a1 = da[1] + 1, b0 = db[0] + 1, b1 = db[1] + 1;
  const auto& g0 = gram.get(da[0], db[0]);
  const auto& g1 = gram.get(da[1], db[1]);
  unit = g0.unit * g1.unit;
  auto addmul = [](C& acc, const C& x, const C& y) {
    if constexpr (integer_coefficients<T>) mpz_addmul(acc.backend().data(), x.backend().data(), y.backend().data());
    else acc += x * y;
  };
  thread_local std::vector<C> t1;
  t1.assign(b0 * a1, C(0));
  for (std::size_t i1 = 0; i1 < a1; ++i1)
    for (std::size_t i0 = 0; i0 < a0; ++i0) {
      const C& x = a[i0 + a0 * i1];
      if (x == 0) continue;
      for (std::size_t j0 = 0; j0 < b0; ++j0) addmul(t1[j0 + b0 * i1], x, g0.g[i0 * b0 + j0]);
    }
  C s(0), t(0);
  for (std::size_t j1 = 0; j1 < b1; ++j1)
    for (std::size_t j0 = 0; j0 < b0; ++j0) {
      const C& bj = b[j0 + b0 * j1];
      if (bj == 0) continue;
      t = C(0);
      for (std::size_t i1 = 0; i1 < a1; ++i1) addmul(t, t1[j0 + b0 * i1], g1.g[i1 * b1 + j1]);
      addmul(s, bj, t);
    }
  return s;
}

/// The integral of P over a cut box's part given by a graph, lo <= int <= hi (on the box's unit
/// cube): int_{s_k <= phi} P = int int A(s, clamp(phi(s))) for P's antiderivative A along k, which
/// is int int A(s, psi(s)) within eps max |P|, minus, where psi leaves [0, 1], F = A(s, psi) -
/// A(s, 1) over {psi > 1} and A(s, psi) over {psi < 0}.
template <class T>
void graph_integral(const SBern<T>& P, GraphCut<T>& g, GramCache<T>& gram, T& lo, T& hi) {
  std::vector<int> ds;
  const auto A = slices_along(P, g.k, true, ds);
  const int q = static_cast<int>(A.size()) - 1;
  const T aunit = P.scale / T(q);  // A's slices: sums of P's, times 1 / (p + 1)
  // A(s, t) = sum_l a_l(s) B_l^q(t) = sum_j alpha_j(s) t^j, alpha_j = sum_{l <= j} (-1)^(j - l)
  // C(q, l) C(q - l, j - l) a_l; then int int alpha_j psi^j by Gram contraction.
  g.ensure_powers(q);
  T total(0);
  for (int j = 0; j <= q; ++j) {
    std::vector<Coef<T>> alpha(A[0].size(), Coef<T>(0));
    for (int l = 0; l <= j; ++l) {
      const T c = detail::binomial_row<T>(q)[l] * detail::binomial_row<T>(q - l)[j - l];
      Coef<T> cc;
      if constexpr (integer_coefficients<T>) cc = numerator(c);
      else cc = c;
      if ((j - l) % 2) cc = -cc;
      for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] += cc * A[l][i];
    }
    T gu(1);
    const Coef<T> v = contract_2d<T>(alpha, ds, g.powers[j], g.power_deg[j], gram, gu);
    total += as_value<T>(v) * gu * g.power_unit[j];
  }
  T blo = total * aunit, bhi = blo;
  if (g.exits) {
    // Where psi > 1, A(s, 1) instead of C(s) = A(s, psi(s)): C - A(s, 1) = int_1^psi P dt lies
    // between (psi - 1) times P's extremes over the longer interval; where psi < 0, 0 instead of
    // C = -int_psi^0 P dt. int int (psi - 1)_+ and (-psi)_+ are the graph's (overshoot).
    Bernstein<T> v{P.deg, std::vector<T>(P.c.size())};
    for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(P.c[i]) * P.scale;
    if (g.ext_lo < T(0)) v = bern_split(v, g.k, g.ext_lo).second;
    if (T(1) < g.ext_hi) v = bern_split(v, g.k, T((g.ext_hi - g.ext_lo) / (T(1) - g.ext_lo))).first;
    T emin = v.c.front(), emax = emin;
    for (const auto& x : v.c) {
      if (x < emin) emin = x;
      if (emax < x) emax = x;
    }
    const auto& o = g.overshoot();
    const T top_lo = std::min(emin * o[0], emin * o[1]), top_hi = std::max(emax * o[0], emax * o[1]);
    const T bottom_lo = -std::max(emax * o[2], emax * o[3]), bottom_hi = -std::min(emin * o[2], emin * o[3]);
    blo -= top_hi + bottom_hi;
    bhi -= top_lo + bottom_lo;
  }
  T pmin, pmax;
  coefficient_range(P, pmin, pmax);
  const T err = g.eps * std::max(T(-pmin), pmax);
  if (g.below) {
    lo = blo - err;
    hi = bhi + err;
  } else {
    const T whole = coefficient_mean(P);
    lo = whole - bhi - err;
    hi = whole - blo + err;
  }
}

}  // namespace vrep_detail

}  // namespace splinex
