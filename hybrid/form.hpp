// Section 4 of papers/003: the hybrid patch in the form of Eq. 4.3 / 4.7, its improved degree
// elevation (Theorem 4.1: Eq. 4.5 for the interior, Eq. 4.6 (Cohen-Lyche-Schumaker) for the
// ribbons) and knot insertion (Theorem 4.2: Eq. 4.8-4.12), and Salvi's original elevation for
// comparison. Generic over the arithmetic T.
//
// The form (Eq. 4.3a, 4.7): S = sum_i [ sum_{j,k} Ct^i_{j,k} N_j(s_i) N_k(h_i) + R_i(s_i, h_i) L_i^* ]
// + C_0 B_0, with Ct = mu C on the interior layers k = 2..l-1 (Ct = 0 on k = 0, 1 and k >= l), the
// interior basis a tensor product of B-splines over knots (U, V) (Bernstein: U = V = {0^(d+1),
// 1^(d+1)}), and the ribbon R_i = sum_j C_j N_j^{p,Ub}(s_i) + h_i sum_j Cbar_j N_j^{p,Ub}(s_i) with
// Cbar_j = tau_j (C_{j,1} - C_{j,0}) (tau the ribbon factor, hybrid/hybrid.hpp). By Remark 4.1,
// L_i^*, B_0 and C_0 stay those of the original patch (`base`) through elevation and insertion, so
// the form equals the patch as long as each side's interior and ribbon are the same functions of
// (s, h): that is what Theorems 4.1 and 4.2 claim, and what proofs/ checks exactly.
#pragma once
#include <vector>

#include "hybrid/hybrid.hpp"

namespace splinex {

template <class T>
struct HybridFormSide {
  int du = 0, dh = 0;         // interior degrees in s and h
  std::vector<T> U, V;        // interior knots (clamped on [0, 1])
  std::vector<T> interior;    // Ct_{j,k} at (k * count_u + j) * q, all rows (zero ones kept)
  int p = 0;                  // ribbon degree
  std::vector<T> Ub;          // ribbon knots
  std::vector<T> P, Tbar;     // ribbon coefficients C_{j,0} and Cbar_j, j * q
  std::size_t count_u() const { return U.size() - du - 1; }
  std::size_t count_h() const { return V.size() - dh - 1; }
  std::size_t count_b() const { return Ub.size() - p - 1; }
};

template <class T>
struct HybridForm {
  HybridPatch<T> base;  // weights mu, L_i^*, B_0 and C_0 (Remark 4.1)
  std::vector<HybridFormSide<T>> sides;
};

/// Eq. 4.3: the patch rewritten (Ct = mu C, Cbar = tau (C_1 - C_0)).
template <class T>
HybridForm<T> hybrid_form(const HybridPatch<T>& P);

template <class T>
std::vector<T> hybrid_form_evaluate(const HybridForm<T>& F, const Point2<T>& x);

/// Side i's interior sum_{j,k} Ct_{j,k} N_j(s) N_k(h) and ribbon R_i(s, h) at one (s, h).
template <class T>
std::vector<T> hybrid_form_interior(const HybridFormSide<T>& S, int q, const T& s, const T& h);
template <class T>
std::vector<T> hybrid_form_ribbon(const HybridFormSide<T>& S, int q, const T& s, const T& h);

/// Eq. 4.6 literally: the coefficients of a degree-p B-spline over U (q values each) elevated to
/// degree p + 1 over Ubar (every distinct knot's multiplicity + 1). A ratio whose denominator is a
/// zero-length knot interval is taken as 0 (the B-spline convention). Returns {Ubar, Q}.
template <class T>
std::pair<std::vector<T>, std::vector<T>> cls_elevate(int p, const std::vector<T>& U, const std::vector<T>& C, int q);

/// Theorem 4.1, one step: S^{d,p} -> S^{d+h,p+1}. Ribbons by Eq. 4.6 (h + 1 = the number of distinct
/// knots of the side, so the ribbon gains h coefficients); the interior, which must be Bernstein,
/// by h applications of Eq. 4.5 (degree + 1 in s and in h each).
template <class T>
HybridForm<T> hybrid_elevate(const HybridForm<T>& F);

/// Theorem 4.2: inserts one knot xs into every side's U, xh into V and xb into Ub (Eq. 4.8 with
/// the NURBS-book 0-based knot numbering; Eq. 4.10 for the interior, 4.11-4.12 for the ribbon).
/// Each must lie strictly inside (0, 1) and keep multiplicities <= the degree (DomainError).
template <class T>
HybridForm<T> hybrid_insert(const HybridForm<T>& F, const T& xs, const T& xh, const T& xb);

/// Salvi's original degree elevation (the GB patch's, papers/003 ref. [18]), for patches with
/// Bezier sides (p_i = d, no interior knots) and odd d: every side's net C^i_{j,k} (k = 0..l-1) is
/// elevated as a degree-d tensor Bezier net by Eq. 4.5 to degree d + 1 (columns 0..d+1, layers
/// 0..l'-1; l' = l for odd d, so every point it needs exists, and shared corners stay shared), and
/// a new hybrid patch of degree d + 1 with Bezier sides is built from it, with the weights, L_i^* and
/// C_0 of degree d + 1. For even d the elevated layer l' - 1 = l would need net points the patch
/// does not have (DomainError). It is not the same surface; papers/003 says so, proofs/ measures it.
template <class T>
HybridPatch<T> hybrid_elevate_salvi(const HybridPatch<T>& P);

}  // namespace splinex
