// Knot-vector steps shared by the fraction-free operations (exact/ff_*.cpp), private.
#pragma once
#include <flint/fmpz_vec.h>
#include <gmp.h>

#include <string>

#include "exact/ff_int.hpp"

namespace splinex::ff::detail {

/// Fibres of direction d: `before` points of lower directions per step (contiguous), n steps,
/// `after` fibres of higher directions (spline/bspline.hpp's FibreLayout).
struct Layout {
  std::size_t before = 1, n = 0, after = 1;
};

inline void check_direction(const FFNet& F, int d) {
  if (d < 0 || d >= F.dim())
    throw UsageError("dir", "direction " + std::to_string(d) + " does not exist in a spline of dimension " +
                                std::to_string(F.dim()),
                     "give a direction in [0, " + std::to_string(F.dim() - 1) + "]");
}

inline Layout layout(const FFNet& F, int d) {
  check_direction(F, d);
  Layout f;
  for (int e = 0; e < d; ++e) f.before *= F.count(e);
  for (int e = d + 1; e < F.dim(); ++e) f.after *= F.count(e);
  f.n = F.count(d);
  return f;
}


/// The numerators of the given rationals over L = lcm(K.den, their denominators). When L is not
/// K.den, `scaled` receives K rewritten over L (otherwise it stays empty and K is the vector).
inline std::vector<Z> onto_knots(const FFKnots& K, FFKnots& scaled, const std::vector<Rational>& xs) {
  Z L, t, f;
  fmpz_set(L.get(), K.den.data());
  for (const Rational& x : xs) {
    fmpz_set_mpz(t.get(), mpq_denref(x.backend().data()));
    fmpz_lcm(L.get(), L.get(), t.get());
  }
  if (!fmpz_equal(L.get(), K.den.data())) {
    fmpz_divexact(f.get(), L.get(), K.den.data());
    scaled.k = ZVec(K.size());
    for (std::size_t j = 0; j < K.size(); ++j) mul(scaled.k + j, K.k + j, f.get());
    fmpz_set(scaled.den.data(), L.get());
  }
  std::vector<Z> out(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    fmpz_set_mpz(t.get(), mpq_denref(xs[i].backend().data()));
    fmpz_divexact(f.get(), L.get(), t.get());
    fmpz_set_mpz(t.get(), mpq_numref(xs[i].backend().data()));
    fmpz_mul(out[i].get(), t.get(), f.get());
  }
  return out;
}

/// K over the lcm of its knots' reduced denominators, which is K / gcd(K, k_0, ..., k_last):
/// the unique form, after an operation that dropped knots.
inline void normalize(FFKnots& K) {
  Z g;
  _fmpz_vec_content(g.get(), K.k.data(), static_cast<slong>(K.size()));
  fmpz_gcd(g.get(), g.get(), K.den.data());
  if (fmpz_is_one(g.get())) return;
  _fmpz_vec_scalar_divexact_fmpz(K.k.data(), K.k.data(), static_cast<slong>(K.size()), g.get());
  fmpz_divexact(K.den.data(), K.den.data(), g.get());
}

/// Index of the first knot > x (std::upper_bound on the integers).
inline std::size_t upper(const FFKnots& U, const fmpz* x) {
  std::size_t lo = 0, hi = U.size();
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (cmp(x, U.k + mid) < 0) hi = mid; else lo = mid + 1;
  }
  return lo;
}
/// Index of the first knot >= x.
inline std::size_t lower(const FFKnots& U, const fmpz* x) {
  std::size_t lo = 0, hi = U.size();
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (cmp(U.k + mid, x) < 0) lo = mid + 1; else hi = mid;
  }
  return lo;
}
inline std::size_t multiplicity(const FFKnots& U, const fmpz* x) { return upper(U, x) - lower(U, x); }

/// insert_knot and refine_knots after their knots are on one denominator: U is direction d's knot
/// vector over it (F's own, or F's rewritten), xk / xs the numerators (xs sorted). The checks,
/// errors and limits of the public functions.
FFNet insert_on(const FFNet& F, int d, const FFKnots& U, const fmpz* xk, int times, const Limits& limits);
FFNet refine_on(const FFNet& F, int d, const FFKnots& U, const std::vector<Z>& xs, const Limits& limits);

/// The control points [first, first + n_new) of direction d, with that direction's knots V.
FFNet slice_direction(const FFNet& F, int d, std::size_t first, std::size_t n_new, FFKnots V);

/// spline/knots.hpp's is_clamped and breakpoints on integer knots (breakpoints as indices into U
/// of the first knot of each distinct value in the domain).
bool is_clamped(const FFKnots& U, int p, std::size_t n);
std::vector<std::size_t> breakpoints(const FFKnots& U, int p, std::size_t n);

}  // namespace splinex::ff::detail
