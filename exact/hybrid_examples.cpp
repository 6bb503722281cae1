#include "exact/hybrid_examples.hpp"

namespace splinex {

std::vector<Rational> uniform_clamped_knots(int d, int p) {
  std::vector<Rational> U(p + 1, Rational(0));
  const int inner = d - p;  // d + 1 functions of degree p
  for (int k = 1; k <= inner; ++k) U.push_back(Rational(k, inner + 1));
  U.insert(U.end(), p + 1, Rational(1));
  return U;
}

HybridPatch<Rational> hybrid_dome(const std::vector<std::array<Rational, 2>>& V, int d, const std::vector<int>& p,
                                  const std::vector<std::vector<Rational>>& knots) {
  HybridPatch<Rational> P;
  P.vertices = V;
  P.d = d;
  P.p = p;
  P.knots = knots;
  P.q = 3;
  const std::size_t n = V.size();
  const int l = P.layers();
  std::array<Rational, 2> G{0, 0};
  for (const auto& v : V) {
    G[0] += v[0] / static_cast<long>(n);
    G[1] += v[1] / static_cast<long>(n);
  }
  P.points.assign(n * l * (d + 1) * 3, Rational(0));
  for (std::size_t i = 0; i < n; ++i) {
    const auto &A = V[i], &B = V[(i + 1) % n], &Pv = V[(i + n - 1) % n], &Nx = V[(i + 2) % n];
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        std::array<Rational, 2> x;
        const Rational sj(j, d), tk(k, d);
        for (int c = 0; c < 2; ++c) {
          if (j < l)
            x[c] = A[c] + sj * (B[c] - A[c]) + tk * (Pv[c] - A[c]);
          else if (j > d - l)
            x[c] = B[c] + Rational(d - j, d) * (A[c] - B[c]) + tk * (Nx[c] - B[c]);
          else {
            const Rational E = A[c] + sj * (B[c] - A[c]);
            x[c] = E + 2 * tk * (G[c] - E);
          }
        }
        const Rational r2 = (x[0] - G[0]) * (x[0] - G[0]) + (x[1] - G[1]) * (x[1] - G[1]);
        const std::size_t at = P.index(i, j, k);
        P.points[at] = x[0];
        P.points[at + 1] = x[1];
        P.points[at + 2] = 1 - 2 * r2;
      }
  }
  validate(P);
  return P;
}

HybridPatch<Rational> hybrid_example_2_1() {
  const Rational h(1, 2);
  const std::vector<Rational> U{0, 0, 0, Rational(1, 5), Rational(2, 5), Rational(3, 5), Rational(4, 5), 1, 1, 1};
  return hybrid_dome({{0, 0}, {1, 0}, {1, h}, {h, 1}, {0, 1}}, 6, std::vector<int>(5, 2), std::vector<std::vector<Rational>>(5, U));
}

HybridPatch<Rational> hybrid_example_3_1_hexagon() {
  const Rational a(1, 3), b(2, 3);
  const std::vector<int> p{5, 3, 2, 4, 4, 2};
  std::vector<std::vector<Rational>> U;
  for (int pi : p) U.push_back(uniform_clamped_knots(6, pi));
  return hybrid_dome({{a, 0}, {1, 0}, {1, b}, {b, 1}, {0, 1}, {0, a}}, 6, p, U);
}

HybridPatch<Rational> hybrid_example_3_1_octagon() {
  const Rational a(1, 4), b(3, 4);
  const std::vector<Rational> U{0, 0, 0, Rational(1, 5), Rational(2, 5), Rational(3, 5), Rational(4, 5), 1, 1, 1};
  return hybrid_dome({{a, 0}, {b, 0}, {1, a}, {1, b}, {b, 1}, {a, 1}, {0, b}, {0, a}}, 6, std::vector<int>(8, 2),
                     std::vector<std::vector<Rational>>(8, U));
}

}  // namespace splinex
