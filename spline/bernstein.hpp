// The Bernstein basis and binomial coefficients in the arithmetic T: the one home of both
// (The NURBS Book, Section 1.3).
#pragma once
#include <vector>

namespace splinex {

namespace detail {

/// Binomial coefficient C(n, k) as an exact T (T(integer) products and exact quotients; no
/// floating intermediate; 0 outside 0 <= k <= n).
template <class T>
T binomial(int n, int k) {
  if (k < 0 || k > n) return T(0);
  T r(1);
  for (int i = 1; i <= k; ++i) r = r * T(n - k + i) / T(i);
  return r;
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
