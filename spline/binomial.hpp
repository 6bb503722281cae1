// Binomial coefficients in the arithmetic T.
#pragma once

namespace splinex::detail {

// Binomial coefficient as an exact T (T(integer) products; no floating intermediate).
template <class T>
T binomial(int n, int k) {
  if (k < 0 || k > n) return T(0);
  T r(1);
  for (int i = 1; i <= k; ++i) r = r * T(n - k + i) / T(i);
  return r;
}

}  // namespace splinex::detail
