// Krawczyk's test (solve/krawczyk.hpp), instantiated for Rational, double and MPFR.
#include "solve/krawczyk.hpp"

#include <Eigen/Dense>

#include <utility>

#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "solve/testing.hpp"

namespace splinex::solve_detail {

namespace {

using solve_testing::Plant;

template <class T>
T from_dbl(double x) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return ArithTraits<T>::from_rational(exact_from_double(x, "solver"));
}

template <class T>
T tabs(const T& x) {
  return x < T(0) ? T(T(0) - x) : x;
}

}  // namespace

/// With the centre c (default: the box's centre); c - Y F(c) + (I - Y J(X)) (X - c).
template <class T>
KrawczykResult<T> krawczyk(const std::vector<Bernstein<T>>& f, std::size_t neq, bool strict, std::vector<T> c) {
  const int n = static_cast<int>(neq);
  KrawczykResult<T> out;
  if (c.empty()) c.assign(n, T(1) / T(2));
  std::vector<T> F(n);
  std::vector<std::vector<Bernstein<T>>> J(n, std::vector<Bernstein<T>>(n));
  // F'(c) with its rows scaled by 2^-e_i into double's range (D J), its inverse in double, and
  // Y = (D J)^-1 D taken exactly: entries beyond double's range do not defeat the test.
  Eigen::MatrixXd Jc(n, n);
  std::vector<long> e(n);
  for (int i = 0; i < n; ++i) {
    F[i] = bern_value(f[i], c);
    std::vector<T> row(n);
    for (int j = 0; j < n; ++j) {
      J[i][j] = bern_derivative(f[i], j);
      row[j] = bern_value(J[i][j], c);
    }
    e[i] = scale_exponent(row);
    const T s = pow2<T>(-e[i]);
    for (int j = 0; j < n; ++j) Jc(i, j) = dbl(T(row[j] * s));
  }
  if (!Jc.allFinite()) return out;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Jc);
  if (!lu.isInvertible()) return out;
  const Eigen::MatrixXd Yd = lu.inverse();
  if (!Yd.allFinite()) return out;
  std::vector<std::vector<T>> Y(n, std::vector<T>(n));
  for (int j = 0; j < n; ++j) {
    const T s = pow2<T>(-e[j]);
    for (int i = 0; i < n; ++i) Y[i][j] = from_dbl<T>(Yd(i, j)) * s;
  }
  std::vector<std::vector<std::pair<T, T>>> R(n, std::vector<std::pair<T, T>>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) R[i][j] = bern_range(J[i][j]);
  out.lo.resize(n);
  out.hi.resize(n);
  bool inside_open = true, inside_closed = true, excluded = false;
  // Test seams (solve/testing.hpp): the closed interior test, and c + Y F(c) for c - Y F(c).
  const bool closed_plant = solve_testing::planted(Plant::closed_interior), sign_plant = solve_testing::planted(Plant::krawczyk_wrong_sign);
  bool sound_open = true, sound_closed = true, sound_excluded = false;
  out.contraction = true;
  T reach(0);
  for (int j = 0; j < n; ++j) reach = tmax(reach, tmax(c[j], T(T(1) - c[j])));
  for (int i = 0; i < n; ++i) {
    T yf(0), sum(0);
    for (int k = 0; k < n; ++k) yf += Y[i][k] * F[k];
    for (int j = 0; j < n; ++j) {
      T slo(0), shi(0);  // the range of sum_k Y_ik J_kj over the box
      for (int k = 0; k < n; ++k) {
        const T p = Y[i][k] * R[k][j].first, q = Y[i][k] * R[k][j].second;
        slo += tmin(p, q);
        shi += tmax(p, q);
      }
      const T delta(i == j ? 1 : 0);
      sum += tmax(tabs(T(delta - slo)), tabs(T(delta - shi)));
    }
    // (X - c) is within [-m, m]^n, m the larger distance of c from a side: the i-th row adds
    // [-m sum, m sum].
    const T mid = c[i] - yf, rad = sum * reach;
    out.lo[i] = mid - rad;
    out.hi[i] = mid + rad;
    out.contraction = out.contraction && sum < T(1);
    if (sign_plant) {
      sound_excluded = sound_excluded || out.hi[i] < T(0) || T(1) < out.lo[i];
      sound_open = sound_open && T(0) < out.lo[i] && out.hi[i] < T(1);
      sound_closed = sound_closed && !(out.lo[i] < T(0)) && !(T(1) < out.hi[i]);
      const T wrong = c[i] + yf;
      out.lo[i] = wrong - rad;
      out.hi[i] = wrong + rad;
    }
    excluded = excluded || out.hi[i] < T(0) || T(1) < out.lo[i];
    inside_open = inside_open && T(0) < out.lo[i] && out.hi[i] < T(1);
    inside_closed = inside_closed && !(out.lo[i] < T(0)) && !(T(1) < out.hi[i]);
  }
  out.inside_closed = inside_closed;
  const auto outcome = [&](bool exc, bool open, bool closed) {
    return exc ? KrawczykResult<T>::excluded
               : open || (!strict && closed && out.contraction) ? KrawczykResult<T>::unique : KrawczykResult<T>::unknown;
  };
  out.outcome = outcome(excluded, inside_open, inside_closed);
  if (closed_plant && !excluded && !inside_open && inside_closed && out.outcome != KrawczykResult<T>::unique) {
    out.outcome = KrawczykResult<T>::unique;  // planted: K(X) in the closed box taken as in the open one
    solve_testing::plant_hit();
  }
  if (sign_plant) {  // a hit when K(X) moved (it then steers refinement) or the outcome changed
    bool moved = out.outcome != outcome(sound_excluded, sound_open, sound_closed);
    for (int i = 0; i < n && !moved; ++i) moved = !(F[i] == T(0));
    if (moved) solve_testing::plant_hit();
  }
  return out;
}

template KrawczykResult<Rational> krawczyk(const std::vector<Bernstein<Rational>>&, std::size_t, bool, std::vector<Rational>);
template KrawczykResult<double> krawczyk(const std::vector<Bernstein<double>>&, std::size_t, bool, std::vector<double>);
template KrawczykResult<Mpfr> krawczyk(const std::vector<Bernstein<Mpfr>>&, std::size_t, bool, std::vector<Mpfr>);

}  // namespace splinex::solve_detail
