// The Bernstein basis and binomial coefficients in the arithmetic T: the one home of both
// (The NURBS Book, Section 1.3).
#pragma once
#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace splinex {

namespace detail {

/// Binomial coefficient C(n, k) as a T: computed in 64-bit integers where it fits (C(n, k) < 2^63;
/// one conversion to T), else by products and quotients in T (exact for exact T); 0 outside
/// 0 <= k <= n.
template <class T>
T binomial(int n, int k) {
  if (k < 0 || k > n) return T(0);
  {
    // In integers while C(n - kk + i, i) fits in 63 bits (always for n <= 62): r (n - k + i) / i
    // is an integer at every step (r = C(n - kk + i - 1, i - 1)); with g = gcd(r, i), i / g
    // divides n - k + i, so no intermediate exceeds the next value, and an overflow is detected.
    // One conversion to T (exact for exact T, correctly rounded otherwise) instead of k
    // multiplications and divisions in T (with a gcd each for rationals: a quarter of the time of
    // exact Bernstein products).
    const int kk = std::min(k, n - k);
    unsigned long long r = 1;
    bool fits = true;
    for (int i = 1; i <= kk && fits; ++i) {
      const unsigned long long g = std::gcd(r, static_cast<unsigned long long>(i));
      fits = !__builtin_mul_overflow(r / g, static_cast<unsigned long long>(n - kk + i) / (static_cast<unsigned long long>(i) / g), &r) &&
             r <= static_cast<unsigned long long>(std::numeric_limits<long>::max());
    }
    if (fits) return T(static_cast<long>(r));
  }
  T r(1);
  for (int i = 1; i <= k; ++i) r = r * T(n - k + i) / T(i);
  return r;
}

/// C(n, 0), ..., C(n, n) as T, equal to binomial<T>(n, i) each: by C(n, i + 1) = C(n, i) (n - i) /
/// (i + 1) in integers while the values fit in a long (always for n <= 62; with g = gcd(C(n, i),
/// i + 1), (i + 1) / g divides n - i, so nothing exceeds the next value), else binomial<T>. One row
/// costs n integer steps instead of n gcd loops.
template <class T>
std::vector<T> binomial_row(int n) {
  std::vector<T> row;
  row.reserve(static_cast<std::size_t>(n) + 1);
  unsigned long long r = 1;
  bool fits = true;
  for (int i = 0; i <= n; ++i) {
    if (fits) row.push_back(T(static_cast<long>(r)));
    else row.push_back(binomial<T>(n, i));
    if (fits && i < n) {
      const unsigned long long d = static_cast<unsigned long long>(i) + 1, g = std::gcd(r, d);
      fits = !__builtin_mul_overflow(r / g, static_cast<unsigned long long>(n - i) / (d / g), &r) &&
             r <= static_cast<unsigned long long>(std::numeric_limits<long>::max());
    }
  }
  return row;
}

/// x^e for e >= 0 by e multiplications in T.
template <class T>
T power(const T& x, int e) {
  T r(1);
  for (int i = 0; i < e; ++i) r = r * x;
  return r;
}

}  // namespace detail

/// All Bernstein polynomials of degree d at t: B_j^d(t) = C(d, j) t^j (1 - t)^(d - j), j = 0..d
/// (The NURBS Book, Eq. 1.8).
template <class T>
std::vector<T> bernstein_all(int d, const T& t) {
  std::vector<T> b(d + 1);
  const T u = T(1) - t;
  for (int j = 0; j <= d; ++j) b[j] = detail::binomial<T>(d, j) * detail::power(t, j) * detail::power(u, d - j);
  return b;
}

/// Power-basis coefficients c_k (sum_k c_k t^k) of the polynomial sum_i b_i B_i^n(t):
/// c_k = sum_{i <= k} b_i C(n, i) C(n - i, k - i) (-1)^(k - i).
template <class T>
std::vector<T> bernstein_to_power(const std::vector<T>& b) {
  const int n = static_cast<int>(b.size()) - 1;
  std::vector<T> c(n + 1, T(0));
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= k; ++i) {
      T term = b[i] * detail::binomial<T>(n, i) * detail::binomial<T>(n - i, k - i);
      c[k] += ((k - i) % 2) ? T(-term) : term;
    }
  return c;
}

}  // namespace splinex
