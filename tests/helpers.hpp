#pragma once
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "io/json_io.hpp"

namespace splinex::test {

inline Json doc(const std::string& text) {
  std::istringstream in(text);
  return read_json(in, "test");
}
inline BSpline<Rational> spline(const std::string& text, const Limits& limits = {}) {
  return spline_from_json(doc(text), limits);
}
inline Rational q(const char* s) { return parse_number(s, "test"); }

/// The field g(x) = a.x + d on a polynomial trivariate V: by affine invariance its control values
/// are g at V's control points, exactly, so it equals g at every point of the cell (an oracle
/// independent of the code that carries or integrates fields).
inline BSpline<Rational> affine_field(const BSpline<Rational>& V, const std::array<Rational, 3>& a, const Rational& d) {
  BSpline<Rational> F = V;
  F.q = 1;
  F.points.clear();
  for (std::size_t i = 0; i < V.size(); ++i)
    F.points.push_back(a[0] * V.points[i * V.q] + a[1] * V.points[i * V.q + 1] + a[2] * V.points[i * V.q + 2] + d);
  return F;
}

/// The unit sphere by inverse stereographic projection, (2u, 2v, u^2 + v^2 - 1) / (1 + u^2 + v^2) on
/// [0, 1]^2: a rational biquadratic patch exactly on the sphere (its Bernstein coefficients from
/// the power form, b_ij = sum C(i,k)/C(2,k) C(j,l)/C(2,l) a_kl); tests/data/sphere_patch.json.
inline BSpline<Rational> stereographic_sphere() {
  const auto binom2 = [](int i, int k) { return Rational(i == 2 && k == 1 ? 2 : (k <= i ? 1 : 0)) / Rational(k == 1 ? 2 : 1); };
  const auto bern22 = [&](const std::vector<std::array<int, 3>>& a) {  // {k, l, coefficient}
    std::vector<Rational> b(9, Rational(0));
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i)
        for (const auto& t : a)
          if (t[0] <= i && t[1] <= j) b[i + 3 * j] += binom2(i, t[0]) * binom2(j, t[1]) * t[2];
    return b;
  };
  const auto W = bern22({{0, 0, 1}, {2, 0, 1}, {0, 2, 1}}), X = bern22({{1, 0, 2}}), Y = bern22({{0, 1, 2}});
  const auto Z = bern22({{2, 0, 1}, {0, 2, 1}, {0, 0, -1}});
  BSpline<Rational> S;
  S.degrees = {2, 2};
  const std::vector<Rational> k{0, 0, 0, 1, 1, 1};
  S.knots = {k, k};
  S.q = 3;
  for (int i = 0; i < 9; ++i)
    for (const auto* c : {&X, &Y, &Z}) S.points.push_back((*c)[i] / W[i]);
  S.weights = W;
  validate(S);
  return S;
}

}  // namespace splinex::test
