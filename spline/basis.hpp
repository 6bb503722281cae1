// B-spline basis functions: NURBS Book A2.2 (BasisFuns) and A2.3 (DersBasisFuns).
#pragma once
#include <cstddef>
#include <type_traits>
#include <vector>

#include "spline/arith.hpp"

namespace splinex {

/// A2.2 into caller storage: N[0..p] receives the p+1 non-zero basis functions N_{s-p..s,p}(x) on
/// span s; left and right hold p+1 scratch values, den and temp two more. Written with compound
/// operations only, so an exact scalar reuses the storage it holds (no temporaries); in floating
/// point every operation is the one of A2.2, in the same order.
template <class T>
void basis_funs_into(std::size_t s, const T& x, int p, const std::vector<T>& U, T* N, T* left, T* right, T& den, T& temp) {
  if constexpr (std::is_floating_point_v<T>) {
    // The same operations on locals the compiler may keep in registers: through T& parameters
    // that may alias, every step was a store and a reload (measured: half the time of eval).
    T* __restrict n = N;
    T* __restrict l = left;
    T* __restrict rt = right;
    n[0] = T(1);
    for (int j = 1; j <= p; ++j) {
      l[j] = x - U[s + 1 - j];
      rt[j] = U[s + j] - x;
      T saved = 0;
      for (int r = 0; r < j; ++r) {
        const T tq = n[r] / (rt[r + 1] + l[j - r]);
        n[r] = saved + rt[r + 1] * tq;
        saved = l[j - r] * tq;
      }
      n[j] = saved;
    }
    (void)den;
    (void)temp;
    return;
  }
  N[0] = one_value<T>();
  for (int j = 1; j <= p; ++j) {
    left[j] = x;
    left[j] -= U[s + 1 - j];
    right[j] = U[s + j];
    right[j] -= x;
    // The j quotients first: they do not depend on each other, so a pipelined divider overlaps
    // them (one loop with the running sum waited for each division in turn). N[r] holds the
    // quotient until the second loop replaces it; the operations and operands are the book's.
    for (int r = 0; r < j; ++r) {
      den = right[r + 1];
      den += left[j - r];
      N[r] /= den;  // temp_r = N[r] / (right[r+1] + left[j-r])
    }
    T& saved = N[j];  // N[j] is written last, so it holds `saved` meanwhile
    saved = zero_value<T>();
    for (int r = 0; r < j; ++r) {
      temp = N[r];
      N[r] = right[r + 1];
      N[r] *= temp;
      N[r] += saved;  // N[r] = saved + right[r+1] * temp_r
      saved = left[j - r];
      saved *= temp;
    }
  }
}

/// A2.2: the p+1 non-zero basis functions N_{s-p..s,p}(x) on span s.
template <class T>
std::vector<T> basis_funs(std::size_t s, const T& x, int p, const std::vector<T>& U) {
  std::vector<T> N(p + 1), left(p + 1), right(p + 1);
  T den, temp;
  basis_funs_into(s, x, p, U, N.data(), left.data(), right.data(), den, temp);
  return N;
}

/// A2.3: ders[k][j] = k-th derivative of N_{s-p+j,p} at x, k = 0..nd (rows past p are zero).
template <class T>
std::vector<std::vector<T>> ders_basis_funs(std::size_t s, const T& x, int p, int nd, const std::vector<T>& U) {
  std::vector<std::vector<T>> ndu(p + 1, std::vector<T>(p + 1)), a(2, std::vector<T>(p + 1));
  std::vector<T> left(p + 1), right(p + 1);
  ndu[0][0] = T(1);
  for (int j = 1; j <= p; ++j) {
    left[j] = x - U[s + 1 - j];
    right[j] = U[s + j] - x;
    T saved(0);
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      T temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  std::vector<std::vector<T>> ders(nd + 1, std::vector<T>(p + 1, T(0)));
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = T(1);
    for (int k = 1; k <= nd && k <= p; ++k) {
      T d(0);
      int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      int j1 = (rk >= -1) ? 1 : -rk;
      int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  T f(p);
  for (int k = 1; k <= nd && k <= p; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= f;
    f *= T(p - k);
  }
  return ders;
}

}  // namespace splinex
