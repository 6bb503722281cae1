// Exact helpers the solver tests share, independent of the solver: univariate polynomials from
// roots in Bernstein form, and the reproducers of tests/data/repro/solver.
#pragma once
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bernstein/tensor.hpp"
#include "exact/rational.hpp"
#include "tests/helpers.hpp"

namespace splinex::solve_fixtures {

/// C(n, k) exactly.
inline Rational binom(int n, int k) {
  Rational r(1);
  for (int i = 1; i <= k; ++i) r = r * Rational(n - k + i) / Rational(i);
  return r;
}

/// Power coefficients (t^0, t^1, ...) of prod (t - r_i).
inline std::vector<Rational> from_roots(const std::vector<Rational>& roots) {
  std::vector<Rational> a{Rational(1)};
  for (const auto& r : roots) {
    std::vector<Rational> b(a.size() + 1, Rational(0));
    for (std::size_t k = 0; k < a.size(); ++k) {
      b[k + 1] += a[k];
      b[k] -= r * a[k];
    }
    a = b;
  }
  return a;
}

/// The Bernstein form on [0, 1] of sum a[k] t^k (b_i = sum_k C(i,k)/C(n,k) a_k).
inline Bernstein<Rational> univariate(const std::vector<Rational>& a) {
  const int n = static_cast<int>(a.size()) - 1;
  Bernstein<Rational> b{{n}, std::vector<Rational>(n + 1, Rational(0))};
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k) b.c[i] += binom(i, k) / binom(n, k) * a[k];
  return b;
}

/// The Bernstein form on [0, 1]^2 of degrees (n, m) of sum a[{k, l}] x^k y^l (an independent
/// conversion, b_ij = sum C(i,k)/C(n,k) C(j,l)/C(m,l) a_kl).
inline Bernstein<Rational> bivariate(int n, int m, const std::map<std::pair<int, int>, Rational>& a) {
  Bernstein<Rational> b{{n, m}, std::vector<Rational>((n + 1) * (m + 1), Rational(0))};
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i)
      for (const auto& [e, c] : a)
        if (e.first <= i && e.second <= j)
          b.c[i + (n + 1) * j] += binom(i, e.first) / binom(n, e.first) * binom(j, e.second) / binom(m, e.second) * c;
  return b;
}

/// The fold of the curve-projection tests: z = x^2 (a parabolic cylinder) over [-1, 1]^2 as a
/// biquadratic B-spline, and the vertical line (1/10, 0, t), t in [0, 2] (test_projection.cpp).
inline BSpline<Rational> fold_surface() {
  return test::spline(R"({"type": "bspline", "degrees": [2, 2], "knots": [[-1, -1, -1, 1, 1, 1], [-1, -1, -1, 1, 1, 1]],
    "points": [[-1, -1, 1], [0, -1, -1], [1, -1, 1], [-1, 0, 1], [0, 0, -1], [1, 0, 1], [-1, 1, 1], [0, 1, -1], [1, 1, 1]]})");
}
inline BSpline<Rational> fold_line() {
  return test::spline(R"({"type": "bspline", "degrees": [1], "knots": [[0, 0, 2, 2]], "points": [["1/10", 0, 0], ["1/10", 0, 2]]})");
}

/// The reproducer `name` of tests/data/repro/solver (copied from ../shared/repro/solver).
inline BSpline<Rational> repro(const std::string& name) {
  const std::string file = __FILE__;
  std::ifstream in(file.substr(0, file.rfind('/')) + "/../data/repro/solver/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return test::spline(text.str());
}

}  // namespace splinex::solve_fixtures
