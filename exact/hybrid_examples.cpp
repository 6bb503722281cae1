#include "exact/hybrid_examples.hpp"

#include <algorithm>

#include "spline/kernel.hpp"

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

namespace {

Rational host_f(const Rational& x, const Rational& y) { return (x * x + y * y) / 4 - x * y / 3 + x / 5; }

// A_i: Bezier (2, 2) interpolation of (X, f(X)) at s, t in {0, 1/2, 1}, then degree p in s and
// side i's interior knots inserted (kernel).
BSpline<Rational> neighbour(const std::array<Rational, 2>& A, const std::array<Rational, 2>& E, const std::array<Rational, 2>& W0,
                            const std::array<Rational, 2>& W1, int p, const std::vector<Rational>& U) {
  auto G = [&](const Rational& s, const Rational& t) {
    std::array<Rational, 3> g;
    for (int c = 0; c < 2; ++c) g[c] = A[c] + s * E[c] + t * ((1 - s) * W0[c] + s * W1[c]);
    g[2] = host_f(g[0], g[1]);
    return g;
  };
  const Rational h(1, 2);
  const Rational at[3] = {Rational(0), h, Rational(1)};
  std::array<std::array<std::array<Rational, 3>, 3>, 3> F;  // F[a][b] = G(at[a], at[b])
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) F[a][b] = G(at[a], at[b]);
  // Quadratic Bernstein interpolation at 0, 1/2, 1: b0 = F0, b2 = F1, b1 = 2 F(1/2) - (F0 + F1)/2.
  auto solve = [](const Rational& f0, const Rational& fh, const Rational& f1) {
    return std::array<Rational, 3>{f0, 2 * fh - (f0 + f1) / 2, f1};
  };
  BSpline<Rational> S;
  S.degrees = {2, 2};
  S.knots = {{0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  S.q = 3;
  S.points.assign(27, Rational(0));
  for (int c = 0; c < 3; ++c) {
    std::array<std::array<Rational, 3>, 3> tmp;  // solved in s for each t sample
    for (int b = 0; b < 3; ++b) {
      const auto r = solve(F[0][b][c], F[1][b][c], F[2][b][c]);
      for (int j = 0; j < 3; ++j) tmp[j][b] = r[j];
    }
    for (int j = 0; j < 3; ++j) {
      const auto r = solve(tmp[j][0], tmp[j][1], tmp[j][2]);
      for (int k = 0; k < 3; ++k) S.points[(k * 3 + j) * 3 + c] = r[k];
    }
  }
  if (p > 2) S = elevate_degree(S, 0, p - 2);
  std::vector<Rational> inner(U.begin() + p + 1, U.end() - p - 1);
  if (!inner.empty()) S = refine_knots(S, 0, inner);
  if (S.knots[0] != U) throw ValidationError("knots", "of the neighbour do not match side's", "internal: check hybrid_hole_example_3_2");
  return S;
}

}  // namespace

HybridHole hybrid_hole_example_3_2(int n) {
  HybridPatch<Rational> base;
  if (n == 5) {
    const Rational h(1, 2), q(1, 4);
    const std::vector<Rational> U{0, 0, 0, q, h, 3 * q, 1, 1, 1};
    base = hybrid_dome({{0, 0}, {1, 0}, {1, h}, {h, 1}, {0, 1}}, 5, std::vector<int>(5, 2), std::vector<std::vector<Rational>>(5, U));
  } else if (n == 6) {
    base = hybrid_example_3_1_hexagon();
  } else {
    throw UsageError("n", "is " + std::to_string(n) + "; Example 3.2 has a five-sided and a six-sided hole", "give 5 or 6");
  }
  const std::size_t N = base.sides();
  const int d = base.d, l = base.layers();
  std::vector<Rational> tau(N), sigma(N);  // start (ribbon) factor and end-span factor per side
  for (std::size_t i = 0; i < N; ++i) {
    const auto& U = base.knots[i];
    tau[i] = Rational(base.p[i]) / U[base.p[i] + 1];
    sigma[i] = Rational(base.p[i]) / (1 - U[d]);
  }
  HybridHole H;
  std::vector<std::vector<Rational>> demand(N);  // D^i_{j,k}, k = 0, 1, at (k (d+1) + j) * 3
  for (std::size_t i = 0; i < N; ++i) {
    const auto& V = base.vertices;
    const auto &A = V[i], &B = V[(i + 1) % N], &Pv = V[(i + N - 1) % N], &Nx = V[(i + 2) % N];
    const Rational a = tau[i] / sigma[(i + N - 1) % N], b = tau[i] / tau[(i + 1) % N];
    const std::array<Rational, 2> E{B[0] - A[0], B[1] - A[1]}, W0{a * (A[0] - Pv[0]), a * (A[1] - Pv[1])},
        W1{b * (B[0] - Nx[0]), b * (B[1] - Nx[1])};
    H.neighbours.push_back(neighbour(A, E, W0, W1, base.p[i], base.knots[i]));
    const auto& S = H.neighbours.back();
    demand[i].assign(2 * (d + 1) * 3, Rational(0));
    for (int j = 0; j <= d; ++j)
      for (int c = 0; c < 3; ++c) {
        const Rational r0 = S.points[j * 3 + c], r1 = S.points[((d + 1) + j) * 3 + c];
        demand[i][j * 3 + c] = r0;
        demand[i][((d + 1) + j) * 3 + c] = r0 - 2 / tau[i] * (r1 - r0);
      }
  }
  HybridPatch<Rational> P = base;
  for (std::size_t i = 0; i < N; ++i)
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        std::vector<const Rational*> dm;
        if (k <= 1) dm.push_back(&demand[i][(k * (d + 1) + j) * 3]);
        if (j < l && j <= 1) dm.push_back(&demand[(i + N - 1) % N][(j * (d + 1) + d - k) * 3]);  // C^{i-1}_{d-k, j}
        if (j > d - l && d - j <= 1) dm.push_back(&demand[(i + 1) % N][((d - j) * (d + 1) + k) * 3]);  // C^{i+1}_{k, d-j}
        const std::size_t at = P.index(i, j, k);
        if (dm.empty()) {  // f at the dome's domain point
          P.points[at + 2] = host_f(P.points[at], P.points[at + 1]);
          continue;
        }
        for (int c = 0; c < 3; ++c) {
          Rational sum = 0;
          for (const auto* v : dm) sum += v[c];
          P.points[at + c] = sum / static_cast<long>(dm.size());
        }
        Rational diff = 0;
        for (const auto* v : dm)
          for (const auto* w : dm)
            for (int c = 0; c < 3; ++c) diff = std::max(diff, Rational(abs(Rational(v[c] - w[c]))));
        if (diff > 0) {
          ++H.conflicts;
          H.max_conflict = std::max(H.max_conflict, diff);
        }
      }
  validate(P);
  H.patch = P;
  H.conflicts /= 2;  // each shared point is visited from both of its sides
  return H;
}

}  // namespace splinex
