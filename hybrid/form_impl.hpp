// Implementation of hybrid/form.hpp; included by the explicit instantiations only.
#pragma once
#include <algorithm>
#include <string>
#include <utility>

#include "hybrid/hybrid_impl.hpp"
#include "hybrid/form.hpp"

namespace splinex {

namespace hybrid_detail {

/// All B-splines of degree p over U at x (zero outside x's span).
template <class T>
std::vector<T> all_basis(const std::vector<T>& U, int p, const T& x) {
  const std::size_t n = U.size() - p - 1, span = find_span(U, p, n, x);
  const auto N = basis_funs(span, x, p, U);
  std::vector<T> all(n, T(0));
  for (int k = 0; k <= p; ++k) all[span - p + k] = N[k];
  return all;
}

template <class T>
std::vector<T> bernstein_knots(int d) {
  std::vector<T> U(d + 1, T(0));
  U.insert(U.end(), d + 1, T(1));
  return U;
}

template <class T>
bool is_bernstein(const std::vector<T>& U, int d) {
  return U == bernstein_knots<T>(d);
}

template <class T>
T ratio_or_zero(const T& num, const T& den) {
  return den == T(0) ? T(0) : num / den;
}

/// Eq. 4.8: alpha_j (j = 0..n-1) and beta_j (j = 0..n-1) for inserting x into U (degree d, n
/// coefficients), 0-based knots; m is the span of x (U_m <= x < U_{m+1}).
template <class T>
std::pair<std::vector<T>, std::vector<T>> boehm_alpha_beta(const std::vector<T>& U, int d, const T& x, const std::string& field) {
  const std::size_t n = U.size() - d - 1;
  if (!(U[d] < x) || !(x < U[n]))
    throw DomainError(field, "knot " + std::string("to insert is not strictly inside the domain"), "insert a knot in the open interval (0, 1)");
  const std::size_t m = find_span(U, d, n, x);
  int mult = 0;
  for (const auto& u : U) mult += u == x ? 1 : 0;
  if (mult + 1 > d)
    throw DomainError(field, "knot would get multiplicity " + std::to_string(mult + 1) + " > degree " + std::to_string(d),
                      "insert it at most degree times (the patch would lose continuity there)");
  std::vector<T> a(n), b(n);
  const long M = static_cast<long>(m), D = d;
  for (long j = 0; j < static_cast<long>(n); ++j) {
    if (j <= M - D) a[j] = T(1);
    else if (j <= M) a[j] = (x - U[j]) / (U[j + D] - U[j]);
    else a[j] = T(0);
    if (j <= M - D - 1) b[j] = T(0);
    else if (j <= M - 1) b[j] = (U[j + D + 1] - x) / (U[j + D + 1] - U[j + 1]);
    else b[j] = T(1);
  }
  return {a, b};
}

template <class T>
std::vector<T> insert_into(std::vector<T> U, const T& x) {
  U.insert(std::upper_bound(U.begin(), U.end(), x), x);
  return U;
}

}  // namespace hybrid_detail

template <class T>
HybridForm<T> hybrid_form(const HybridPatch<T>& P) {
  using namespace hybrid_detail;
  validate(P);
  HybridForm<T> F;
  F.base = P;
  const int d = P.d, l = P.layers(), q = P.q;
  for (std::size_t i = 0; i < P.sides(); ++i) {
    HybridFormSide<T> S;
    S.du = S.dh = d;
    S.U = S.V = bernstein_knots<T>(d);
    S.interior.assign(static_cast<std::size_t>(d + 1) * (d + 1) * q, T(0));
    for (int k = 2; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        const T w = mu(d, j, k, T(0), T(0));  // constant for k >= 2
        for (int c = 0; c < q; ++c) S.interior[(static_cast<std::size_t>(k) * (d + 1) + j) * q + c] = w * P.points[P.index(i, j, k) + c];
      }
    S.p = P.p[i];
    S.Ub = P.knots[i];
    for (int j = 0; j <= d; ++j) {
      const T tau = ribbon_factor(P, i, j);
      for (int c = 0; c < q; ++c) {
        S.P.push_back(P.points[P.index(i, j, 0) + c]);
        S.Tbar.push_back(tau * (P.points[P.index(i, j, 1) + c] - P.points[P.index(i, j, 0) + c]));
      }
    }
    F.sides.push_back(std::move(S));
  }
  return F;
}

template <class T>
std::vector<T> hybrid_form_interior(const HybridFormSide<T>& S, int q, const T& s, const T& h) {
  const auto Ns = hybrid_detail::all_basis(S.U, S.du, s), Nh = hybrid_detail::all_basis(S.V, S.dh, h);
  std::vector<T> out(q, T(0));
  const std::size_t nu = S.count_u();
  for (std::size_t k = 0; k < Nh.size(); ++k) {
    if (Nh[k] == T(0)) continue;
    for (std::size_t j = 0; j < nu; ++j) {
      if (Ns[j] == T(0)) continue;
      const T w = Ns[j] * Nh[k];
      for (int c = 0; c < q; ++c) out[c] = out[c] + S.interior[(k * nu + j) * q + c] * w;
    }
  }
  return out;
}

template <class T>
std::vector<T> hybrid_form_ribbon(const HybridFormSide<T>& S, int q, const T& s, const T& h) {
  const auto N = hybrid_detail::all_basis(S.Ub, S.p, s);
  std::vector<T> out(q, T(0));
  for (std::size_t j = 0; j < N.size(); ++j) {
    if (N[j] == T(0)) continue;
    for (int c = 0; c < q; ++c) out[c] = out[c] + (S.P[j * q + c] + h * S.Tbar[j * q + c]) * N[j];
  }
  return out;
}

template <class T>
std::vector<T> hybrid_form_evaluate(const HybridForm<T>& F, const Point2<T>& x) {
  using namespace hybrid_detail;
  const auto& P = F.base;
  const auto L = hybrid_local(P, x);
  std::vector<T> S(P.q, T(0));
  T blend(0);
  for (std::size_t i = 0; i < P.sides(); ++i) {
    const T lstar = side_blend(P, L, i, blend, [](int, int, const T&) {});
    const auto I = hybrid_form_interior(F.sides[i], P.q, L.s[i], L.h[i]);
    for (int c = 0; c < P.q; ++c) S[c] = S[c] + I[c];
    if (!(lstar == T(0))) {
      const auto R = hybrid_form_ribbon(F.sides[i], P.q, L.s[i], L.h[i]);
      for (int c = 0; c < P.q; ++c) S[c] = S[c] + R[c] * lstar;
    }
  }
  const T b0 = T(1) - blend;
  const auto C0 = central_point(P);
  for (int c = 0; c < P.q; ++c) S[c] = S[c] + C0[c] * b0;
  return S;
}

template <class T>
std::pair<std::vector<T>, std::vector<T>> cls_elevate(int p, const std::vector<T>& u, const std::vector<T>& C, int q) {
  using hybrid_detail::ratio_or_zero;
  /// Ubar: every distinct knot once more.
  std::vector<T> ub;
  for (std::size_t k = 0; k < u.size(); ++k) {
    ub.push_back(u[k]);
    if (k + 1 == u.size() || !(u[k + 1] == u[k])) ub.push_back(u[k]);
  }
  const std::size_t n = u.size() - p - 1, nbar = ub.size() - (p + 1) - 1;
  if (C.size() != n * q) throw ValidationError("ribbon", "has the wrong number of coefficients", "give #knots - p - 1 coefficients");
  std::vector<T> Q(nbar * q, T(0));
  for (std::size_t j = 0; j < nbar; ++j) {
    /// Level r: Lambda^r_s(j), alpha^r_s(j) for s = 0..u.size() - r - 2.
    const std::size_t n0 = u.size() - 1;
    std::vector<T> Lam(n0), alp(n0);
    for (std::size_t s = 0; s < n0; ++s) {
      const bool in = !(ub[j] < u[s]) && ub[j] < u[s + 1];
      Lam[s] = alp[s] = in ? T(1) : T(0);
    }
    for (int r = 1; r <= p; ++r) {
      const std::size_t ns = u.size() - r - 1;
      std::vector<T> L2(ns), A2(ns);
      for (std::size_t s = 0; s < ns; ++s) {
        A2[s] = ratio_or_zero(T(ub[j + r] - u[s]), T(u[s + r] - u[s])) * alp[s] +
                ratio_or_zero(T(u[s + r + 1] - ub[j + r]), T(u[s + r + 1] - u[s + 1])) * alp[s + 1];
        L2[s] = ratio_or_zero(T(ub[j + r + 1] - u[s]), T(u[s + r] - u[s])) * Lam[s] +
                ratio_or_zero(T(u[s + r + 1] - ub[j + r + 1]), T(u[s + r + 1] - u[s + 1])) * Lam[s + 1] + A2[s];
      }
      Lam = std::move(L2);
      alp = std::move(A2);
    }
    for (std::size_t s = 0; s < n; ++s)
      for (int c = 0; c < q; ++c) Q[j * q + c] = Q[j * q + c] + C[s * q + c] * Lam[s] / T(p + 1);
  }
  return {ub, Q};
}

namespace hybrid_detail {

/// Eq. 4.5 once: a full (d+1) x (d+1) tensor Bernstein net (Ct_{j,k} at (k (d+1) + j) q) to
/// degree d + 1 in both directions.
template <class T>
std::vector<T> elevate_net(const std::vector<T>& C, int d, int q) {
  const int e = d + 1;
  std::vector<T> Q(static_cast<std::size_t>(e + 1) * (e + 1) * q, T(0));
  auto at = [&](int j, int k, int c) -> T {
    if (j < 0 || j > d || k < 0 || k > d) return T(0);
    return C[(static_cast<std::size_t>(k) * (d + 1) + j) * q + c];
  };
  for (int k = 0; k <= e; ++k)
    for (int j = 0; j <= e; ++j) {
      const T eta = T(j) / T(e), v = T(k) / T(e);
      for (int c = 0; c < q; ++c)
        Q[(static_cast<std::size_t>(k) * (e + 1) + j) * q + c] = eta * v * at(j - 1, k - 1, c) + (T(1) - eta) * v * at(j, k - 1, c) +
                                                                  eta * (T(1) - v) * at(j - 1, k, c) + (T(1) - eta) * (T(1) - v) * at(j, k, c);
    }
  return Q;
}

}  // namespace hybrid_detail

template <class T>
HybridForm<T> hybrid_elevate(const HybridForm<T>& F) {
  using namespace hybrid_detail;
  HybridForm<T> G = F;
  const int q = F.base.q;
  for (std::size_t i = 0; i < F.sides.size(); ++i) {
    auto& S = G.sides[i];
    if (!is_bernstein(S.U, S.du) || !is_bernstein(S.V, S.dh) || S.du != S.dh)
      throw DomainError("sides[" + std::to_string(i) + "]", "interior is not a Bernstein tensor of equal degrees (knots were inserted)",
                        "elevate before inserting knots (Theorem 4.1 applies to Eq. 4.3's Bernstein interior)");
    int distinct = 1;
    for (std::size_t k = 1; k < S.Ub.size(); ++k) distinct += S.Ub[k] == S.Ub[k - 1] ? 0 : 1;
    const int h = distinct - 1;
    auto [ub, Pq] = cls_elevate(S.p, S.Ub, S.P, q);
    auto Tq = cls_elevate(S.p, S.Ub, S.Tbar, q).second;
    S.Ub = std::move(ub);
    S.P = std::move(Pq);
    S.Tbar = std::move(Tq);
    S.p += 1;
    for (int t = 0; t < h; ++t) {
      S.interior = elevate_net(S.interior, S.du, q);
      S.du += 1;
      S.dh += 1;
    }
    S.U = bernstein_knots<T>(S.du);
    S.V = bernstein_knots<T>(S.dh);
  }
  return G;
}

template <class T>
HybridForm<T> hybrid_insert(const HybridForm<T>& F, const T& xs, const T& xh, const T& xb) {
  using namespace hybrid_detail;
  HybridForm<T> G = F;
  const std::size_t q = static_cast<std::size_t>(F.base.q);
  for (std::size_t i = 0; i < F.sides.size(); ++i) {
    const auto& S = F.sides[i];
    auto& R = G.sides[i];
    const std::string f = "sides[" + std::to_string(i) + "]";
    const auto [as, bs] = boehm_alpha_beta(S.U, S.du, xs, f + ".U");
    const auto [ah, bh] = boehm_alpha_beta(S.V, S.dh, xh, f + ".V");
    /// Not a structured binding: C++17 lambdas cannot capture those (clang refuses it).
    const auto boundary_ab = boehm_alpha_beta(S.Ub, S.p, xb, f + ".Ub");
    const std::vector<T>& ab = boundary_ab.first;
    const std::vector<T>& bb = boundary_ab.second;
    const std::size_t nu = S.count_u(), nh = S.count_h(), nb = S.count_b();
    /// Eq. 4.10 (coefficients outside the old index ranges are 0).
    auto C = [&](long j, long k, std::size_t c) -> T {
      if (j < 0 || k < 0 || j >= static_cast<long>(nu) || k >= static_cast<long>(nh)) return T(0);
      return S.interior[(static_cast<std::size_t>(k) * nu + j) * q + c];
    };
    auto A = [](const std::vector<T>& a, long j) -> T { return j < 0 || j >= static_cast<long>(a.size()) ? T(0) : a[j]; };
    R.interior.assign((nu + 1) * (nh + 1) * q, T(0));
    for (long k = 0; k <= static_cast<long>(nh); ++k)
      for (long j = 0; j <= static_cast<long>(nu); ++j)
        for (std::size_t c = 0; c < q; ++c)
          R.interior[(static_cast<std::size_t>(k) * (nu + 1) + j) * q + c] =
              A(as, j) * A(ah, k) * C(j, k, c) + A(as, j) * A(bh, k - 1) * C(j, k - 1, c) + A(bs, j - 1) * A(ah, k) * C(j - 1, k, c) +
              A(bs, j - 1) * A(bh, k - 1) * C(j - 1, k - 1, c);
    /// Eq. 4.11 and 4.12.
    auto ribbon = [&](const std::vector<T>& X) {
      std::vector<T> Y((nb + 1) * q, T(0));
      for (long j = 0; j <= static_cast<long>(nb); ++j)
        for (std::size_t c = 0; c < q; ++c) {
          const T x0 = j < static_cast<long>(nb) ? X[j * q + c] : T(0), x1 = j > 0 ? X[(j - 1) * q + c] : T(0);
          Y[j * q + c] = A(ab, j) * x0 + A(bb, j - 1) * x1;
        }
      return Y;
    };
    R.P = ribbon(S.P);
    R.Tbar = ribbon(S.Tbar);
    R.U = insert_into(S.U, xs);
    R.V = insert_into(S.V, xh);
    R.Ub = insert_into(S.Ub, xb);
  }
  return G;
}

template <class T>
HybridPatch<T> hybrid_elevate_salvi(const HybridPatch<T>& P) {
  using namespace hybrid_detail;
  validate(P);
  const int d = P.d, l = P.layers(), q = P.q, e = d + 1;
  if (d % 2 == 0)
    throw DomainError("degree", "is even (" + std::to_string(d) + "): the elevated layer " + std::to_string(l) +
                                    " needs net points beyond the patch's l = " + std::to_string(l) + " layers",
                      "use an odd d for Salvi's original elevation");
  for (std::size_t i = 0; i < P.sides(); ++i)
    if (P.p[i] != d || !is_bernstein(P.knots[i], d))
      throw DomainError("sides[" + std::to_string(i) + "]", "is not a Bezier side (p_i = d, no interior knots)",
                        "Salvi's original elevation is defined for the Bezier-sided patch of ref. [18]");
  HybridPatch<T> Q;
  Q.vertices = P.vertices;
  Q.d = e;
  Q.q = q;
  Q.ribbon = P.ribbon;
  Q.p.assign(P.sides(), e);
  Q.knots.assign(P.sides(), bernstein_knots<T>(e));
  const int l2 = Q.layers();
  Q.points.assign(P.sides() * static_cast<std::size_t>(l2) * (e + 1) * q, T(0));
  for (std::size_t i = 0; i < P.sides(); ++i) {
    std::vector<T> net(static_cast<std::size_t>(d + 1) * (d + 1) * q, T(0));
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j)
        for (int c = 0; c < q; ++c) net[(static_cast<std::size_t>(k) * (d + 1) + j) * q + c] = P.points[P.index(i, j, k) + c];
    const auto up = elevate_net(net, d, q);
    for (int k = 0; k < l2; ++k)  // layers 0..l2-1 = 0..l-1 use net layers <= l-1 only
      for (int j = 0; j <= e; ++j)
        for (int c = 0; c < q; ++c) Q.points[Q.index(i, j, k) + c] = up[(static_cast<std::size_t>(k) * (e + 1) + j) * q + c];
  }
  validate(Q);
  return Q;
}

}  // namespace splinex
