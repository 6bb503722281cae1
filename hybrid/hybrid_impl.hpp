// Implementation of hybrid/hybrid.hpp; included by the explicit instantiations only.
#pragma once
#include <algorithm>

#include "base/point.hpp"
#include "hybrid/hybrid.hpp"
#include "spline/basis.hpp"
#include "spline/bernstein.hpp"
#include "spline/dual.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace hybrid_detail {

using detail::power;

/// All d + 1 B-splines N_j^{p_i,U_i}(s) of side i (zero outside s's span), by A2.2 on the span.
template <class T>
std::vector<T> side_basis(const HybridPatch<T>& P, std::size_t i, const T& s) {
  const int p = P.p[i];
  const std::size_t n = static_cast<std::size_t>(P.d + 1), span = find_span(P.knots[i], p, n, s);
  const auto N = basis_funs(span, s, p, P.knots[i]);
  std::vector<T> all(n, T(0));
  for (int k = 0; k <= p; ++k) all[span - p + k] = N[k];
  return all;
}

/// Outward normal of side i (from V_i to V_{i+1}) of a counter-clockwise polygon, not normalized.
template <class T>
Point2<T> normal(const HybridPatch<T>& P, std::size_t i) {
  const auto& a = P.vertices[i];
  const auto& b = P.vertices[(i + 1) % P.sides()];
  return {b[1] - a[1], a[0] - b[0]};
}

/// mu^i_{j,k} (Definition 2.4) for layers k = 0..l-1.
template <class T>
T mu(int d, int j, int k, const T& alpha, const T& beta) {
  if (2 * j <= d) {  // j <= d/2
    if (j < k && k >= 2) return T(0);
    if (2 <= j && j == k && k < (d + 1) / 2) return T(1) / T(2);
    if (j < 2 && k < 2) return alpha;
    return T(1);
  }
  if (j > d - k && k >= 2) return T(0);
  if (j == d - k && k >= 2) return T(1) / T(2);
  if (j > d - 2 && k < 2) return beta;
  return T(1);
}

/// Ribbon factor tau_j of side i (see the header).
template <class T>
T ribbon_factor(const HybridPatch<T>& P, std::size_t i, int j) {
  const auto& U = P.knots[i];
  const int p = P.p[i];
  if (P.ribbon == RibbonFactor::side_interpolant) return T(p) / (U[p + 1] - U[1]);
  const T den = U[p + j] - U[j];
  if (den == T(0))
    throw DomainError("sides[" + std::to_string(i) + "]",
                      "Eq. 2.11's factor p / (U_{p+j} - U_j) is p/0 at j = " + std::to_string(j) +
                          " (U_" + std::to_string(p + j) + " = U_" + std::to_string(j) + ")",
                      "use \"ribbon_factor\": \"side_interpolant\" (p / (U_{p+1} - U_1), the h-derivative of the side "
                      "interpolant I_i), the corrected Eq. 2.11");
  return T(p) / den;
}

}  // namespace hybrid_detail

template <class T>
HybridLocal<T> hybrid_local(const HybridPatch<T>& P, const Point2<T>& x) {
  using namespace hybrid_detail;
  const std::size_t n = P.sides();
  std::vector<T> phi(n), c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto N = normal(P, i);
    phi[i] = (P.vertices[i][0] - x[0]) * N[0] + (P.vertices[i][1] - x[1]) * N[1];
    if (phi[i] < T(0))
      throw DomainError("point", "lies outside the patch domain (beyond side " + std::to_string(i) + ")",
                        "evaluate at points of the closed convex domain");
  }
  for (std::size_t k = 0; k < n; ++k) c[k] = cross(normal(P, (k + n - 1) % n), normal(P, k));
  HybridLocal<T> L;
  L.lambda.assign(n, T(0));
  T sum(0);
  for (std::size_t k = 0; k < n; ++k) {
    T w = c[k];
    for (std::size_t j = 0; j < n; ++j)
      if (j != k && j != (k + n - 1) % n) w = w * phi[j];
    L.lambda[k] = w;
    sum = sum + w;
  }
  for (auto& v : L.lambda) v = v / sum;
  L.s.resize(n);
  L.h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n, prev = (i + n - 1) % n;
    L.h[i] = T(1) - L.lambda[i] - L.lambda[next];
    const T num = c[next] * phi[prev], den = c[next] * phi[prev] + c[i] * phi[next];
    L.s[i] = den == T(0) ? T(1) / T(2) : num / den;  // 0/0 only at a triangle's opposite vertex
  }
  return L;
}

namespace hybrid_detail {

/// P_i(s) and T_i(s) from side i's basis values N (one basis evaluation serves both).
template <class T>
std::vector<T> boundary_from(const HybridPatch<T>& P, std::size_t i, const std::vector<T>& N) {
  std::vector<T> out(P.q, T(0));
  for (int j = 0; j <= P.d; ++j)
    for (int c = 0; c < P.q; ++c) out[c] = out[c] + P.points[P.index(i, j, 0) + c] * N[j];
  return out;
}

template <class T>
std::vector<T> cross_tangent_from(const HybridPatch<T>& P, std::size_t i, const std::vector<T>& N) {
  std::vector<T> out(P.q, T(0));
  for (int j = 0; j <= P.d; ++j) {
    if (N[j] == T(0)) continue;
    const T f = ribbon_factor(P, i, j) * N[j];
    for (int c = 0; c < P.q; ++c) out[c] = out[c] + (P.points[P.index(i, j, 1) + c] - P.points[P.index(i, j, 0) + c]) * f;
  }
  return out;
}

}  // namespace hybrid_detail

template <class T>
std::vector<T> hybrid_boundary(const HybridPatch<T>& P, std::size_t i, const T& s) {
  return hybrid_detail::boundary_from(P, i, hybrid_detail::side_basis(P, i, s));
}

template <class T>
std::vector<T> hybrid_cross_tangent(const HybridPatch<T>& P, std::size_t i, const T& s) {
  return hybrid_detail::cross_tangent_from(P, i, hybrid_detail::side_basis(P, i, s));
}

namespace hybrid_detail {

/// The mu-weighted Bernstein terms of side i at L: adds them to `blend` (B_Sigma), calls
/// interior(j, k, w) for the interior layers k >= 2 (weight w = mu B_j^d(s_i) B_k^d(h_i)) and
/// returns L_i^*, the sum over the two ribbon layers k = 0, 1.
template <class T, class F>
T side_blend(const HybridPatch<T>& P, const HybridLocal<T>& L, std::size_t i, T& blend, F&& interior) {
  const std::size_t n = P.sides();
  const int d = P.d, l = P.layers();
  const T &hp = L.h[(i + n - 1) % n], &hi = L.h[i], &hn = L.h[(i + 1) % n];
  const T a_den = hp * hp + hi * hi, b_den = hn * hn + hi * hi;
  const T alpha = a_den == T(0) ? T(1) / T(2) : hp * hp / a_den;  // corner V_i: see the header
  const T beta = b_den == T(0) ? T(1) / T(2) : hn * hn / b_den;    // corner V_{i+1}
  const auto Bs = bernstein_all(d, L.s[i]), Bh = bernstein_all(d, hi);
  T lstar(0);
  for (int k = 0; k < l; ++k)
    for (int j = 0; j <= d; ++j) {
      const T w = mu(d, j, k, alpha, beta) * Bs[j] * Bh[k];
      if (w == T(0)) continue;
      blend = blend + w;
      if (k < 2) lstar = lstar + w;
      else interior(j, k, w);
    }
  return lstar;
}

/// C_0 (Eq. 2.7), the mean of the points C^i_{l,l-1}.
template <class T>
std::vector<T> central_point(const HybridPatch<T>& P) {
  std::vector<T> C0(P.q, T(0));
  const int l = P.layers();
  for (std::size_t i = 0; i < P.sides(); ++i)
    for (int c = 0; c < P.q; ++c) C0[c] = C0[c] + P.points[P.index(i, l, l - 1) + c];
  for (auto& c : C0) c = c / T(static_cast<long>(P.sides()));
  return C0;
}

}  // namespace hybrid_detail

template <class T>
std::vector<T> hybrid_evaluate(const HybridPatch<T>& P, const Point2<T>& x) {
  using namespace hybrid_detail;
  const auto L = hybrid_local(P, x);
  std::vector<T> S(P.q, T(0));
  T blend(0);  // B_Sigma
  for (std::size_t i = 0; i < P.sides(); ++i) {
    const T lstar = side_blend(P, L, i, blend, [&](int j, int k, const T& w) {
      for (int c = 0; c < P.q; ++c) S[c] = S[c] + P.points[P.index(i, j, k) + c] * w;
    });
    if (!(lstar == T(0))) {
      const auto N = side_basis(P, i, L.s[i]);
      const auto Pi = boundary_from(P, i, N), Ti = cross_tangent_from(P, i, N);
      for (int c = 0; c < P.q; ++c) S[c] = S[c] + (Pi[c] + L.h[i] * Ti[c]) * lstar;
    }
  }
  const T b0 = T(1) - blend;
  const auto C0 = central_point(P);
  for (int c = 0; c < P.q; ++c) S[c] = S[c] + C0[c] * b0;
  return S;
}

template <class T>
HybridJet<T> hybrid_jet(const HybridPatch<T>& P, const Point2<T>& x, const Point2<T>& w) {
  using D = Dual<T>;
  for (std::size_t k = 0; k < P.sides(); ++k)
    if (P.vertices[k][0] == x[0] && P.vertices[k][1] == x[1])
      throw DomainError("point", "is corner " + std::to_string(k) + " of the domain, where the patch has no derivative in general "
                                 "(alpha_i and beta_{i-1} are 0/0 with a direction-dependent limit)",
                        "differentiate at a nearby point; along a side use the side's boundary curve");
  const auto Q = convert_hybrid<D>(P, [](const T& v) { return D(v); });
  const std::array<D, 2> xd{D(x[0], w[0]), D(x[1], w[1])};
  const auto S = hybrid_evaluate(Q, xd);
  const auto L = hybrid_local(Q, xd);
  HybridJet<T> J;
  for (const auto& c : S) {
    J.point.push_back(c.v);
    J.derivative.push_back(c.d);
  }
  auto split = [](const std::vector<D>& a, std::vector<T>& v, std::vector<T>& dv) {
    for (const auto& c : a) {
      v.push_back(c.v);
      dv.push_back(c.d);
    }
  };
  split(L.lambda, J.local.lambda, J.local_derivative.lambda);
  split(L.s, J.local.s, J.local_derivative.s);
  split(L.h, J.local.h, J.local_derivative.h);
  return J;
}

template <class T>
HybridDerivatives<T> hybrid_derivatives(const HybridPatch<T>& P, const Point2<T>& x) {
  auto a = hybrid_jet(P, x, {T(1), T(0)});
  auto b = hybrid_jet(P, x, {T(0), T(1)});
  return {std::move(a.point), std::move(a.derivative), std::move(b.derivative)};
}

template <class T>
HybridCrossDerivative<T> hybrid_cross_derivative(const HybridPatch<T>& P, std::size_t i, const Point2<T>& x) {
  using namespace hybrid_detail;
  const std::size_t n = P.sides();
  if (i >= n) throw UsageError("side", std::to_string(i) + " does not exist (the patch has " + std::to_string(n) + " sides)", "give a side 0..n-1");
  /// Lines of sides i-1 and i+1: points V_{i-1}, V_{i+1}, directions a, b.
  const auto& A = P.vertices[(i + n - 1) % n];
  const auto& B = P.vertices[(i + 1) % n];
  const Point2<T> a{P.vertices[i][0] - A[0], P.vertices[i][1] - A[1]};
  const Point2<T> b{P.vertices[(i + 2) % n][0] - B[0], P.vertices[(i + 2) % n][1] - B[1]};
  const T den = cross(a, b);
  Point2<T> w;
  if (den == T(0)) {
    w = a;  // parallel sides: the iso-lines are parallel to them
  } else {
    const T t = cross(Point2<T>{B[0] - A[0], B[1] - A[1]}, b) / den;  // O = A + t a
    w = {A[0] + t * a[0] - x[0], A[1] + t * a[1] - x[1]};
  }
  const auto J = hybrid_jet(P, x, w);
  const T dh = J.local_derivative.h[i];
  if (dh == T(0))
    throw DomainError("point", "is where h_" + std::to_string(i) + " is stationary along the iso-line of s_" + std::to_string(i),
                      "take the derivative at a point of the closed domain away from the far corners");
  HybridCrossDerivative<T> C;
  for (const auto& c : J.derivative) C.value.push_back(c / dh);
  C.direction = w;
  return C;
}

template <class T>
void validate(const HybridPatch<T>& P) {
  using namespace hybrid_detail;
  const std::size_t n = P.sides();
  if (n < 3) throw ValidationError("domain", "has " + std::to_string(n) + " vertices", "give a convex polygon with at least 3 vertices");
  for (std::size_t i = 0; i < n; ++i) {
    const T o = cross(Point2<T>{P.vertices[(i + 1) % n][0] - P.vertices[i][0], P.vertices[(i + 1) % n][1] - P.vertices[i][1]},
                      Point2<T>{P.vertices[(i + 2) % n][0] - P.vertices[(i + 1) % n][0],
                                       P.vertices[(i + 2) % n][1] - P.vertices[(i + 1) % n][1]});
    const std::string f = "domain[" + std::to_string((i + 1) % n) + "]";
    if (o == T(0)) throw ValidationError(f, "is degenerate: collinear with its neighbours (or repeated)", "remove the vertex; the domain must be strictly convex");
    if (o < T(0)) {
      bool all_cw = true;
      for (std::size_t k = 0; k < n; ++k) {
        const auto &a = P.vertices[k], &b = P.vertices[(k + 1) % n], &c = P.vertices[(k + 2) % n];
        if (!(cross(Point2<T>{b[0] - a[0], b[1] - a[1]}, Point2<T>{c[0] - b[0], c[1] - b[1]}) < T(0))) all_cw = false;
      }
      if (all_cw) throw ValidationError("domain", "is clockwise", "list the vertices counter-clockwise");
      throw ValidationError(f, "is a reflex vertex: the domain is not convex", "give a strictly convex polygon");
    }
  }
  // Convex turning at every vertex can still wind twice (a star); the winding must be 2 pi: the
  // vertices must be sorted by angle around the first one.
  for (std::size_t k = 2; k < n; ++k) {
    const auto &a = P.vertices[0], &b = P.vertices[k - 1], &c = P.vertices[k];
    if (!(T(0) < cross(Point2<T>{b[0] - a[0], b[1] - a[1]}, Point2<T>{c[0] - a[0], c[1] - a[1]})))
      throw ValidationError("domain", "winds around more than once (self-intersecting)", "give a simple strictly convex polygon");
  }
  if (P.d < 3) throw ValidationError("degree", "is " + std::to_string(P.d) + "; the patch needs two ribbon layers", "give d >= 3");
  if (P.q < 1) throw ValidationError("points", "have no coordinates", "give points with at least one coordinate");
  if (P.p.size() != n || P.knots.size() != n)
    throw ValidationError("sides", "has " + std::to_string(P.p.size()) + " entries for " + std::to_string(n) + " domain sides",
                          "give one side per domain edge");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string f = "sides[" + std::to_string(i) + "]";
    const int p = P.p[i];
    if (p < 1 || p > P.d) throw ValidationError(f + ".degree", "is " + std::to_string(p), "give 1 <= p_i <= d");
    const auto& U = P.knots[i];
    const std::size_t want = static_cast<std::size_t>(P.d + p + 2);
    if (U.size() != want)
      throw ValidationError(f + ".knots", "has " + std::to_string(U.size()) + " knots; d + 1 = " + std::to_string(P.d + 1) +
                                              " control points of degree " + std::to_string(p) + " need " + std::to_string(want),
                            "give d + p_i + 2 knots");
    for (std::size_t k = 0; k + 1 < U.size(); ++k)
      if (U[k + 1] < U[k]) throw ValidationError(f + ".knots", "decrease at index " + std::to_string(k + 1), "sort the knots");
    for (int k = 0; k <= p; ++k)
      if (!(U[k] == T(0)) || !(U[U.size() - 1 - k] == T(1)))
        throw ValidationError(f + ".knots", "are not clamped on [0, 1]", "start with p + 1 zeros and end with p + 1 ones (s_i runs over [0, 1])");
    for (std::size_t k = 0; k + static_cast<std::size_t>(p) + 1 < U.size(); ++k)
      if (!(U[k] < U[k + p + 1]))
        throw ValidationError(f + ".knots", "has a knot of multiplicity above p at index " + std::to_string(k), "lower the multiplicity");
  }
  const int l = P.layers();
  const std::size_t want = n * static_cast<std::size_t>(l) * (P.d + 1) * P.q;
  if (P.points.size() != want)
    throw ValidationError("points", "has " + std::to_string(P.points.size() / P.q) + " control points, the patch needs " +
                                        std::to_string(want / P.q) + " (n sides x l = ceil(d/2) layers x (d + 1) columns)",
                          "give every side l layers of d + 1 points");
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n;
    for (int a = 0; a < l; ++a)
      for (int b = 0; b < l; ++b)
        for (int c = 0; c < P.q; ++c)
          if (!(P.points[P.index(i, a, b) + c] == P.points[P.index(prev, P.d - b, a) + c]))
            throw ValidationError("sides[" + std::to_string(i) + "].layers[" + std::to_string(b) + "][" + std::to_string(a) + "]",
                                  "disagrees with sides[" + std::to_string(prev) + "].layers[" + std::to_string(a) + "][" +
                                      std::to_string(P.d - b) + "] (a shared corner control point, C^i_{a,b} = C^{i-1}_{d-b,a})",
                                  "give neighbouring sides the same corner points");
  }
}

}  // namespace splinex
