// The integer steps of the fraction-free kernel (exact/ffnet.hpp), private to exact/ff_*.cpp.
//
// Every step has a small path on FLINT's inline words (|v| <= COEFF_MAX = 2^62 - 1): products in
// 128 bits, the result checked against the small range before it is stored. When an operand is
// big or the result leaves the range, the step is redone with FLINT's integer calls (counted in
// ff::promotions()). No signed 64-bit operation can overflow: every product and sum of two
// small words is computed in __int128, where it fits.
#pragma once
#include <flint/fmpz.h>

#include <cstdint>
#include <cstring>

#include "exact/ffnet.hpp"

namespace splinex::ff::detail {

__extension__ typedef __int128 i128;  // GCC's 128-bit integer (-Wpedantic: an extension)

/// An owned FLINT integer (freed on every path out, exceptions included).
struct Z {
  fmpz_t v;
  Z() { fmpz_init(v); }
  Z(const Z& o) { fmpz_init_set(v, o.v); }
  Z(Z&& o) noexcept { *v = *o.v; *o.v = 0; }
  Z& operator=(const Z& o) { fmpz_set(v, o.v); return *this; }
  Z& operator=(Z&& o) noexcept { fmpz_swap(v, o.v); return *this; }
  ~Z() { fmpz_clear(v); }
  fmpz* get() { return v; }
  const fmpz* get() const { return v; }
};

inline bool small(const fmpz* a) { return !COEFF_IS_MPZ(*a); }
inline bool fast() { return policy().tier == Tier::small_first; }
inline bool fits(i128 v) { return v >= -static_cast<i128>(COEFF_MAX) && v <= static_cast<i128>(COEFF_MAX); }

/// out = v for a value known to fit the small range.
inline void set_small(fmpz* out, slong v) {
  if (COEFF_IS_MPZ(*out)) _fmpz_demote(out);
  *out = v;
}

inline void set(fmpz* out, const fmpz* a) {
  if (small(a) && small(out)) *out = *a;
  else fmpz_set(out, a);
}

/// Whether any of n words holds a big value (a tagged mpz pointer, which FLINT stores as a word
/// above COEFF_MAX). One branch-free pass the compiler vectorises.
inline bool any_big(const fmpz* p, std::size_t n) {
  // A big word has its top two bits 01; a small value 00 (>= 0) or 11 (< 0). Bit 63 of
  // ~w & (w << 1) is set exactly for 01: plain bit operations, vectorised on any x86-64.
  std::uint64_t acc = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto w = static_cast<std::uint64_t>(p[i]);
    acc |= ~w & (w << 1);
  }
  return (acc >> 63) != 0;
}

/// Copies n values into words that hold no big value (zeros or small values): a memcpy, and for
/// big values their own copies (the words are zeroed first, so an allocation failure part way
/// leaves only valid words behind). Returns whether a big value was copied.
inline bool init_copy(fmpz* dst, const fmpz* src, std::size_t n) {
  std::uint64_t acc = 0;  // any_big, fused with the copy: one pass over the words
  for (std::size_t i = 0; i < n; ++i) {
    const auto w = static_cast<std::uint64_t>(src[i]);
    acc |= ~w & (w << 1);
    dst[i] = src[i];
  }
  if ((acc >> 63) == 0) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (!small(src + i)) dst[i] = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!small(src + i)) fmpz_set(dst + i, src + i);
  return true;
}

/// Copies n values into words that hold values (a memcpy when neither side holds a big one).
inline void copy_block(fmpz* dst, const fmpz* src, std::size_t n) {
  if (!any_big(dst, n) && !any_big(src, n)) {
    std::memmove(dst, src, n * sizeof(fmpz));
    return;
  }
  for (std::size_t i = 0; i < n; ++i) fmpz_set(dst + i, src + i);
}

/// out = a*x + b*y (out may alias any operand).
inline void lin2(fmpz* out, const fmpz* a, const fmpz* x, const fmpz* b, const fmpz* y) {
  if (fast() && small(a) && small(x) && small(b) && small(y)) {
    const i128 v = static_cast<i128>(*a) * *x + static_cast<i128>(*b) * *y;
    if (fits(v)) return set_small(out, static_cast<slong>(v));
    ++promotions();
  }
  Z t;
  fmpz_mul(t.get(), a, x);
  fmpz_addmul(t.get(), b, y);
  fmpz_swap(out, t.get());
}

/// out = a*b (out may alias).
inline void mul(fmpz* out, const fmpz* a, const fmpz* b) {
  if (fast() && small(a) && small(b)) {
    const i128 v = static_cast<i128>(*a) * *b;
    if (fits(v)) return set_small(out, static_cast<slong>(v));
    ++promotions();
  }
  fmpz_mul(out, a, b);
}

/// out = a - b (out may alias).
inline void sub(fmpz* out, const fmpz* a, const fmpz* b) {
  if (fast() && small(a) && small(b)) {
    const i128 v = static_cast<i128>(*a) - *b;
    if (fits(v)) return set_small(out, static_cast<slong>(v));
    ++promotions();
  }
  fmpz_sub(out, a, b);
}

inline int cmp(const fmpz* a, const fmpz* b) {
  if (small(a) && small(b)) return (*a > *b) - (*a < *b);
  return fmpz_cmp(a, b);
}

inline std::uint64_t small_abs(slong v) { return v < 0 ? -static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v); }

inline std::uint64_t binary_gcd(std::uint64_t a, std::uint64_t b) {
  if (a == 0) return b;
  if (b == 0) return a;
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return a << shift;
}

/// Divides the m numerators and the denominator (at p[m], > 0) of one point by their gcd, so
/// that the point's representation is the unique reduced one.
inline void reduce_point(fmpz* p, std::size_t m) {
  bool all_small = true;
  for (std::size_t c = 0; c <= m && all_small; ++c) all_small = small(p + c);
  if (all_small) {
    std::uint64_t g = static_cast<std::uint64_t>(p[m]);
    for (std::size_t c = 0; c < m && g != 1; ++c) g = binary_gcd(g, small_abs(p[c]));
    if (g <= 1) return;
    const slong gs = static_cast<slong>(g);
    for (std::size_t c = 0; c <= m; ++c) p[c] /= gs;
    return;
  }
  Z g;
  fmpz_set(g.get(), p + m);
  for (std::size_t c = 0; c < m && !fmpz_is_one(g.get()); ++c) fmpz_gcd(g.get(), g.get(), p + c);
  if (!fmpz_is_one(g.get()))
    for (std::size_t c = 0; c <= m; ++c) fmpz_divexact(p + c, p + c, g.get());
}

/// reduce_point only when the denominator has grown past 2^48 (or is big): the integers stay short
/// enough for 64-bit products without a gcd per step (a gcd of four 60-bit words costs more than
/// the blend that made them), and a blend's coefficients (knot differences, usually below 2^14)
/// times such a point still fit FLINT's 62-bit words. Every point an operation stores goes through
/// it. (2^30 reduced at p = 7 on most blends: bench_kernel exact/double, refine 11 -> 7, elevate
/// 48 -> 37, evaluation 36 -> 31 at 2^48; beyond 2^50 nothing more is gained.)
inline void reduce_if_long(fmpz* p, std::size_t m) {
  if (!small(p + m) || p[m] > (slong(1) << 48)) reduce_point(p, m);
}

/// Two positive word denominators brought onto their lcm: a/EA + b/EB = (a fa + b fb) / lcm with
/// fa = EB/g, fb = EA/g, g = gcd(EA, EB) (fa = fb = 1 when they are equal). lcm < 2^124.
struct WordLcm {
  i128 fa, fb, lcm;
};
inline WordLcm word_lcm(slong EA, slong EB) {
  if (EA == EB) return {1, 1, EA};
  const slong g = static_cast<slong>(binary_gcd(static_cast<std::uint64_t>(EA), static_cast<std::uint64_t>(EB)));
  return {EB / g, EA / g, static_cast<i128>(EA) * (EB / g)};
}

/// One fraction-free de Casteljau/de Boor step on homogeneous points of m numerators and a
/// denominator: out = ((t - s) P + s Q) / t with t > 0, reduced when long. `out` may be P or Q.
struct Blend {
  Z a_, c1_, c2_, e_, g_;
  fmpz* a = a_.get();
  fmpz* c1 = c1_.get();
  fmpz* c2 = c2_.get();
  fmpz* e = e_.get();
  fmpz* g = g_.get();
  Blend() = default;
  Blend(const Blend&) = delete;
  Blend& operator=(const Blend&) = delete;

  void operator()(fmpz* out, const fmpz* P, const fmpz* Q, const fmpz* s, const fmpz* t, std::size_t m) {
    if (m <= kWordsMax && words(out, P, Q, s, t, m)) return;
    sub(a, t, s);
    if (cmp(P + m, Q + m) == 0) {
      // Same denominator E: N = (t - s) N_P + s N_Q over t E.
      for (std::size_t c = 0; c < m; ++c) lin2(out + c, a, P + c, s, Q + c);
      mul(out + m, t, P + m);
    } else {
      // Over the lcm: with g = gcd(E_P, E_Q), N = (t - s)(E_Q/g) N_P + s (E_P/g) N_Q over
      // t (E_P/g) E_Q. The products stay smaller than over E_P E_Q, so more of them fit 62 bits.
      if (small(P + m) && small(Q + m)) {
        const slong gs = static_cast<slong>(binary_gcd(static_cast<std::uint64_t>(P[m]), static_cast<std::uint64_t>(Q[m])));
        set_small(g, gs);
        set_small(c2, P[m] / gs);  // E_P / g
        set_small(e, Q[m] / gs);   // E_Q / g
      } else {
        fmpz_gcd(g, P + m, Q + m);
        fmpz_divexact(c2, P + m, g);
        fmpz_divexact(e, Q + m, g);
      }
      mul(c1, a, e);        // (t - s) E_Q / g
      mul(e, c2, Q + m);    // (E_P / g) E_Q: the lcm
      mul(c2, s, c2);       // s E_P / g
      for (std::size_t c = 0; c < m; ++c) lin2(out + c, c1, P + c, c2, Q + c);
      mul(out + m, t, e);
    }
    reduce_if_long(out, m);
  }

 private:
  static constexpr std::size_t kWordsMax = 7;
  /// The blend when every operand is a small word and every product fits one: plain 64-bit words
  /// and 128-bit products, no FLINT call. Returns false (nothing written) otherwise.
  static bool words(fmpz* out, const fmpz* P, const fmpz* Q, const fmpz* s, const fmpz* t, std::size_t m) {
    if (!fast() || !small(s) || !small(t) || any_big(P, m + 1) || any_big(Q, m + 1)) return false;
    const slong S = *s, T = *t;
    const WordLcm L = word_lcm(P[m], Q[m]);
    if (!fits(L.lcm)) return false;  // then t times it does not fit either (t >= 1)
    const i128 c1 = (static_cast<i128>(T) - S) * L.fa;  // |t - s| < 2^63, fa < 2^62: fits
    const i128 c2 = static_cast<i128>(S) * L.fb;
    const i128 E = static_cast<i128>(T) * L.lcm;
    if (!fits(c1) || !fits(c2) || !fits(E)) return false;
    slong v[kWordsMax + 1];
    for (std::size_t c = 0; c < m; ++c) {
      const i128 x = c1 * P[c] + c2 * Q[c];  // each product < 2^124: the sum fits
      if (!fits(x)) return false;
      v[c] = static_cast<slong>(x);
    }
    v[m] = static_cast<slong>(E);
    for (std::size_t c = 0; c <= m; ++c) set_small(out + c, v[c]);
    reduce_if_long(out, m);
    return true;
  }
};

}  // namespace splinex::ff::detail
